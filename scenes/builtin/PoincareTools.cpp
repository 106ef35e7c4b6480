// PoincareTools.cpp -- the tools on a scene's trajectory and map that draw points (BuiltinTool.h): poincare
// (the map's points; resumable, so `--checkpoint` and a stopped chart go on), map3d (the map in three
// dimensions) and plot (the plot section's observables along the trajectory). Their charts are
// BuiltinCharts.cpp's.
#include "dynamics/core/Errors.h"
#include "dynamics/core/NaN.h"
#include "dynamics/tools/PlotFilter.h"
#include "dynamics/tools/TrajectoryLanes.h"
#include "scenes/SceneTools.h"
#include "scenes/builtin/BuiltinTool.h"

#include <fmt/core.h>
#include <limits>

namespace rv {

namespace {

// The map's points from the scene's initial state, resumable: poincare's rows are the map coordinates, the
// time and the sheet; map3d's three coordinates (a 3D map's, else the first three state variables at each
// crossing of a 2D map's section)
class MapPointsRun final : public ToolRun {
public:
  MapPointsRun(const Scene& scene, bool threeD) : map_(scenePoincareMap(scene)), threeD_(threeD) {
    const auto& names = map_->coordinateNames();
    if (!threeD_) {
      table_.names = names;
      table_.names.insert(table_.names.end(), {"t", "sheet"});
    } else {
      const auto& state = scene.model->info().stateNames;
      fromState_ = names.size() < 3;
      if (fromState_ && state.size() < 3)
        throw InputError("map3d: " + scene.model->info().id + " has no 3D map");
      const auto& n = fromState_ ? state : names;
      table_.names = {n[0], n[1], n[2]};
    }
    table_.values.assign(table_.names.size(), {});
  }
  bool advance(const ToolControl& control) override {
    while (auto p = map_->next(control)) {
      std::vector<double> row;
      if (!threeD_) {
        row = p->coordinates;
        row.insert(row.end(), {p->time, static_cast<double>(p->sheet)});
      } else {
        for (int i = 0; i < 3; ++i)
          row.push_back(fromState_ ? map_->lastState()[i] : p->coordinates[static_cast<std::size_t>(i)]);
      }
      table_.addRow(row);
    }
    return !control.stopRequested();
  }
  ToolResult result() const override {
    ToolResult r;
    r.table = table_;
    r.cloud = threeD_ ? 3 : static_cast<int>(std::min<std::size_t>(3, map_->coordinateNames().size()));
    r.fields = {{"points", table_.rows()}};
    return r;
  }
  void save(Snapshot& state) const override {
    map_->save(state);
    putTable(state, table_);
  }
  void restore(Snapshot& state) override {
    map_->restore(state);
    getTable(state, table_);
  }

private:
  std::unique_ptr<PoincareMap> map_;
  bool threeD_;
  bool fromState_ = false;
  NamedColumns table_;
};

// the plot section's observables along the scene's trajectory (dynamics/tools/PlotFilter.h)
ToolResult runPlot(const Scene& scene, const ToolControl& control) {
  auto integ = scene.startIntegrator();
  const auto points = samplePlot(*scene.model, *integ, scene.plot.settings, control, "plot");
  ToolResult r;
  r.table.names = scene.plot.settings.axes;
  r.table.values.assign(r.table.names.size(), {});
  for (const auto& p : points)
    r.table.addRow(p);
  r.fields = {{"points", r.table.rows()}};
  r.stopped = control.stopRequested();
  return r;
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

// orbit: an orbit diagram, the map's points after a transient, one row per grid point
SweepQuantity orbitDiagram() {
  SweepQuantity q{
      "orbit",
      "poincare",
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
      /*needsMap=*/true,
      /*cloud=*/true};
  // a flow's orbits on lanes, their crossings located lane by lane (dynamics/tools/TrajectoryLanes.h)
  q.evaluateLanes = [](const SweepSpec& sp, const std::vector<Scene>& scenes,
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
  return q;
}

} // namespace

BuiltinTool poincareTool() {
  return {
      .entry = {.id = "poincare",
                .title = "Poincaré map",
                .description =
                    "a trajectory's crossings of the section (poincare.section = poincare.value), on the "
                    "map window",
                .section = "poincare",
                .command = "poincare",
                .commandHelp = "points of the Poincare map of a scene's trajectory, as CSV",
                .chartView = "poincare",
                .outputs = {{"<map coordinates>", "the point on the section"},
                            {"t", "the time of the crossing"},
                            {"sheet", "the root of the completion the point lies on"}},
                .reference = "manual §2.3.1",
                .computation =
                    "dynamics/tools/PoincareMap.h (PoincareMap); as a job dynamics/jobs/PoincareTask.h"},
      .settings = ToolSection{.title = "Poincaré map", .table = &poincareTable(), .observableKey = "section"},
      .runner = ToolRunner{.start = [](const Scene& s) { return std::make_unique<MapPointsRun>(s, false); },
                           .tableIsResult = true,
                           .window = ToolWindow::MapTrajectory,
                           .cloud = true},
      .quantities = {orbitDiagram()}};
}

BuiltinTool map3dTool() {
  return {
      .entry =
          {.id = "map3d",
           .title = "Map3D",
           .parent = "poincare",
           .description = "the map in three dimensions (a chart window)",
           .command = "map3d",
           .commandHelp =
               "the map's points in three dimensions (a 2D map's: the first three state variables), as CSV",
           .chartView = "map3d",
           .outputs = {{"<three coordinates>", "the points in space"}},
           .reference = "manual §2.3.1",
           .computation = "dynamics/tools/PoincareMap.h (PoincareMap)"},
      .runner =
          ToolRunner{.start = [](const Scene& s) { return std::make_unique<MapPointsRun>(s, true); },
                     .arguments = {{"points", "N", "how many points (default: the scene's poincare.points)",
                                    [](const std::string& value) {
                                      return std::vector<SceneOverride>{{"poincare.points", value}};
                                    }}},
                     .tableIsResult = true,
                     .cloud = true}};
}

BuiltinTool plotTool() {
  return {
      .entry = {.id = "plot",
                .title = "2D / 3D plot",
                .parent = "poincare",
                .description =
                    "the plot section's observables along the 3D view's run and every trajectory of the map "
                    "(a live filter window)",
                .section = "plot",
                .command = "plot",
                .commandHelp = "the plot section's observables along a scene's trajectory, as CSV",
                .chartView = "plot",
                .outputs = {{"<plot.x, plot.y[, plot.z]>", "the observables at each output"}},
                .reference = "manual §2.4.1-§2.4.2",
                .computation = "dynamics/tools/PlotFilter.h (PlotSampler); live: dynamics/jobs/PlotTap.h"},
      .settings = ToolSection{.title = "2D / 3D plot", .table = &plotTable()},
      .runner = ToolRunner{.run = runPlot, .tableIsResult = true, .window = ToolWindow::PlotWindow}};
}

} // namespace rv
