// Sweep.cpp -- a sweep file read and validated (scenes/Sweep.h): its scene, quantity, options and axes, the
// scene of each grid point, and the quantities a sweep can chart. The points' evaluation (one at a time or
// on lanes) is SweepEvaluate.cpp, the refinement and the grid's values SweepRefine.cpp, the CSV and the
// chart's description SweepOutput.cpp.
#include "scenes/Sweep.h"

#include "dynamics/core/Errors.h"
#include "dynamics/tools/ToolRegistry.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/JsonFields.h"
#include "scenes/SceneLoader.h"
#include "scenes/SceneTools.h"
#include "scenes/ToolRunner.h"

#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>

namespace rv {

using nlohmann::json;

namespace {

// the quantities the tools add (addSweepQuantity), in the order they register
struct AddedQuantities {
  std::mutex mutex;
  std::vector<SweepQuantity> all;
};
AddedQuantities& addedQuantities() {
  static AddedQuantities added;
  return added;
}

std::vector<SweepQuantity> makeQuantities() {
  std::vector<SweepQuantity> q;
  {
    auto& added = addedQuantities();
    const std::lock_guard lock(added.mutex);
    q = added.all;
  }
  const auto single = [](const std::string& name) {
    return [name](const SweepSpec&) { return std::vector<std::string>{name}; };
  };
  // the numbers of every tool that runs through scenes/ToolRunner.h (a module's too): "TOOL.OUTPUT" or the
  // output's own quantity name
  for (const auto& tool : ToolRegistry::global().entries()) {
    if (!findToolRunner(tool.id)) continue;
    for (const auto& out : tool.outputs) {
      if (!out.quantity) continue;
      const std::string id = sweepQuantityId(tool, out);
      q.push_back({id, tool.id, out.description, single(id),
                   [&tool, name = out.name](const SweepSpec&, const Scene& s, const ToolControl& c) {
                     const ToolResult r = runTool(tool, s, c);
                     if (r.stopped) throw Stopped{};
                     const auto& v = r.fields.at(name);
                     if (!v.is_number())
                       throw ComputationError(tool.id + " gave no number for " + name + ": " + v.dump());
                     return std::vector<double>{v.get<double>()};
                   }});
      if (const ToolRunner* runner = findToolRunner(tool.id); runner->narrowTo)
        q.back().narrow = [runner, name = out.name](Scene& s) { runner->narrowTo(name, s); };
      if (const LanesEvaluator* lanes = findLanesEvaluator(tool.id))
        q.back().evaluateLanes = [lanes, name = out.name](const SweepSpec&, const std::vector<Scene>& scenes,
                                                          const ToolControl& c) {
          return (*lanes)(name, scenes, c);
        };
    }
  }
  return q;
}

std::string resolveScenePath(const std::string& name, const std::string& sweepPath, const Where& w) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path p(name);
  if (p.is_absolute()) return name;
  for (const fs::path& base : {fs::path(sweepPath).parent_path(), fs::path(".")}) {
    const fs::path candidate = base / p;
    if (fs::is_regular_file(candidate, ec)) return candidate.lexically_normal().string();
  }
  w.fail("no scene file '" + name + "' (looked beside the sweep file and in the working folder)");
}

// the scene document of grid point `index`
std::pair<json, std::vector<SceneOverride>> pointDocument(const SweepSpec& spec, long index) {
  json doc = spec.base.document;
  std::vector<SceneOverride> overrides;
  const auto values = spec.axisValues(index);
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    const SweepAxis& axis = spec.axes[a];
    if (axis.mapCoordinate < 0) {
      overrides.push_back({axis.id, fmt::format("{:.17g}", values[a])});
      continue;
    }
    json& initial = doc["initial"];
    if (!initial.contains("map") || !initial["map"].is_array()) {
      json root = initial.contains("root") ? initial["root"] : json();
      initial = json::object();
      initial["map"] = json::array();
      if (!root.is_null()) initial["root"] = root;
    }
    json& point = initial["map"];
    while (point.size() <= static_cast<std::size_t>(axis.mapCoordinate))
      point.push_back(0.0);
    point[static_cast<std::size_t>(axis.mapCoordinate)] = values[a];
    if (doc.contains("fixedpoint") && doc["fixedpoint"].is_object())
      doc["fixedpoint"].erase("guess"); // searched from here
  }
  return {std::move(doc), std::move(overrides)};
}

} // namespace

void addSweepQuantity(SweepQuantity quantity) {
  auto& added = addedQuantities();
  const std::lock_guard lock(added.mutex);
  for (const auto& q : added.all)
    if (q.id == quantity.id) throw InputError("sweep quantity " + quantity.id + " is added twice");
  added.all.push_back(std::move(quantity));
}

const std::vector<SweepQuantity>& sweepQuantities() {
  static const std::vector<SweepQuantity> q = makeQuantities();
  return q;
}

double SweepAxis::at(int i) const {
  if (count <= 1) return min;
  return i == count - 1 ? max : min + (max - min) * i / (count - 1);
}

long SweepSpec::points() const {
  long n = 1;
  for (const auto& a : axes)
    n *= a.count;
  return n;
}

std::vector<double> SweepSpec::axisValues(long index) const {
  std::vector<double> v;
  for (const auto& a : axes) {
    v.push_back(a.at(static_cast<int>(index % a.count)));
    index /= a.count;
  }
  return v;
}

SweepSpec sweepFromJson(json doc, const std::string& source) {
  const Where root{source, ""};
  requireObject(doc, root);
  onlyKeys(doc, root, {"scene", "axes", "quantity", "set", "options", "title", "description"});
  SweepSpec spec;
  spec.source = source;
  if (doc.contains("title")) spec.title = text(doc["title"], root / "title");

  // the scene: a path or the document itself (as ranks receive it), with `set` applied
  if (!doc.contains("scene")) root.fail("missing \"scene\" (a scene file)");
  std::vector<SceneOverride> sets;
  if (doc.contains("set")) {
    for (const auto& [k, v] : requireObject(doc["set"], root / "set").items())
      sets.push_back({k, v.dump()});
  }
  try {
    if (doc["scene"].is_object()) {
      spec.base = sceneFromJson(doc["scene"], source + ":scene", sets);
    } else {
      const std::string path = resolveScenePath(text(doc["scene"], root / "scene"), source, root / "scene");
      spec.base = loadScene(path, sets);
    }
  } catch (const InputError& e) {
    const std::string msg = e.what();
    // an override names itself as "--set KEY": say where it is in the sweep file
    if (msg.rfind("--set ", 0) == 0) (root / "set").fail(msg.substr(6));
    throw;
  }

  // the quantity
  if (!doc.contains("quantity")) root.fail("missing \"quantity\"");
  const std::string quantity = text(doc["quantity"], root / "quantity");
  for (const auto& q : sweepQuantities()) {
    const bool prefix = q.id.back() == '.';
    const std::string stem = prefix ? q.id : q.id + "."; // what a name follows: "observable.", "reversal."
    if (!prefix && quantity == q.id) {
      spec.quantity = &q;
      break;
    }
    if ((prefix || q.optionalName) && quantity.rfind(stem, 0) == 0 && quantity.size() > stem.size()) {
      spec.quantity = &q;
      spec.quantityName = quantity.substr(stem.size());
      break;
    }
  }
  if (!spec.quantity) {
    std::string known;
    for (const auto& q : sweepQuantities())
      known += " " + q.id + (q.id.back() == '.' ? "NAME" : "");
    (root / "quantity").fail("unknown quantity '" + quantity + "' (known:" + known + ")");
  }
  if (!spec.quantity->tool.empty() && !ToolRegistry::global().find(spec.quantity->tool))
    (root / "quantity").fail("the tool " + spec.quantity->tool + " is not registered");
  if (!spec.quantityName.empty() && spec.base.model->findObservable(spec.quantityName) < 0)
    (root / "quantity")
        .fail("unknown observable '" + spec.quantityName + "' of " + spec.base.model->info().id +
              " (`rollviz describe " + spec.base.model->info().id + "` lists them)");
  if (spec.quantity->needsMap && !spec.base.model->isMap() && spec.base.poincare.observable.empty())
    (root / "quantity").fail(quantity + " needs the scene's Poincare section (poincare.section)");

  // the options
  auto options = std::make_shared<ParameterValues>(sweepOptionsTable());
  if (doc.contains("options"))
    readParameters(requireObject(doc["options"], root / "options"), root / "options", *options);
  spec.options = options;

  // the axes
  const Where wa = root / "axes";
  if (!doc.contains("axes")) root.fail("missing \"axes\" (one or two)");
  if (!doc["axes"].is_array() || doc["axes"].empty() || doc["axes"].size() > 2)
    wa.fail("expected an array of one or two axes");
  std::set<std::string> ids;
  double total = 1;
  for (std::size_t i = 0; i < doc["axes"].size(); ++i) {
    const Where w = wa / std::to_string(i);
    const json& a = requireObject(doc["axes"][i], w);
    onlyKeys(a, w, {"id", "min", "max", "count"});
    for (const char* k : {"id", "min", "max", "count"})
      if (!a.contains(k)) w.fail(std::string("missing \"") + k + "\"");
    SweepAxis axis;
    axis.id = text(a["id"], w / "id");
    axis.min = number(a["min"], w / "min");
    axis.max = number(a["max"], w / "max");
    const double count = number(a["count"], w / "count");
    if (!(count >= 1) || count != std::floor(count) || count > 1e8)
      (w / "count").fail("must be a whole number from 1 to 10^8, got " + shown(a["count"]));
    axis.count = static_cast<int>(count);
    if (!std::isfinite(axis.min) || !std::isfinite(axis.max)) w.fail("min and max must be finite");
    if (axis.min > axis.max) (w / "min").fail(fmt::format("min {} is above max {}", axis.min, axis.max));
    if (!ids.insert(axis.id).second) (w / "id").fail("axis '" + axis.id + "' given twice");
    total *= axis.count;
    if (axis.id.rfind("map.", 0) == 0) {
      const std::string k = axis.id.substr(4);
      if (k.size() != 1 || k[0] < '0' || k[0] > '2')
        (w / "id").fail("a map axis is map.0, map.1 or map.2 (the coordinates on the section)");
      axis.mapCoordinate = k[0] - '0';
    } else {
      // the key must be one --set takes: try it with the scene's own value there (or min when it has none)
      json value = axis.min;
      const json* node = &spec.base.document;
      std::stringstream path(axis.id.find('.') == std::string::npos ? "parameters." + axis.id : axis.id);
      for (std::string part; node && std::getline(path, part, '.');)
        node = node->is_object() && node->contains(part) ? &(*node)[part] : nullptr;
      if (node && node->is_number()) value = *node;
      try {
        (void)sceneFromJson(spec.base.document, source, {{axis.id, value.dump()}});
      } catch (const InputError& e) {
        std::string msg = e.what();
        if (msg.rfind("--set ", 0) == 0) msg = msg.substr(msg.find(": ") + 2);
        (w / "id").fail("'" + axis.id + "' is not a parameter or scene key of this scene: " + msg);
      }
    }
    spec.axes.push_back(axis);
  }
  spec.lanes = static_cast<int>(options->get("lanes"));
  if (spec.lanes != 0 && spec.lanes != 1 && spec.lanes != 4 && spec.lanes != 8)
    (root / "options" / "lanes")
        .fail("0 (as many as the CPU's registers take), 1 (one point at a time), 4 or 8, got " +
              std::to_string(spec.lanes));
  // refinement: the axes become the finest grid, of which the file's grid is level 0
  spec.refine = static_cast<int>(options->get("refine"));
  spec.refineThreshold = options->get("refine_threshold");
  if (options->choice("refine_by") == "value") {
    if (spec.quantity->categorical)
      (root / "options" / "refine_by")
          .fail("a categorical quantity is refined wherever it changes: refine_by value needs a number");
    spec.refineAt = options->get("refine_at");
  }
  if (spec.refine > 0) {
    if (spec.quantity->cloud)
      (root / "options" / "refine")
          .fail("an orbit diagram (a cloud of points per grid point) is not refined");
    total = 1;
    for (auto& axis : spec.axes) {
      if (axis.count > 1) axis.count = (axis.count - 1) * (1 << spec.refine) + 1;
      total *= axis.count;
    }
  }
  if (total > 1e9)
    wa.fail(spec.refine ? "more than 10^9 points on the finest grid" : "more than 10^9 grid points");
  spec.columns = spec.quantity->columns(spec);

  spec.resolved = doc;
  spec.resolved["scene"] = spec.base.document;
  spec.resolved.erase("set");
  return spec;
}

SweepSpec loadSweep(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(path + ": is a folder, not a sweep file");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path + ": cannot open the sweep file (" +
                     (fs::exists(path, ec) ? "not readable" : "no such file") + ")");
  return sweepFromJson(parseSceneJson(in, path), path);
}

SweepSpec zoomSweep(const SweepSpec& spec, const std::vector<double>& bounds, const std::string& what) {
  const std::size_t axes = spec.axes.size();
  if (bounds.size() != 2 * axes)
    throw InputError(fmt::format("{}: {} numbers for a sweep of {} ax{}: give min,max of each ({})", what,
                                 bounds.size(), axes, axes == 1 ? "is" : "es",
                                 axes == 2 ? "x0,x1,y0,y1" : "x0,x1"));
  json doc = spec.resolved; // the scene inlined, `set` applied: the file's counts, options and quantity
  for (std::size_t a = 0; a < axes; ++a) {
    const double lo = bounds[2 * a], hi = bounds[2 * a + 1];
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi))
      throw InputError(fmt::format("{}: the range of {} needs finite min < max, got {}, {}", what,
                                   spec.axes[a].id, lo, hi));
    doc["axes"][a]["min"] = lo;
    doc["axes"][a]["max"] = hi;
  }
  SweepSpec zoomed = sweepFromJson(std::move(doc), spec.source);
  zoomed.title = spec.title;
  return zoomed;
}

Scene sweepPointScene(const SweepSpec& spec, long index) {
  auto [doc, overrides] = pointDocument(spec, index);
  return sceneFromJson(std::move(doc), spec.source, overrides);
}

SweepSpec sweepWithOptions(const SweepSpec& spec, const json& options, const std::string& what) {
  json doc = spec.resolved;
  for (const auto& [key, value] : options.items())
    doc["options"][key] = value;
  try {
    SweepSpec changed = sweepFromJson(std::move(doc), spec.source);
    changed.title = spec.title;
    return changed;
  } catch (const InputError& e) {
    throw InputError(what + ": " + e.what());
  }
}

std::string SweepSpec::axisLabel(std::size_t a) const {
  const SweepAxis& axis = axes.at(a);
  if (axis.mapCoordinate < 0) return axis.id;
  try {
    const auto names = scenePoincareMap(base, 1)->coordinateNames();
    if (static_cast<std::size_t>(axis.mapCoordinate) < names.size())
      return names[static_cast<std::size_t>(axis.mapCoordinate)] + " (" + axis.id + ")";
  } catch (const std::exception&) { // a label is not worth failing for
  }
  return axis.id;
}

} // namespace rv
