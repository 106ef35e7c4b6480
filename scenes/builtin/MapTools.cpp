// MapTools.cpp -- the tools of the fixed-point family (BuiltinTool.h): fixedpoint, continuation,
// multipliers, separatrix, bifurcation_tree, on the scene's map. Every front end derives its part from them
// -- the CLI command (flags, --json, -o, what it says on the way), the Python method (its result's shape is
// written here, `python`), the chart of a continuation, and the GUI's map window, which draws a family's,
// a branch's or a tree's rows as they come (ToolWindow::MapRows, ToolControl::row). The computations are
// dynamics/tools' (FixedPoint.h, Continuation.h, Separatrix.h, BifurcationTree.h).
#include "dynamics/core/Errors.h"
#include "dynamics/tools/BifurcationTree.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/FixedPointJson.h"
#include "scenes/JsonFields.h"
#include "scenes/SceneTools.h"
#include "scenes/builtin/BuiltinTool.h"

#include <fmt/core.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <optional>

namespace rv {

namespace {

using nlohmann::json;

// --guess x,y[,z]: fixedpoint.guess
ToolArgument guessArgument() {
  return {"guess", "X,Y[,Z]",
          "starting point in map coordinates (default: fixedpoint.guess, or the scene's initial map point)",
          [](const std::string& value) {
            return std::vector<SceneOverride>{{"fixedpoint.guess", json(commaNumbers(value)).dump()}};
          }};
}

// an argument that is another section's setting under a short name (--order is fixedpoint.order)
ToolArgument settingArgument(const std::string& name, const std::string& key, const std::string& valueName,
                             const std::string& description) {
  return {name, valueName, description, [key](const std::string& value) {
            // a JSON value as is (a number), anything else as a string
            const json parsed = json::parse(value, nullptr, false);
            return std::vector<SceneOverride>{
                {key, parsed.is_discarded() || parsed.is_string() ? json(value).dump() : value}};
          }};
}

std::vector<ToolArgument> searchArguments() {
  return {guessArgument(),
          settingArgument("order", "fixedpoint.order", "N",
                          "order n of the map Map^n (default: fixedpoint.order)"),
          settingArgument("method", "fixedpoint.method", "newton|gradient",
                          "the search: newton or gradient (default: fixedpoint.method)")};
}

// the continuation's everyday flags beside its section's settings (its own `method` is natural|arclength)
std::vector<ToolArgument> continuationArguments() {
  return {guessArgument(),
          settingArgument("order", "fixedpoint.order", "N",
                          "order n of the map Map^n (default: fixedpoint.order)"),
          settingArgument("param", "continuation.parameter", "NAME",
                          "the model parameter to continue in (default: continuation.parameter)"),
          settingArgument("to", "continuation.to", "VALUE",
                          "finite value of the parameter (default: continuation.to)")};
}

json pointsJson(const std::vector<Eigen::VectorXd>& points) {
  json j = json::array();
  for (const auto& p : points)
    j.push_back(toVector(p));
  return j;
}

// a fixed point as the fixedpoint tool gives it (its search path apart)
json fixedPointFields(const FixedPointResult& r, const ReturnMap& map) {
  return {{"point", toVector(r.point)},
          {"coordinates", map.coordinateNames()},
          {"multipliers", multipliersJson(r.multipliers)},
          {"type", toString(r.type)},
          {"residual", r.residual},
          {"family", r.family},
          {"iterations", r.iterations},
          {"evaluations", r.evaluations},
          {"order", map.order()}};
}

// the search path as rows of points (Python always has it)
json searchPathRows(const FixedPointResult& r) {
  std::vector<Eigen::VectorXd> points;
  for (const auto& q : r.path)
    points.push_back(q.point);
  return pointsJson(points);
}

// the fixed point the scene's search finds; nothing when stopped on request. `streamPath`: each step of the
// search handed on as a row (the map window draws the path as it goes)
std::optional<FixedPointResult> searchFixedPoint(const SceneMap& s, const ReturnMap& map,
                                                 const ToolControl& control, bool streamPath = false) {
  std::function<void(const SearchPoint&)> onStep;
  if (streamPath && control.row) {
    StreamedRow row{map.coordinateNames(), {}, {}, {}};
    row.names.emplace_back("residual");
    onStep = [&control, row](const SearchPoint& p) mutable {
      row.values = toVector(p.point);
      row.values.push_back(p.residual);
      control.row(row);
    };
  }
  try {
    return findFixedPoint(map, s.guess(), s.search(), control, onStep);
  } catch (const Stopped&) {
    return std::nullopt;
  }
}

ToolResult runFixedPoint(const Scene& scene, const ToolControl& control) {
  const SceneMap s(scene);
  const ReturnMap map = s.map();
  ToolResult result;
  const auto found = searchFixedPoint(s, map, control, true);
  result.stopped = !found;
  if (!found) return result;
  const FixedPointResult& r = *found;
  result.fields = fixedPointFields(r, map);
  if (scene.tool("fixedpoint").choice("path") == "yes") {
    json path = json::array();
    for (const auto& q : r.path)
      path.push_back({{"point", toVector(q.point)}, {"residual", q.residual}});
    result.fields["path"] = path;
  }
  result.python = fixedPointFields(r, map);
  result.python["path"] = searchPathRows(r);
  return result;
}

std::string describeFixedPoint(const ToolResult& r) {
  const json& f = r.fields;
  if (!f.contains("point")) return {};
  std::string text;
  if (f.contains("path"))
    for (const auto& q : f["path"])
      text +=
          fmt::format("search: {:.17g}  |Map^n(x) - x| = {:.3g}\n",
                      fmt::join(q["point"].get<std::vector<double>>(), ", "), q["residual"].get<double>());
  text += fmt::format("point: {:.17g}\n", fmt::join(f["point"].get<std::vector<double>>(), ", "));
  for (const auto& z : f["multipliers"]) {
    const double re = z[0], im = z[1];
    text += fmt::format("multiplier: {:.15g} {:+.15g} i  (|m| = {:.15g})\n", re, im, std::hypot(re, im));
  }
  text +=
      fmt::format("type: {}\nresidual: {:.3g}\n", f["type"].get<std::string>(), f["residual"].get<double>());
  if (const int family = f.value("family", 0); family > 0)
    text += fmt::format("family: the point lies on a {}-dimensional family of fixed points (D Map^n - I has "
                        "lost rank; integrals): the search ends at the family's point nearest the guess, and "
                        "the type is of the multipliers off it\n",
                        family);
  text += fmt::format("iterations: {}\nmap evaluations: {}\n", f["iterations"].get<int>(),
                      f["evaluations"].get<long>());
  return text;
}

// --- continuation

json changeJson(const TypeChange& t) {
  return {{"parameter", t.parameter},
          {"kind", toString(t.kind)},
          {"from", toString(t.from)},
          {"to", toString(t.to)},
          {"point", toVector(t.at.fixedPoint.point)},
          {"multipliers", multipliersJson(t.at.fixedPoint.multipliers)}};
}

// what the CLI's --json says of a family
json familySummary(const Continuation& family, const ContinuationSettings& c) {
  json changes = json::array();
  for (const auto& t : family.changes())
    changes.push_back(changeJson(t));
  return {{"parameter", c.parameter},
          {"method", c.method == ContinuationMethod::Arclength ? "arclength" : "natural"},
          {"points", family.points().size()},
          {"last", family.points().empty() ? 0.0 : family.points().back().parameter},
          {"changes", changes},
          {"end", family.end()}};
}

// a family as Python has it: its points, multipliers and types as arrays, its changes described
json familyPython(const Continuation& family, const ContinuationSettings& c, const ReturnMap& map,
                  const std::string& failure) {
  json values = json::array(), points = json::array(), multipliers = json::array(), residual = json::array(),
       types = json::array(), changes = json::array();
  for (const auto& p : family.points()) {
    values.push_back(p.parameter);
    points.push_back(toVector(p.fixedPoint.point));
    multipliers.push_back(multipliersJson(p.fixedPoint.multipliers));
    residual.push_back(p.fixedPoint.residual);
    types.push_back(toString(p.fixedPoint.type));
  }
  for (const auto& t : family.changes()) {
    json ch = changeJson(t);
    ch["description"] = describe(t, c.parameter);
    changes.push_back(ch);
  }
  return {{"parameter", c.parameter},
          {"parameter_values", values},
          {"coordinates", map.coordinateNames()},
          {"points", points},
          {"multipliers", multipliers},
          {"residual", residual},
          {"types", types},
          {"changes", changes},
          {"failure", failure},
          {"end", failure.empty() ? family.end() : failure}};
}

ToolResult runContinuation(const Scene& scene, const ToolControl& control) {
  const SceneMap s(scene);
  const ContinuationSettings c = s.continuation();
  const auto run = s.continuationRun();
  Continuation& cont = *run;
  ToolResult result;
  const ReturnMap map = s.map();
  // the table: the parameter, the point, its multipliers, the residual; its type as text, last
  const auto head = [&](std::size_t multipliers) {
    result.table.names = {c.parameter};
    for (const auto& n : map.coordinateNames())
      result.table.names.push_back(n);
    for (std::size_t i = 1; i <= multipliers; ++i) {
      result.table.names.push_back(fmt::format("re{}", i));
      result.table.names.push_back(fmt::format("im{}", i));
    }
    result.table.names.push_back("residual");
    result.table.values.assign(result.table.names.size(), {});
    result.text = {{"type", {}, result.table.names.size()}};
  };
  head(static_cast<std::size_t>(map.dimension()));
  bool done = false;
  try {
    done = cont.run(
        control,
        [&](const ContinuationPoint& p) {
          if (result.table.rows() == 0) {
            head(p.fixedPoint.multipliers.size());
            if (cont.doubled())
              addNote(result, control,
                      fmt::format("the family of order {} born at the period doubling starts at {} = {:.12g}",
                                  2 * s.section().order, c.parameter, p.parameter));
          }
          std::vector<double> row{p.parameter};
          for (double x : toVector(p.fixedPoint.point))
            row.push_back(x);
          for (auto z : p.fixedPoint.multipliers)
            row.push_back(z.real()), row.push_back(z.imag());
          row.push_back(p.fixedPoint.residual);
          addRow(result, control, row, {toString(p.fixedPoint.type)});
        },
        [&](const TypeChange& t) { addNote(result, control, describe(t, c.parameter)); });
  } catch (const ComputationError& e) {
    if (cont.points().empty() || (c.switchAt > 0 && !cont.doubled())) throw;
    result.failure = e.what(); // the family up to here is a result: keep it, and say why it ends
  }
  result.stopped = !done && result.failure.empty();
  const Continuation& family = cont.doubled() ? *cont.doubled() : cont;
  result.fields = familySummary(cont, c);
  if (cont.doubled()) {
    result.fields["doubled"] = familySummary(family, c);
    result.fields["doubled"]["order"] = 2 * s.section().order;
    // (a doubled family that failed at its first point has none)
    result.fields["doubled"]["first"] =
        family.points().empty() ? json(nullptr) : json(family.points().front().parameter);
  }
  if (done && (c.method == ContinuationMethod::Arclength || cont.doubled()))
    addNote(result, control, "the family ends: " + family.end());
  if (!cont.doubled()) {
    result.python = familyPython(cont, c, map, result.failure);
  } else { // switched: the family of doubled order, its parent under "parent"
    SectionSettings twice = s.section();
    twice.order *= 2;
    result.python = familyPython(family, c, ReturnMap(*scene.model, s.integrators(), twice), result.failure);
    result.python["order"] = twice.order;
    result.python["parent"] = familyPython(cont, c, map, "");
  }
  return result;
}

// --- separatrix

// separatrix.branches, else separatrix.branch
std::vector<int> branchesOf(const Scene& scene) {
  const json& doc = scene.document;
  if (doc.contains("separatrix") && doc["separatrix"].contains("branches")) {
    const json& b = doc["separatrix"]["branches"];
    if (b.is_string()) return {1, 2, 3, 4};
    return b.get<std::vector<int>>();
  }
  return {static_cast<int>(scene.tool("separatrix")["branch"])};
}

ToolArgument branchArgument() {
  return {"branch", "1,2,3,4|all",
          "the branches to grow, comma-separated, or all (default: separatrix.branch)",
          [](const std::string& value) {
            if (value == "all") return std::vector<SceneOverride>{{"separatrix.branches", "\"all\""}};
            const auto list = commaNumbers(value);
            for (double b : list)
              if (b != 1 && b != 2 && b != 3 && b != 4) throw InputError("branches are 1, 2, 3, 4");
            return std::vector<SceneOverride>{{"separatrix.branches", json(list).dump()}};
          }};
}

ToolResult runSeparatrix(const Scene& scene, const ToolControl& control) {
  const SceneMap s(scene);
  const ReturnMap map = s.map();
  if (map.dimension() != 2) throw InputError("separatrix: separatrices are drawn for 2D maps only");
  const std::vector<int> list = branchesOf(scene);
  ToolResult result;
  const auto found = searchFixedPoint(s, map, control);
  result.stopped = !found;
  if (!found) return result;
  const FixedPointResult& fp = *found;
  result.table.names = {"branch"};
  for (const auto& n : map.coordinateNames())
    result.table.names.push_back(n);
  result.table.names.push_back("parameter");
  result.table.values.assign(result.table.names.size(), {});
  json branches = json::array(), python = json::object();
  for (int b : list) {
    SeparatrixSettings ss = separatrixSettingsTable().read(scene.tool("separatrix"));
    ss.fixedPointAccuracy = s.search().accuracy;
    ss.branch = b;
    // each level's points as they are grown, for a front end drawing them (their parameters come with the
    // table, once the branch is grown)
    const auto onPoints = [&](const std::vector<Eigen::VectorXd>& points) {
      if (!control.row) return;
      StreamedRow streamed{{"branch"}, {}, {}, {}};
      for (const auto& n : map.coordinateNames())
        streamed.names.push_back(n);
      for (const auto& p : points) {
        streamed.values = {static_cast<double>(b)};
        for (double x : toVector(p))
          streamed.values.push_back(x);
        control.row(streamed);
      }
    };
    const SeparatrixResult r = growSeparatrix(map, fp, ss, control, onPoints);
    for (std::size_t i = 0; i < r.points.size(); ++i) {
      std::vector<double> row{static_cast<double>(b)};
      for (double x : toVector(r.points[i]))
        row.push_back(x);
      row.push_back(r.parameters[i]);
      result.table.addRow(row);
    }
    addNote(result, control,
            fmt::format("branch {}: {} points, multiplier {:.12g} ({}), linear region {:g}, ended by {}", b,
                        r.points.size(), r.multiplier, r.unstable ? "outgoing" : "incoming", r.linearRegion,
                        r.stoppedBecause));
    const json branch{{"multiplier", r.multiplier},
                      {"unstable", r.unstable},
                      {"linear_region", r.linearRegion},
                      {"ended_by", r.stoppedBecause}};
    json numbered = branch;
    numbered["branch"] = b;
    numbered["points"] = r.points.size();
    branches.push_back(numbered);
    json x = branch;
    x["points"] = pointsJson(r.points);
    x["parameters"] = r.parameters;
    python[std::to_string(b)] = x; // Python: a dict by branch number
    if (r.stoppedBecause == "stopped") {
      result.stopped = true;
      break;
    }
  }
  result.fields = {{"fixedpoint", fixedPointFields(fp, map)}, {"branches", branches}};
  json fixed = fixedPointFields(fp, map);
  fixed["path"] = searchPathRows(fp);
  result.python = {{"fixedpoint", fixed}, {"branches", python}};
  return result;
}

// --- bifurcation tree

ToolResult runBifurcationTree(const Scene& scene, const ToolControl& control) {
  const SceneMap s(scene);
  const ContinuationSettings c = s.continuation();
  BifurcationTreeSettings settings;
  settings.continuation = c;
  const BifurcationTreeSettings t =
      bifurcationTreeSettingsTable().read(scene.tool("bifurcation_tree"), settings);
  const double start = s.spec().modelParameters[c.parameter];
  const ReturnMap map = s.map();
  ToolResult result;
  // the table: each point's branch, the parameter, the point and its multipliers; its type as text, last
  result.table.names = {"level", "order", c.parameter};
  for (const auto& n : map.coordinateNames())
    result.table.names.push_back(n);
  for (int i = 1; i <= map.dimension(); ++i) {
    result.table.names.push_back(fmt::format("re{}", i));
    result.table.names.push_back(fmt::format("im{}", i));
  }
  result.table.values.assign(result.table.names.size(), {});
  result.text = {{"type", {}, result.table.names.size()}};
  BifurcationTreeResult r;
  try {
    bifurcationTree(
        s.spec().modelAt(c.parameter), s.integrators(), s.section(), start, s.guess(), t, control,
        [&](const TreeBranch& b, const ContinuationPoint& p) {
          std::vector<double> row{static_cast<double>(b.level), static_cast<double>(b.order), p.parameter};
          for (double x : toVector(p.fixedPoint.point))
            row.push_back(x);
          for (auto z : p.fixedPoint.multipliers)
            row.push_back(z.real()), row.push_back(z.imag());
          addRow(result, control, row, {toString(p.fixedPoint.type)});
        },
        [&](const PeriodDoubling& d) {
          addNote(
              result, control,
              fmt::format("period doubling of order {} at {} = {:.12g}", d.order, c.parameter, d.parameter));
        },
        &r);
  } catch (const Stopped&) {
    result.stopped = true;
  }
  for (double q : r.ratios())
    addNote(result, control, fmt::format("ratio: {:.10g}", q));
  if (!r.end.empty()) addNote(result, control, "the tree ends: " + r.end);
  json doublings = json::array();
  for (const auto& x : r.doublings)
    doublings.push_back({{"level", x.level}, {"order", x.order}, {"parameter", x.parameter}});
  result.fields = {
      {"parameter", c.parameter}, {"doublings", doublings}, {"ratios", r.ratios()}, {"end", r.end}};
  json rows = json::array();
  for (long k = 0; k < result.table.rows(); ++k)
    rows.push_back(result.table.row(k));
  result.python = result.fields;
  result.python["columns"] = result.table.names;
  result.python["rows"] = rows;
  result.python["types"] = result.text[0].values;
  return result;
}

// the multipliers of the scene's fixed point along its continuation (or of the point alone)
ToolResult runMultipliers(const Scene& scene, const ToolControl& control) {
  const SceneMap s(scene);
  std::vector<std::vector<std::complex<double>>> path;
  ToolResult r;
  try {
    path = multiplierPath(s, control);
  } catch (const Stopped&) {
    r.stopped = true;
    return r;
  }
  const std::size_t m = path.empty() ? 0 : path.front().size();
  r.table.names = {"step"};
  for (std::size_t i = 1; i <= m; ++i) {
    r.table.names.push_back(fmt::format("re{}", i));
    r.table.names.push_back(fmt::format("im{}", i));
  }
  r.table.values.assign(r.table.names.size(), {});
  nlohmann::json all = nlohmann::json::array();
  for (std::size_t k = 0; k < path.size(); ++k) {
    std::vector<double> row{static_cast<double>(k)};
    for (auto z : path[k])
      row.push_back(z.real()), row.push_back(z.imag());
    r.table.addRow(row);
    all.push_back(multipliersJson(path[k]));
  }
  r.fields = {{"multipliers", all}};
  return r;
}

// a flag that sets a scene key to a value (--doubled is continuation.switch = 1)
ToolArgument flagArgument(const std::string& name, const std::string& key, const std::string& value,
                          const std::string& description) {
  return {.name = name,
          .description = description,
          .toSettings =
              [key, value](const std::string&) {
                return std::vector<SceneOverride>{{key, value}};
              },
          .flag = true};
}

// the smallest d dividing n with |Map^d(x) - x| small: the least period of a point of Map^n
int leastPeriod(const Scene& scene, const Eigen::VectorXd& x, int n, double tolerance,
                const ToolControl& control) {
  for (int d = 1; d < n; ++d) {
    if (n % d) continue;
    MapToolOverrides o;
    o.order = d;
    const SceneMap m(scene, o, false);
    const ReturnMap map = m.map();
    if (map.difference(map(x, control), x).norm() < tolerance) return d;
  }
  return n;
}

// "0 elliptic, 1 hyperbolic, ...": the codes of FixedPointType in the CSV
std::string typeCodes() {
  std::string codes;
  for (int k = 0; k <= static_cast<int>(FixedPointType::Unstable); ++k)
    codes += fmt::format("{}{} {}", k ? ", " : "", k, toString(static_cast<FixedPointType>(k)));
  return codes;
}

// fixedpoint.type: the type of the fixed point found from the grid point
SweepQuantity fixedPointType() {
  SweepQuantity q{"fixedpoint.type",
                  "fixedpoint",
                  "the type of the fixed point of order fixedpoint.order found from the point: " +
                      typeCodes(),
                  [](const SweepSpec&) { return std::vector<std::string>{"fixedpoint.type"}; },
                  [](const SweepSpec&, const Scene& s, const ToolControl& c) {
                    const SceneMap m(s);
                    const ReturnMap map = m.map();
                    const FixedPointResult r = findFixedPoint(map, m.guess(), m.search(), c);
                    return std::vector<double>{static_cast<double>(r.type)};
                  },
                  /*needsMap=*/true};
  q.categorical = true;
  return q;
}

// fixedpoint.order: the least period of a periodic point near the grid point, and its type
SweepQuantity fixedPointOrder() {
  SweepQuantity q{
      "fixedpoint.order",
      "fixedpoint",
      "the least period (1..options.max_order) of a periodic point found within options.radius of "
      "the point, and its type (as fixedpoint.type)",
      [](const SweepSpec&) {
        return std::vector<std::string>{"fixedpoint.order", "fixedpoint.type"};
      },
      [](const SweepSpec& sp, const Scene& s, const ToolControl& c) {
        const int maxOrder = static_cast<int>(sp.options->get("max_order"));
        const double radius = sp.options->get("radius");
        std::string last = "no periodic point of order <= " + std::to_string(maxOrder);
        for (int n = 1; n <= maxOrder; ++n) {
          MapToolOverrides o;
          o.order = n;
          const SceneMap m(s, o);
          const ReturnMap map = m.map();
          FixedPointResult r;
          try {
            r = findFixedPoint(map, m.guess(), m.search(), c);
          } catch (const ComputationError& e) {
            last = e.what();
            continue;
          }
          if (map.difference(r.point, m.guess()).norm() > radius) continue;
          const int period = leastPeriod(s, r.point, n, 1e3 * m.search().accuracy + 1e-9, c);
          return std::vector<double>{static_cast<double>(period), static_cast<double>(r.type)};
        }
        throw ComputationError(fmt::format("within radius {}: {}", radius, last));
      },
      /*needsMap=*/true};
  q.categorical = true;
  return q;
}

// --step STEP: continuation.step
ToolArgument stepArgument() {
  return settingArgument("step", "continuation.step", "STEP",
                         "signed step of the parameter (default: continuation.step)");
}

} // namespace

BuiltinTool fixedPointTool() {
  return {
      .entry =
          {.id = "fixedpoint",
           .title = "Fixed points",
           .description = "Newton (or gradient) search from fixedpoint.guess; its type and multipliers",
           .section = "fixedpoint",
           .command = "fixedpoint",
           .commandHelp = "a fixed point of order n of the scene's map, its multipliers and type",
           .outputs = {{"point", "the fixed point"},
                       {"coordinates", "the names of its coordinates"},
                       {"type", "elliptic, hyperbolic, ..."},
                       {"multipliers", "the eigenvalues of D(Map^n), [re, im] each (complex in Python)"},
                       {"residual", "|Map^n(x) - x|"},
                       {"family",
                        "the dimension of the family of fixed points it lies on (0: isolated; a map with "
                        "integrals has families: the search ends at the point nearest the guess)"},
                       {"iterations", "the search's iterations"},
                       {"evaluations", "the map evaluations it spent"},
                       {"order", "n"},
                       {"<path>",
                        "with fixedpoint.path = yes (--path): each point of the search and its residual "
                        "(always in Python, as rows)"}},
           .reference = "manual §2.3.4",
           .computation =
               "dynamics/tools/FixedPoint.h (findFixedPoint); its runner scenes/builtin/MapTools.cpp"},
      .settings = ToolSection{.title = "Fixed point finding", .table = &fixedPointSettingsTable().table()},
      .runner = ToolRunner{.run = runFixedPoint,
                           .arguments = {guessArgument(),
                                         flagArgument("path", "fixedpoint.path", "\"yes\"",
                                                      "also give the whole search path (the manual's \"show "
                                                      "all points\"; fixedpoint.path = yes)")},
                           .describe = describeFixedPoint,
                           .complexFields = {"multipliers"},
                           .window = ToolWindow::MapSearch},
      .quantities = {fixedPointType(), fixedPointOrder()}};
}

BuiltinTool continuationTool() {
  auto arguments = continuationArguments();
  arguments.push_back(flagArgument("arclength", "continuation.method", "\"arclength\"",
                                   "pseudo-arclength continuation, which passes folds (continuation.method = "
                                   "arclength)"));
  arguments.push_back(flagArgument("doubled", "continuation.switch", "1",
                                   "branch switching: the family of doubled order born at the first "
                                   "period doubling instead, continued to the "
                                   "end of [start, --to] on its side (continuation.switch = 1)"));
  return {
      .entry = {.id = "continuation",
                .title = "Continuation",
                .parent = "fixedpoint",
                .description =
                    "the family of the fixed point in continuation.parameter up to continuation.to",
                .section = "continuation",
                .command = "continue",
                .commandHelp = "continue a fixed point in a parameter: the family, its multipliers and where "
                               "its type changes",
                .chartView = "continuation",
                .outputs = {{"parameter",
                             "the continued parameter: its name (JSON), its value at each point (a column)"},
                            {"<map coordinates>", "the fixed point"},
                            {"<re1, im1, ...>", "its multipliers"},
                            {"residual", "|Map^n(x) - x| at each point"},
                            {"type", "its type"},
                            {"changes", "JSON: where the type changes"},
                            {"points", "JSON: how many points the family has"},
                            {"end", "JSON: why the family ends"},
                            {"<doubled>",
                             "JSON, with continuation.switch: the family of doubled order followed instead "
                             "(its points are the table)"}},
                .reference = "manual §2.3.5",
                .computation =
                    "dynamics/tools/Continuation.h (Continuation); its runner scenes/builtin/MapTools.cpp"},
      .settings =
          ToolSection{.title = "Fixed point continuation", .table = &continuationSettingsTable().table()},
      .runner = ToolRunner{.run = runContinuation,
                           .arguments = arguments,
                           .tableIsResult = true,
                           .complexFields = {"multipliers"},
                           .window = ToolWindow::MapRows}};
}

BuiltinTool multipliersTool() {
  auto arguments = continuationArguments();
  arguments.push_back(stepArgument());
  return {
      .entry = {.id = "multipliers",
                .title = "Multipliers",
                .parent = "continuation",
                .description = "the multipliers of the continued fixed point on the complex plane",
                .command = "multipliers",
                .commandHelp =
                    "the multipliers of a fixed point along its continuation (or of the point alone), as CSV",
                .chartView = "multipliers",
                .outputs = {{"step", "the continuation's step (a column, beside re1, im1, re2, im2, ...)"},
                            {"multipliers",
                             "JSON: each step's multipliers, [re, im] each (complex in Python)"}},
                .reference = "manual §2.4.3",
                .computation = "dynamics/tools/Continuation.h (Continuation)"},
      .runner = ToolRunner{.run = runMultipliers, .arguments = arguments, .complexFields = {"multipliers"}}};
}

BuiltinTool separatrixTool() {
  auto arguments = searchArguments();
  arguments.push_back(branchArgument());
  return {
      .entry = {.id = "separatrix",
                .title = "Separatrices",
                .parent = "fixedpoint",
                .description = "the branches of the invariant manifolds of a hyperbolic point",
                .section = "separatrix",
                .command = "separatrix",
                .commandHelp = "the separatrices of a hyperbolic fixed point of a 2D map, as CSV",
                .outputs = {{"branch", "1..4, each point's branch"},
                            {"<map coordinates>", "the points of the branch"},
                            {"parameter",
                             "each point's k + s: the image F^k of the linear segment's point s"},
                            {"fixedpoint", "JSON: the hyperbolic point (as the fixedpoint tool gives it)"},
                            {"branches",
                             "JSON: each branch grown: its multiplier, direction (outgoing or incoming), "
                             "linear region and why it ended"}},
                .reference = "manual §2.3.6",
                .computation =
                    "dynamics/tools/Separatrix.h (growSeparatrix); its runner scenes/builtin/MapTools.cpp"},
      .settings = ToolSection{.title = "Separatrix", .table = &separatrixSettingsTable().table()},
      .runner = ToolRunner{.run = runSeparatrix,
                           .arguments = arguments,
                           .tableIsResult = true,
                           .complexFields = {"multipliers"},
                           .window = ToolWindow::MapRows}};
}

BuiltinTool bifurcationTreeTool() {
  auto arguments = continuationArguments();
  arguments.push_back(searchArguments()[2]); // --method: the search's (the tree's section has none)
  arguments.push_back(stepArgument());
  return {
      .entry =
          {.id = "bifurcation_tree",
           .title = "Bifurcation tree",
           .parent = "fixedpoint",
           .description = "period doublings along the continuation",
           .section = "bifurcation_tree",
           .command = "bifurcation-tree",
           .commandHelp = "the period-doubling cascade of an elliptic fixed point",
           .outputs = {{"level", "the level of each point's branch in the tree (0: the starting family)"},
                       {"order", "the order of each point's branch"},
                       {"<parameter>", "the continued parameter's value at each point"},
                       {"<map coordinates>", "the fixed point"},
                       {"<re1, im1, ...>", "its multipliers"},
                       {"type", "each point's type"},
                       {"doublings", "JSON: each period doubling (level, order, parameter)"},
                       {"ratios", "JSON: the Feigenbaum ratios"},
                       {"end",
                        "why the tree ended (levels reached, the finite value, a family that could not be "
                        "followed, ...)"}},
           .reference = "manual §2.3.7",
           .computation =
               "dynamics/tools/BifurcationTree.h (bifurcationTree); its runner scenes/builtin/MapTools.cpp",
           .alsoSections = {"continuation"}},
      .settings = ToolSection{.title = "Bifurcating tree", .table = &bifurcationTreeSettingsTable().table()},
      .runner = ToolRunner{.run = runBifurcationTree,
                           .arguments = arguments,
                           .tableIsResult = true,
                           .window = ToolWindow::MapRows,
                           .ellipticMultipliersEachRow = true}};
}

} // namespace rv
