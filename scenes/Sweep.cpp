#include "scenes/Sweep.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/Lanes.h"
#include "dynamics/tools/FixedPoint.h"
#include "dynamics/tools/ToolRegistry.h"
#include "dynamics/tools/ToolSettings.h"
#include "dynamics/tools/TrajectoryLanes.h"
#include "scenes/JsonFields.h"
#include "scenes/SceneLoader.h"
#include "scenes/SceneTools.h"
#include "scenes/ToolRunner.h"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <numeric>
#include <set>
#include <sstream>

namespace rv {

using nlohmann::json;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// the observable named after a quantity's prefix, or the default
const Observable& namedObservable(const Scene& scene, const std::string& name) {
  const int k = scene.model->findObservable(name);
  if (k < 0) throw InputError("no observable '" + name + "' in " + scene.model->info().id);
  return scene.model->observables()[static_cast<std::size_t>(k)];
}

// the scene's trajectory up to `time`: `onStep(t0, x0, t1, x1)` sees every step, the last one cut at `time`
template <class OnStep>
void integrateTo(const Scene& scene, double time, const ToolControl& control, OnStep onStep) {
  auto integ = scene.startIntegrator();
  Eigen::VectorXd prev = integ->state(), end;
  double tPrev = integ->time();
  while (tPrev < time) {
    if (control.stopRequested()) throw Stopped{};
    integ->step();
    if (integ->time() >= time) {
      integ->sampleAt(time, end);
      onStep(tPrev, prev, time, end);
      return;
    }
    onStep(tPrev, prev, integ->time(), integ->state());
    prev = integ->state();
    tPrev = integ->time();
  }
}

// What a trajectory quantity reads along one orbit: each step as integrateTo gives it, and its values at the
// end. One reading per point, whether the point's orbit is integrated alone or on a lane beside others.
struct OrbitReading {
  std::function<void(double t0, const Eigen::VectorXd& x0, double t1, const Eigen::VectorXd& x1)> onStep;
  std::function<std::vector<double>()> values;
};
using ReadingOf = OrbitReading (*)(const SweepSpec&, const Scene&);

// observable.NAME: the value at the end, or the time average by the trapezoidal rule
OrbitReading observableReading(const SweepSpec& sp, const Scene& s) {
  struct Sums {
    double sum = 0, last = 0;
  };
  const Observable& f = namedObservable(s, sp.quantityName);
  const double time = sp.options->get("time");
  const bool mean = sp.options->choice("statistic") == "mean";
  auto sums = std::make_shared<Sums>();
  sums->last = f.value(0, s.initialState.data());
  return {[&f, sums](double t0, const Eigen::VectorXd& x0, double t1, const Eigen::VectorXd& x1) {
            const double v = f.value(t1, x1.data());
            sums->sum += 0.5 * (f.value(t0, x0.data()) + v) * (t1 - t0);
            sums->last = v;
          },
          [sums, mean, time] { return std::vector<double>{mean ? sums->sum / time : sums->last}; }};
}

// reversal[.NAME]: whether the observable (the spin about the vertical) changed sign, when first (linear
// interpolation in the step), and its value at the end
OrbitReading reversalReading(const SweepSpec& sp, const Scene& s) {
  struct Sign {
    double start = 0, at = kNaN, end = 0;
  };
  const Observable& f = namedObservable(s, sp.quantityName.empty() ? "omega_vertical" : sp.quantityName);
  auto sign = std::make_shared<Sign>();
  sign->start = sign->end = f.value(0, s.initialState.data());
  return {[&f, sign](double t0, const Eigen::VectorXd& x0, double t1, const Eigen::VectorXd& x1) {
            const double a = f.value(t0, x0.data()), b = f.value(t1, x1.data());
            if (std::isnan(sign->at) && sign->start != 0 && b * sign->start < 0)
              sign->at = a == b ? t1 : t0 + (t1 - t0) * a / (a - b);
            sign->end = b;
          },
          [sign] {
            return std::vector<double>{std::isnan(sign->at) ? 0.0 : 1.0, sign->at, sign->end};
          }};
}

// orbit: how many map points an orbit diagram's point computes (the transient, then those it keeps)
long orbitLength(const SweepSpec& sp) {
  return static_cast<long>(sp.options->get("transient")) + static_cast<long>(sp.options->get("orbit_points"));
}

// orbit: the kept points' coordinate options.coordinate; ComputationError where the map ended early
std::vector<double> orbitValues(const SweepSpec& sp, const std::vector<MapPoint>& points) {
  if (static_cast<long>(points.size()) < orbitLength(sp))
    throw ComputationError(fmt::format("the map ended after {} points", points.size()));
  const auto skip = static_cast<std::size_t>(sp.options->get("transient"));
  const auto k = static_cast<std::size_t>(sp.options->get("coordinate"));
  std::vector<double> v;
  for (std::size_t n = skip; n < points.size(); ++n)
    v.push_back(k < points[n].coordinates.size() ? points[n].coordinates[k] : kNaN);
  return v;
}

// a trajectory quantity at one point: its scene's orbit to options.time, read
auto alongTheOrbit(ReadingOf reading) {
  return [reading](const SweepSpec& sp, const Scene& s, const ToolControl& c) {
    const OrbitReading r = reading(sp, s);
    integrateTo(s, sp.options->get("time"), c, r.onStep);
    return r.values();
  };
}

// a trajectory quantity at several points at once, their orbits on SIMD lanes (dynamics/tools/
// TrajectoryLanes.h): each lane's steps are its orbit's alone, bit for bit, so each reading is the one-at-a-
// time one; a failed step sends the points to be integrated alone (where each fails, or not, as alone)
auto alongTheOrbitsOnLanes(ReadingOf reading) {
  return [reading](const SweepSpec& sp, const std::vector<Scene>& scenes,
                   const ToolControl& c) -> std::optional<std::vector<LaneValues>> {
    const auto points = pointsOnLanes(scenes);
    if (!points) return std::nullopt;
    const IntegratorFactory make = [&] { return points->run.makeIntegrator(*points->models.front()); };
    if (!trajectoriesRunOnLanes(points->models, make)) return std::nullopt;
    std::vector<OrbitReading> readings;
    readings.reserve(scenes.size());
    for (const Scene& s : scenes)
      readings.push_back(reading(sp, s));
    const auto onStep = [&](int lane, double t0, const Eigen::VectorXd& x0, double t1,
                            const Eigen::VectorXd& x1) {
      readings[static_cast<std::size_t>(lane)].onStep(t0, x0, t1, x1);
    };
    try {
      if (!integrateOnLanes(points->models, make, points->starts, sp.options->get("time"), c, onStep))
        throw Stopped{};
    } catch (const ComputationError&) {
      return std::nullopt;
    }
    std::vector<LaneValues> values;
    values.reserve(readings.size());
    for (const OrbitReading& r : readings)
      values.push_back({r.values(), nullptr});
    return values;
  };
}

std::vector<double> lyapunovExponents(const Scene& scene, const ToolControl& control) {
  const ToolResult r = runTool(ToolRegistry::global().get("lyapunov"), scene, control);
  if (r.stopped) throw Stopped{};
  return r.fields.at("exponents").get<std::vector<double>>();
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

std::vector<SweepQuantity> makeQuantities() {
  std::vector<SweepQuantity> q;
  const auto single = [](const std::string& name) {
    return [name](const SweepSpec&) { return std::vector<std::string>{name}; };
  };
  q.push_back({"lyapunov.positive", "lyapunov",
               "how many exponents exceed options.zero (finite-time estimates of zero exponents decay like "
               "1/t)",
               single("lyapunov.positive"), [](const SweepSpec& sp, const Scene& s, const ToolControl& c) {
                 const double zero = sp.options->get("zero");
                 const auto e = lyapunovExponents(s, c);
                 return std::vector<double>{static_cast<double>(
                     std::count_if(e.begin(), e.end(), [zero](double v) { return v > zero; }))};
               }});
  q.back().categorical = true;
  q.push_back({"fixedpoint.type", "fixedpoint",
               "the type of the fixed point of order fixedpoint.order found from the point: " + typeCodes(),
               single("fixedpoint.type"),
               [](const SweepSpec&, const Scene& s, const ToolControl& c) {
                 const SceneMap m(s);
                 const ReturnMap map = m.map();
                 const FixedPointResult r = findFixedPoint(map, m.guess(), m.search(), c);
                 return std::vector<double>{static_cast<double>(r.type)};
               },
               /*needsMap=*/true});
  q.back().categorical = true;
  q.push_back({"fixedpoint.order", "fixedpoint",
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
               /*needsMap=*/true});
  q.back().categorical = true;
  q.push_back(
      {"observable.", "",
       "observable.NAME: the observable's value at options.time, or its time average over [0, time] "
       "(options.statistic)",
       [](const SweepSpec& sp) { return std::vector<std::string>{sp.quantity->id + sp.quantityName}; },
       alongTheOrbit(observableReading)});
  q.back().evaluateLanes = alongTheOrbitsOnLanes(observableReading);
  q.push_back({"reversal", "",
               "reversal[.NAME]: whether the spin about the vertical (or the observable NAME) changed sign "
               "within options.time (1/0), when it first did (linear interpolation) and its value at the end",
               [](const SweepSpec&) {
                 return std::vector<std::string>{"reversed", "reversal_at", "spin_end"};
               },
               alongTheOrbit(reversalReading),
               /*needsMap=*/false, /*cloud=*/false, /*optionalName=*/true});
  q.back().evaluateLanes = alongTheOrbitsOnLanes(reversalReading);
  q.back().categorical = true; // refined where it reverses or not
  q.push_back({"orbit", "poincare",
               "an orbit diagram: the last options.orbit_points points (after options.transient) of the map "
               "coordinate options.coordinate, one row per grid point",
               [](const SweepSpec& sp) {
                 const auto names = scenePoincareMap(sp.base, 1)->coordinateNames();
                 const auto k = static_cast<std::size_t>(sp.options->get("coordinate"));
                 const std::string name = k < names.size() ? names[k] : "x";
                 std::vector<std::string> cols;
                 for (int i = 1; i <= static_cast<int>(sp.options->get("orbit_points")); ++i)
                   cols.push_back(fmt::format("{}.{}", name, i));
                 return cols;
               },
               [](const SweepSpec& sp, const Scene& s, const ToolControl& c) {
                 const auto map = scenePoincareMap(s, orbitLength(sp));
                 std::vector<MapPoint> points;
                 for (long n = 0; n < orbitLength(sp); ++n) {
                   auto p = map->next(c);
                   if (!p) {
                     if (c.stopRequested()) throw Stopped{};
                     break; // the map ended: orbitValues says so
                   }
                   points.push_back(std::move(*p));
                 }
                 return orbitValues(sp, points);
               },
               /*needsMap=*/true, /*cloud=*/true});
  // a flow's orbits on lanes, their crossings located lane by lane (dynamics/tools/TrajectoryLanes.h)
  q.back().evaluateLanes = [](const SweepSpec& sp, const std::vector<Scene>& scenes,
                              const ToolControl& c) -> std::optional<std::vector<LaneValues>> {
    const auto points = pointsOnLanes(scenes);
    if (!points) return std::nullopt;
    const IntegratorFactory make = [&] { return points->run.makeIntegrator(*points->models.front()); };
    if (!trajectoriesRunOnLanes(points->models, make)) return std::nullopt;
    SectionSettings settings = scenes.front().poincare;
    settings.maxPoints = orbitLength(sp);
    std::optional<std::vector<std::vector<MapPoint>>> orbits;
    try {
      orbits = mapPointsOnLanes(points->models, make, points->starts, settings, c);
    } catch (const ComputationError&) {
      return std::nullopt; // each alone, failing or not as alone
    }
    if (!orbits) throw Stopped{};
    std::vector<LaneValues> values;
    for (const auto& orbit : *orbits) {
      values.emplace_back();
      try {
        values.back().values = orbitValues(sp, orbit);
      } catch (const ComputationError&) {
        values.back().failure = std::current_exception();
      }
    }
    return values;
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

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s)
    q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + "\"";
}

} // namespace

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

namespace {
// grid point `index`'s scene as the quantity computes on it (narrowed to what it needs)
Scene evaluatedScene(const SweepSpec& spec, long index) {
  Scene scene = sweepPointScene(spec, index);
  if (spec.quantity->narrow) spec.quantity->narrow(scene);
  return scene;
}
} // namespace

SweepRecord evaluateSweepPoint(const SweepSpec& spec, long index, const ToolControl& control) {
  const auto start = std::chrono::steady_clock::now();
  SweepRecord r;
  try {
    const Scene scene = evaluatedScene(spec, index);
    r.values = spec.quantity->evaluate(spec, scene, control);
    r.values.resize(spec.columns.size(), kNaN);
  } catch (const Stopped&) {
    r.ok = false;
    r.reason = "stopped";
  } catch (const std::exception& e) { // InputError (no scene at these values) or ComputationError
    r.ok = false;
    r.reason = e.what();
    if (r.reason.rfind(spec.source + ":", 0) == 0) r.reason.erase(0, spec.source.size() + 1); // said once
  }
  if (!r.ok) r.values.assign(spec.columns.size(), kNaN);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

int sweepBatch(const SweepSpec& spec) {
  if (!spec.quantity->evaluateLanes) return 1;
  return spec.lanes == 0 ? laneWidth() : spec.lanes;
}

std::optional<PointsOnLanes> pointsOnLanes(const std::vector<Scene>& scenes) {
  const auto common = [](const Scene& s) {
    nlohmann::json doc = s.document;
    doc.erase("initial");
    doc.erase("parameters");
    return doc;
  };
  if (scenes.empty()) return std::nullopt;
  const nlohmann::json first = common(scenes.front());
  PointsOnLanes p{.run = scenes.front().runSpec()};
  for (const Scene& s : scenes) {
    if (common(s) != first) return std::nullopt;
    p.models.push_back(s.model.get());
    p.starts.push_back(s.initialState);
  }
  return p;
}

namespace {
// the points `indices`, whose scenes are `scenes`, together on lanes; each record to the sink
void evaluateOnLanes(const SweepSpec& spec, const std::vector<long>& indices,
                     const std::vector<Scene>& scenes, std::chrono::steady_clock::time_point start,
                     const ToolControl& control, const RecordSink& sink) {
  if (indices.size() < 2) { // alone, as a point of a sweep that does not batch
    for (const long index : indices)
      sink(index, evaluateSweepPoint(spec, index, control));
    return;
  }
  std::optional<std::vector<LaneValues>> lanes;
  try {
    lanes = spec.quantity->evaluateLanes(spec, scenes, control);
  } catch (const Stopped&) {
    for (const long index : indices)
      sink(index, {std::vector<double>(spec.columns.size(), kNaN), 0, false, "stopped"});
    return;
  } catch (const std::exception&) { // bad settings: each point says so, as alone
    lanes.reset();
  }
  if (!lanes) {
    for (const long index : indices)
      sink(index, evaluateSweepPoint(spec, index, control));
    return;
  }
  const double share = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
                       static_cast<double>(indices.size());
  for (std::size_t j = 0; j < indices.size(); ++j) {
    SweepRecord r;
    const LaneValues& lane = (*lanes)[j];
    if (lane.failure) { // the reason as evaluateSweepPoint words it
      try {
        std::rethrow_exception(lane.failure);
      } catch (const std::exception& e) {
        r.ok = false;
        r.reason = e.what();
        if (r.reason.rfind(spec.source + ":", 0) == 0) r.reason.erase(0, spec.source.size() + 1);
      }
      r.values.assign(spec.columns.size(), kNaN);
    } else {
      r.values = lane.values;
      r.values.resize(spec.columns.size(), kNaN);
    }
    r.seconds = share;
    sink(indices[j], r);
  }
}
} // namespace

void evaluateSweepPoints(const SweepSpec& spec, const std::vector<long>& indices, const ToolControl& control,
                         const RecordSink& sink) {
  const std::size_t width = static_cast<std::size_t>(sweepBatch(spec));
  std::vector<Scene> scenes;
  std::vector<long> batched;
  auto start = std::chrono::steady_clock::now();
  for (const long index : indices) {
    if (control.stopRequested()) return;
    if (width == 1) {
      sink(index, evaluateSweepPoint(spec, index, control));
      continue;
    }
    try {
      scenes.push_back(evaluatedScene(spec, index));
      batched.push_back(index);
    } catch (const std::exception&) {
      // no scene at its values: its failure, said alone; its lane is the next point's
      sink(index, evaluateSweepPoint(spec, index, control));
      continue;
    }
    if (batched.size() == width) {
      evaluateOnLanes(spec, batched, scenes, start, control, sink);
      scenes.clear();
      batched.clear();
      start = std::chrono::steady_clock::now();
    }
  }
  if (!batched.empty() && !control.stopRequested())
    evaluateOnLanes(spec, batched, scenes, start, control, sink);
}

std::vector<SweepRecord> evaluateSweepPoints(const SweepSpec& spec, const std::vector<long>& indices,
                                             const ToolControl& control) {
  std::map<long, SweepRecord> computed;
  evaluateSweepPoints(spec, indices, control,
                      [&](long index, const SweepRecord& record) { computed[index] = record; });
  std::vector<SweepRecord> records;
  records.reserve(indices.size());
  for (const long index : indices) {
    const auto found = computed.find(index);
    records.push_back(found != computed.end()
                          ? found->second
                          : SweepRecord{std::vector<double>(spec.columns.size(), kNaN), 0, false, "stopped"});
  }
  return records;
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

std::vector<std::string> sweepCsvHeader(const SweepSpec& spec, bool timing) {
  std::vector<std::string> h;
  for (const auto& a : spec.axes)
    h.push_back(a.id);
  h.insert(h.end(), spec.columns.begin(), spec.columns.end());
  if (timing) h.emplace_back("seconds");
  h.emplace_back("status");
  return h;
}

SweepChartData sweepChartData(const SweepSpec& spec) {
  SweepChartData d;
  d.title = spec.title;
  for (std::size_t k = 0; k < spec.axes.size(); ++k) {
    const SweepAxis& a = spec.axes[k];
    d.axes.push_back(spec.axisLabel(k));
    d.counts.push_back(a.count);
    d.mins.push_back(a.min);
    d.maxs.push_back(a.max);
  }
  d.columns = spec.columns;
  d.orbit = spec.quantity->cloud;
  return d;
}

namespace {

// the grid indices of a point, the first axis fastest (an axis of count 1 has index 0)
std::vector<long> gridIndices(const SweepSpec& spec, long index) {
  std::vector<long> k;
  for (const auto& a : spec.axes) {
    k.push_back(index % a.count);
    index /= a.count;
  }
  return k;
}

long gridIndex(const SweepSpec& spec, const std::vector<long>& k) {
  long index = 0;
  for (std::size_t a = spec.axes.size(); a-- > 0;)
    index = index * spec.axes[a].count + k[a];
  return index;
}

// calls visit(k) for every point from `from` to `to` (per axis, inclusive) in steps of `step`
template <class Visit>
void forLattice(const std::vector<long>& from, const std::vector<long>& to, long step, Visit visit) {
  std::vector<long> k = from;
  while (true) {
    visit(k);
    std::size_t a = 0;
    for (; a < k.size(); ++a) {
      if (k[a] + step <= to[a]) {
        k[a] += step;
        break;
      }
      k[a] = from[a];
    }
    if (a == k.size()) return;
  }
}

} // namespace

int sweepPointLevel(const SweepSpec& spec, long index) {
  int level = 0;
  const auto k = gridIndices(spec, index);
  for (std::size_t a = 0; a < k.size(); ++a) {
    int zeros = 0; // how many times 2 divides the index (an index 0 lies on every level's lattice)
    for (long v = k[a]; v != 0 && v % 2 == 0 && zeros < spec.refine; v /= 2)
      ++zeros;
    if (k[a] == 0) zeros = spec.refine;
    level = std::max(level, spec.refine - zeros);
  }
  return level;
}

std::vector<char> sweepLevelPoints(const SweepSpec& spec, const SweepStore& store, int level) {
  const long n = spec.points();
  std::vector<char> wanted(static_cast<std::size_t>(n), 0);
  if (level == 0) {
    for (long i = 0; i < n; ++i)
      wanted[static_cast<std::size_t>(i)] = sweepPointLevel(spec, i) == 0 ? 1 : 0;
    return wanted;
  }
  const long cell = 1L << (spec.refine - level + 1), half = cell / 2; // the cells of level - 1, halved
  // the quantity's range over level 0: what "differ" is measured against
  double lo = INFINITY, hi = -INFINITY;
  for (long i = 0; i < n; i += 1) {
    if (sweepPointLevel(spec, i) != 0 || !store.done(i)) continue;
    const SweepRecord r = store.read(i);
    if (r.ok && !r.values.empty() && std::isfinite(r.values[0])) {
      lo = std::min(lo, r.values[0]);
      hi = std::max(hi, r.values[0]);
    }
  }
  const double tolerance = hi > lo ? spec.refineThreshold * (hi - lo) : 0.0;
  const auto differ = [&](const SweepRecord& a, const SweepRecord& b) {
    if (a.ok != b.ok) return true;
    if (!a.ok) return false;
    const double x = a.values.empty() ? kNaN : a.values[0], y = b.values.empty() ? kNaN : b.values[0];
    if (std::isnan(x) || std::isnan(y)) return std::isnan(x) != std::isnan(y);
    if (!std::isnan(spec.refineAt)) return (x < spec.refineAt) != (y < spec.refineAt); // across the value
    return spec.quantity->categorical ? x != y : std::abs(x - y) > tolerance;
  };
  std::vector<long> origin(spec.axes.size(), 0), last(spec.axes.size()), cellLast(spec.axes.size());
  for (std::size_t a = 0; a < spec.axes.size(); ++a)
    last[a] = spec.axes[a].count > 1 ? spec.axes[a].count - 1 - cell : 0; // the last cell's origin
  forLattice(origin, last, cell, [&](const std::vector<long>& c) {
    // a cell of level - 1 exists where every corner is computed (its parent was halved)
    std::vector<SweepRecord> corners;
    std::vector<long> far(c);
    for (std::size_t a = 0; a < c.size(); ++a)
      far[a] = spec.axes[a].count > 1 ? c[a] + cell : c[a];
    bool complete = true;
    forLattice(c, far, cell, [&](const std::vector<long>& k) {
      const long i = gridIndex(spec, k);
      if (!store.done(i)) {
        complete = false;
        return;
      }
      corners.push_back(store.read(i));
    });
    if (!complete) return;
    bool split = false;
    for (std::size_t p = 1; p < corners.size() && !split; ++p)
      split = differ(corners[0], corners[p]);
    if (!split) return;
    forLattice(c, far, half, [&](const std::vector<long>& k) {
      const long i = gridIndex(spec, k);
      if (!store.done(i)) wanted[static_cast<std::size_t>(i)] = 1;
    });
  });
  return wanted;
}

bool runSweepLevels(const SweepSpec& spec, SweepStore& store, int workers,
                    const std::function<bool(ChunkScheduler&)>& runLevel) {
  const long chunk = static_cast<long>(spec.options->get("chunk"));
  for (int level = 0; level <= spec.refine; ++level) {
    ChunkScheduler scheduler(store, workers, chunk,
                             spec.refine > 0 ? sweepLevelPoints(spec, store, level) : std::vector<char>{},
                             sweepBatch(spec));
    if (!runLevel(scheduler)) return false;
  }
  return true;
}

namespace {

// the grid's values from the points computed (done(i), read(i)): see sweepGridValues
template <class Done, class Read>
std::vector<double> gridValues(const SweepSpec& spec, const Done& done, const Read& read) {
  const std::size_t columns = spec.columns.size();
  const long n = spec.points();
  std::vector<double> values(static_cast<std::size_t>(n) * columns, kNaN);
  const auto put = [&](long to, const SweepRecord& r) {
    for (std::size_t c = 0; c < columns && c < r.values.size(); ++c)
      values[static_cast<std::size_t>(to) * columns + c] = r.values[c];
  };
  if (spec.refine == 0) {
    for (long i = 0; i < n; ++i)
      if (done(i)) put(i, read(i));
    return values;
  }
  // coarse to fine: each computed point paints the box of its level's half spacing around it, finer points
  // over coarser ones
  std::vector<std::vector<long>> byLevel(static_cast<std::size_t>(spec.refine) + 1);
  for (long i = 0; i < n; ++i)
    if (done(i)) byLevel[static_cast<std::size_t>(sweepPointLevel(spec, i))].push_back(i);
  for (int level = 0; level <= spec.refine; ++level) {
    const long reach = (1L << (spec.refine - level)) / 2;
    for (long i : byLevel[static_cast<std::size_t>(level)]) {
      const SweepRecord r = read(i);
      const auto k = gridIndices(spec, i);
      std::vector<long> from(k), to(k);
      for (std::size_t a = 0; a < k.size(); ++a) {
        from[a] = std::max(0L, k[a] - reach);
        to[a] = std::min<long>(spec.axes[a].count - 1, k[a] + reach);
      }
      forLattice(from, to, 1, [&](const std::vector<long>& p) { put(gridIndex(spec, p), r); });
    }
  }
  return values;
}

} // namespace

namespace {
struct LanesEvaluators {
  std::mutex mutex;
  std::map<std::string, LanesEvaluator> byTool;
};
LanesEvaluators& lanesEvaluators() {
  static LanesEvaluators all;
  return all;
}
} // namespace

void addLanesEvaluator(const std::string& id, LanesEvaluator evaluate) {
  auto& all = lanesEvaluators();
  const std::lock_guard lock(all.mutex);
  if (!all.byTool.emplace(id, std::move(evaluate)).second)
    throw InputError("tool " + id + " has a batch evaluation on lanes already");
}

const LanesEvaluator* findLanesEvaluator(const std::string& id) {
  auto& all = lanesEvaluators();
  const std::lock_guard lock(all.mutex);
  const auto it = all.byTool.find(id);
  return it == all.byTool.end() ? nullptr : &it->second; // (entries are never removed: the pointer stays)
}

std::vector<double> sweepGridValues(const SweepSpec& spec, const SweepStore& store) {
  return gridValues(
      spec, [&](long i) { return store.done(i); }, [&](long i) { return store.read(i); });
}

std::vector<double> sweepGridValues(const SweepSpec& spec, const std::function<bool(long)>& done,
                                    const std::function<SweepRecord(long)>& read) {
  return gridValues(spec, done, read);
}

std::string sweepCsvRow(const SweepSpec& spec, long index, const SweepRecord& r, bool timing) {
  std::string row;
  for (double v : spec.axisValues(index))
    row += fmt::format("{:.17g},", v);
  for (double v : r.values)
    row += fmt::format("{:.17g},", v);
  if (timing) row += fmt::format("{:.6g},", r.seconds);
  row += r.ok ? "ok" : csvField("failed: " + r.reason);
  return row;
}

std::vector<double> readSweepCsv(const SweepSpec& spec, const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw InputError(what + " " + path + ": cannot open");
  std::string line, expected, timed;
  for (const auto& h : sweepCsvHeader(spec))
    expected += (expected.empty() ? "" : ",") + h;
  for (const auto& h : sweepCsvHeader(spec, true))
    timed += (timed.empty() ? "" : ",") + h;
  if (!std::getline(in, line) || (line != expected && line != timed))
    throw InputError(what + " " + path + ": not the CSV of this sweep (expected the header " + expected +
                     ")");
  const std::size_t first = spec.axes.size(), n = spec.columns.size();
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(spec.points()) * n);
  std::map<long, SweepRecord> computed; // a refined sweep's rows: its computed points, found by their axes
  long row = 0;
  for (; std::getline(in, line); ++row) {
    std::stringstream fields(line);
    std::string field;
    std::vector<long> k;
    SweepRecord record;
    for (std::size_t c = 0; c < first + n; ++c) {
      if (!std::getline(fields, field, ','))
        throw InputError(fmt::format("{} {}:{}: too few columns", what, path, row + 2));
      double v = kNaN;
      try {
        v = field == "nan" ? kNaN : std::stod(field);
      } catch (const std::exception&) {
        throw InputError(fmt::format("{} {}:{}: not a number '{}'", what, path, row + 2, field));
      }
      if (c >= first) {
        (spec.refine ? record.values : values).push_back(v);
        continue;
      }
      const SweepAxis& axis = spec.axes[c];
      const double at = axis.count > 1 ? (v - axis.min) / (axis.max - axis.min) * (axis.count - 1) : 0.0;
      if (!(at > -0.5 && at < axis.count - 0.5))
        throw InputError(
            fmt::format("{} {}:{}: {} = {} is off the sweep's grid", what, path, row + 2, axis.id, v));
      k.push_back(std::lround(at));
    }
    if (spec.refine) computed[gridIndex(spec, k)] = std::move(record);
  }
  if (spec.refine)
    return gridValues(
        spec, [&](long i) { return computed.count(i) > 0; }, [&](long i) { return computed.at(i); });
  if (row != spec.points())
    throw InputError(fmt::format("{} {}: {} rows, the sweep has {} points", what, path, row, spec.points()));
  return values;
}

} // namespace rv
