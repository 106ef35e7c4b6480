#include "scenes/Session.h"

#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "scenes/SnapshotJson.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace rv {

namespace {
std::map<std::string, double> namedNumbers(const nlohmann::json& j, const Where& w) {
  requireObject(j, w);
  std::map<std::string, double> m;
  for (const auto& [id, value] : j.items())
    m[id] = number(value, w / id);
  return m;
}
const nlohmann::json& field(const nlohmann::json& j, const char* key, const Where& w) {
  if (!j.contains(key)) w.fail(std::string("the field '") + key + "' is missing");
  return j[key];
}
// a tool number as saved (0, or absent in older files: none known)
int numberField(const nlohmann::json& j, const Where& w) {
  if (!j.contains("id")) return 0;
  const double n = number(j["id"], w / "id");
  if (!(n >= 0 && n <= 1e9) || n != std::floor(n))
    (w / "id").fail("must be a tool's number: 1, 2, ... (0: none)");
  return static_cast<int>(n);
}
constexpr std::pair<SavedToolOutput::Outcome, const char*> kOutcomes[] = {
    {SavedToolOutput::Outcome::Finished, "finished"},
    {SavedToolOutput::Outcome::Stopped, "stopped"},
    {SavedToolOutput::Outcome::Failed, "failed"}};
Rgb colourField(const nlohmann::json& j, const Where& w) {
  const auto colour = numbers(field(j, "colour", w), w / "colour");
  if (colour.size() != 3 ||
      std::any_of(colour.begin(), colour.end(), [](double c) { return c < 0 || c > 1; }))
    (w / "colour").fail("must be three numbers from 0 to 1 (red, green, blue)");
  return {colour[0], colour[1], colour[2]};
}
} // namespace

nlohmann::json toJson(const SavedTrajectory& t) {
  return {{"start", t.start},
          {"parameters", t.parameters},
          {"integrator", t.integrator},
          {"colour", t.colour},
          {"x", t.x},
          {"y", t.y},
          {"z", t.z},
          {"state", snapshotToJson(Snapshot{t.state, 0})},
          {"running", t.running},
          {"first", t.first},
          {"last", t.last},
          {"origin", t.origin},
          {"id", t.id}};
}

SavedTrajectory savedTrajectoryFromJson(const nlohmann::json& j, const Where& w) {
  requireObject(j, w);
  SavedTrajectory t;
  t.start = numbers(field(j, "start", w), w / "start");
  t.parameters = namedNumbers(field(j, "parameters", w), w / "parameters");
  t.integrator = namedNumbers(field(j, "integrator", w), w / "integrator");
  t.colour = colourField(j, w);
  t.x = numbers(field(j, "x", w), w / "x");
  t.y = numbers(field(j, "y", w), w / "y");
  t.z = numbers(field(j, "z", w), w / "z");
  if (t.y.size() != t.x.size() || (!t.z.empty() && t.z.size() != t.x.size()))
    w.fail("x, y (and z) must hold as many points");
  t.state = snapshotFromJson(field(j, "state", w), (w / "state").str()).values;
  // written by older rollviz (the jobs saved at exit): running, no range, no origin
  t.running = j.contains("running") ? boolean(j["running"], w / "running") : true;
  t.first = j.contains("first") ? static_cast<long>(number(j["first"], w / "first")) : 1;
  t.last = j.contains("last") ? static_cast<long>(number(j["last"], w / "last")) : 0;
  if (t.first < 1) (w / "first").fail("must be 1 or more");
  t.origin = j.contains("origin") ? text(j["origin"], w / "origin") : std::string{};
  t.id = numberField(j, w);
  return t;
}

nlohmann::json toJson(const SavedToolOutput& t) {
  nlohmann::json multipliers = nlohmann::json::array();
  for (const auto& [parameter, m] : t.multipliers) {
    nlohmann::json values = nlohmann::json::array();
    for (const auto& z : m)
      values.push_back({z.real(), z.imag()});
    multipliers.push_back({{"parameter", parameter}, {"multipliers", values}});
  }
  const char* outcome = "";
  for (const auto& [o, name] : kOutcomes)
    if (o == t.outcome) outcome = name;
  return {{"name", t.name},
          {"summary", t.summary},
          {"colour", t.colour},
          {"x", t.x},
          {"y", t.y},
          {"found", t.found},
          {"fixed_points", multipliers},
          {"every_step", t.everyStep},
          {"outcome", outcome},
          {"id", t.id}};
}

SavedToolOutput savedToolOutputFromJson(const nlohmann::json& j, const Where& w) {
  requireObject(j, w);
  SavedToolOutput t;
  t.name = text(field(j, "name", w), w / "name");
  t.summary = j.contains("summary") ? text(j["summary"], w / "summary") : std::string{};
  t.colour = colourField(j, w);
  t.x = numbers(field(j, "x", w), w / "x");
  t.y = numbers(field(j, "y", w), w / "y");
  if (t.y.size() != t.x.size()) w.fail("x and y must hold as many points");
  if (j.contains("found")) t.found = numbers(j["found"], w / "found");
  if (!t.found.empty() && t.found.size() != 2) (w / "found").fail("must be a point of the map: [x, y]");
  if (j.contains("every_step")) t.everyStep = boolean(j["every_step"], w / "every_step");
  if (j.contains("outcome")) { // (older files: finished)
    const std::string outcome = text(j["outcome"], w / "outcome");
    const auto* o = std::find_if(std::begin(kOutcomes), std::end(kOutcomes),
                                 [&outcome](const auto& k) { return outcome == k.second; });
    if (o == std::end(kOutcomes)) (w / "outcome").fail("must be finished, stopped or failed");
    t.outcome = o->first;
  }
  t.id = numberField(j, w);
  if (j.contains("fixed_points")) {
    const auto& list = j["fixed_points"];
    if (!list.is_array()) (w / "fixed_points").fail("must be an array");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const Where at = w / ("fixed_points[" + std::to_string(i) + "]");
      requireObject(list[i], at);
      std::vector<std::complex<double>> m;
      const auto& values = field(list[i], "multipliers", at);
      if (!values.is_array()) (at / "multipliers").fail("must be an array of [re, im] pairs");
      for (std::size_t k = 0; k < values.size(); ++k) {
        const Where mk = at / ("multipliers[" + std::to_string(k) + "]");
        const auto z = numbers(values[k], mk);
        if (z.size() != 2) mk.fail("must be [re, im]");
        m.emplace_back(z[0], z[1]);
      }
      t.multipliers.emplace_back(number(field(list[i], "parameter", at), at / "parameter"), std::move(m));
    }
  }
  return t;
}

bool isSession(const nlohmann::json& document) {
  return document.is_object() && document.contains(kSessionKey);
}

nlohmann::json sessionToJson(const Session& s) {
  nlohmann::json trajectories = nlohmann::json::array();
  for (const auto& t : s.trajectories)
    trajectories.push_back(toJson(t));
  nlohmann::json tools = nlohmann::json::array();
  for (const auto& t : s.tools)
    tools.push_back(toJson(t));
  return {
      {kSessionKey, kSessionFormat},  {"scene", s.scene}, {"scene_path", s.scenePath}, {"origin", s.origin},
      {"trajectories", trajectories}, {"tools", tools},   {"results", s.results},      {"gui", s.gui}};
}

Session sessionFromJson(const nlohmann::json& j, const std::string& file) {
  const Where w{file, ""};
  if (!isSession(j)) w.fail(std::string("not a rollviz session (no '") + kSessionKey + "' field)");
  const auto& version = j[kSessionKey];
  if (!version.is_number_integer() || version.get<int>() != kSessionFormat)
    (w / kSessionKey)
        .fail("a session of format " + shown(version) + "; this rollviz reads format " +
              std::to_string(kSessionFormat));
  Session s;
  s.scene = requireObject(field(j, "scene", w), w / "scene");
  if (j.contains("scene_path")) s.scenePath = text(j["scene_path"], w / "scene_path");
  if (j.contains("origin")) s.origin = text(j["origin"], w / "origin");
  if (j.contains("results")) s.results = text(j["results"], w / "results");
  if (j.contains("gui")) s.gui = requireObject(j["gui"], w / "gui");
  const auto& list = field(j, "trajectories", w);
  if (!list.is_array()) (w / "trajectories").fail("must be an array");
  for (std::size_t i = 0; i < list.size(); ++i)
    s.trajectories.push_back(
        savedTrajectoryFromJson(list[i], Where{file, "trajectories[" + std::to_string(i) + "]"}));
  if (j.contains("tools")) { // (sessions written before the tools were kept have none)
    const auto& tools = j["tools"];
    if (!tools.is_array()) (w / "tools").fail("must be an array");
    for (std::size_t i = 0; i < tools.size(); ++i)
      s.tools.push_back(savedToolOutputFromJson(tools[i], Where{file, "tools[" + std::to_string(i) + "]"}));
  }
  return s;
}

Session readSession(const std::string& path) {
  std::istringstream in(readInputFile(path, "session file"));
  return sessionFromJson(parseSceneJson(in, path), path);
}

std::optional<Session> readSessionIfAny(const std::string& path) {
  std::istringstream in(readInputFile(path, "scene file"));
  const nlohmann::json document = parseSceneJson(in, path);
  if (!isSession(document)) return std::nullopt;
  return sessionFromJson(document, path);
}

void writeSession(const Session& s, const std::string& path) {
  AtomicFile file(path, path);
  {
    std::ofstream out(file.tempPath());
    out << sessionToJson(s).dump(1) << '\n';
    if (!out) throw ComputationError("cannot write " + path);
  }
  file.commit();
}

} // namespace rv
