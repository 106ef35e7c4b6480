// PoincareTools.cpp -- the runners of the tools on a scene's trajectory and map that draw points
// (scenes/ToolRunner.h): poincare (the map's points; resumable, so `--checkpoint` and a stopped chart go on),
// map3d (the map in three dimensions) and plot (the plot section's observables along the trajectory). Their
// charts are scenes/BuiltinCharts.cpp.
#include "dynamics/core/Errors.h"
#include "dynamics/tools/PlotFilter.h"
#include "scenes/BuiltinTools.h"
#include "scenes/SceneTools.h"
#include "scenes/ToolRunner.h"

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

} // namespace

void registerPoincareTools() {
  addToolRunner("poincare", {.start = [](const Scene& s) { return std::make_unique<MapPointsRun>(s, false); },
                             .tableIsResult = true,
                             .window = ToolWindow::MapTrajectory,
                             .cloud = true});
  addToolRunner("map3d",
                {.start = [](const Scene& s) { return std::make_unique<MapPointsRun>(s, true); },
                 .arguments = {{"points", "N", "how many points (default: the scene's poincare.points)",
                                [](const std::string& value) {
                                  return std::vector<SceneOverride>{{"poincare.points", value}};
                                }}},
                 .tableIsResult = true,
                 .cloud = true});
  addToolRunner("plot", {.run = runPlot, .tableIsResult = true, .window = ToolWindow::PlotWindow});
}

} // namespace rv
