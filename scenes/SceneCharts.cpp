#include "scenes/SceneCharts.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"
#include "dynamics/tools/FixedPoint.h"
#include "dynamics/tools/ToolRegistry.h"
#include "render/charts/ToolCharts.h"
#include "scenes/BuiltinTools.h"
#include "scenes/SceneLoader.h"
#include "scenes/SceneTools.h"
#include "scenes/Session.h"
#include "scenes/ToolRunner.h"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>

namespace rv {

std::string chartTitle(const std::string& view) {
  for (const auto& e : ToolRegistry::global().entries())
    if (e.chartView == view) return e.title;
  return view;
}

namespace {

// a run of a tool that runs through ToolRunner.h (ToolRun: a stopped one goes on)
struct ToolRunProgress final : ChartProgress {
  explicit ToolRunProgress(std::unique_ptr<ToolRun> r) : run(std::move(r)) {}
  std::unique_ptr<ToolRun> run;
};

struct MapProgress final : ChartProgress {
  MapProgress(const Scene& scene, long points) : model(scene.model), map(scenePoincareMap(scene, points)) {}
  std::shared_ptr<const Model> model;
  std::unique_ptr<PoincareMap> map;
  std::array<std::vector<double>, 3> c;
};

// One builder per view: what it computes and how it is drawn. The table below is the only place a view's name
// is matched; the menu order is the table's.
struct ChartRequest {
  long points;
  std::unique_ptr<ChartProgress>* progress; ///< where a resumable view keeps its computation, or nullptr
};

// The computation of a resumable view: the one kept from the last run when there is one (a stopped chart goes
// on), else a new one, kept for the next run when the caller keeps progress.
template <class P, class... Args>
P& progressOf(const ChartRequest& r, std::unique_ptr<ChartProgress>& local, Args&&... args) {
  std::unique_ptr<ChartProgress>& slot = r.progress ? *r.progress : local;
  if (!dynamic_cast<P*>(slot.get())) slot = std::make_unique<P>(std::forward<Args>(args)...);
  return static_cast<P&>(*slot);
}

using ChartBuilder = std::unique_ptr<Chart> (*)(const Scene&, const ChartRequest&, const ToolControl&);

// a 3D map's three coordinates; a 2D map's points on the energy level, in the first three state variables
std::unique_ptr<Chart> map3dChart(const Scene& scene, const ChartRequest& r, const ToolControl& control) {
  std::unique_ptr<ChartProgress> local;
  auto& progress = progressOf<MapProgress>(r, local, scene, r.points);
  const auto& map = progress.map;
  const bool threeD = map->coordinateNames().size() >= 3;
  const auto& state = scene.model->info().stateNames;
  if (!threeD && state.size() < 3)
    throw InputError("--view map3d: " + scene.model->info().id + " has no 3D map");
  auto& c = progress.c;
  while (auto p = map->next(control))
    for (int i = 0; i < 3; ++i)
      c[i].push_back(threeD ? p->coordinates[i] : map->lastState()[i]);
  const auto& n = threeD ? map->coordinateNames() : state;
  auto chart3 = std::make_unique<Chart3D>(std::array<std::string, 3>{n[0], n[1], n[2]});
  chart3->addSeries(c[0], c[1], c[2], seriesColor(0), 3);
  return chart3;
}

std::unique_ptr<Chart> plotChart(const Scene& scene, const ChartRequest&, const ToolControl& control) {
  const PlotView& pv = scene.plot;
  auto integ = scene.startIntegrator();
  const auto pts = samplePlot(*scene.model, *integ, pv.settings, control, "plot");
  std::array<std::vector<double>, 3> c;
  for (const auto& p : pts)
    for (std::size_t i = 0; i < p.size(); ++i)
      c[i].push_back(p[i]);
  auto plot = std::make_unique<PlotChart>(pv.settings.axes, pv.chart);
  plot->setSeries(plot->addSeries(seriesColor(0)), c);
  return plot;
}

std::unique_ptr<Chart> poincareChart(const Scene& scene, const ChartRequest& r, const ToolControl& control) {
  std::unique_ptr<ChartProgress> local;
  auto& progress = progressOf<MapProgress>(r, local, scene, r.points);
  const auto& map = progress.map;
  auto& x = progress.c[0];
  auto& y = progress.c[1];
  while (auto p = map->next(control)) {
    x.push_back(p->coordinates.at(0));
    y.push_back(p->coordinates.size() > 1 ? p->coordinates[1] : p->time);
  }
  const auto& names = map->coordinateNames();
  auto chart = std::make_unique<PoincareChart>(names.at(0), names.size() > 1 ? names[1] : "t");
  chart->addSeries(x, y, seriesColor(0));
  chart->select(0);
  return chart;
}

std::unique_ptr<Chart> multipliersChart(const Scene& scene, const ChartRequest&, const ToolControl& control) {
  auto chart = std::make_unique<PoincareChart>("Re", "Im");
  drawMultipliers(*chart, multiplierPath(SceneMap(Scene(scene)), control));
  return chart;
}

// a tool that runs through ToolRunner.h: its own chart, or its table's columns against the first
std::unique_ptr<Chart> toolResultChart(const ToolEntry& tool, const Scene& scene, const ToolResult& result) {
  registerBuiltinCharts();
  if (const ToolRunner* runner = findToolRunner(tool.id); runner && runner->chart)
    return runner->chart(scene, result);
  const auto& t = result.table;
  if (t.names.size() < 2) throw InputError("tool '" + tool.id + "' has no table to draw");
  auto chart = std::make_unique<PoincareChart>(t.names[0], tool.title);
  std::vector<std::vector<double>> ys(t.values.begin() + 1, t.values.end());
  std::vector<std::string> names(t.names.begin() + 1, t.names.end());
  drawCurves(*chart, t.values[0], ys, {}, names);
  std::string title = tool.title;
  for (const auto& o : tool.outputs)
    if (o.quantity && result.fields.contains(o.name) && result.fields[o.name].is_number())
      title += fmt::format("  {} = {:.6g}", o.name, result.fields[o.name].get<double>());
  chart->setTitle(title);
  return chart;
}

const std::vector<std::pair<std::string, ChartBuilder>>& chartBuilders() {
  static const std::vector<std::pair<std::string, ChartBuilder>> b{{"poincare", poincareChart},
                                                                   {"map3d", map3dChart},
                                                                   {"plot", plotChart},
                                                                   {"multipliers", multipliersChart}};
  return b;
}

} // namespace

const std::vector<std::string>& chartViews() {
  static const std::vector<std::string> v = [] {
    std::vector<std::string> names;
    for (const auto& [name, build] : chartBuilders())
      names.push_back(name);
    for (const auto& e : ToolRegistry::global().entries()) // the views of the tools that run by themselves
      if (runnableToolOfView(e.chartView) == &e) names.push_back(e.chartView);
    return names;
  }();
  return v;
}

std::unique_ptr<Chart> sceneChart(const Scene& scene, const std::string& view, const ToolControl& control,
                                  long points, const std::string& diagram,
                                  std::unique_ptr<ChartProgress>* progress) {
  if (!diagram.empty()) // the scene's diagram.diagram, for this chart
    return sceneChart(
        sceneFromJson(scene.document, scene.source, {{"diagram.diagram", nlohmann::json(diagram).dump()}}),
        view, control, points, "", progress);
  for (const auto& [name, build] : chartBuilders())
    if (name == view) {
      auto chart = build(scene, {points, progress}, control);
      if (auto* plane = dynamic_cast<PoincareChart*>(chart.get())) // every chart says what it is
        plane->setTitle(chartTitle(view));
      return chart;
    }
  if (const ToolEntry* tool = runnableToolOfView(view)) {
    std::unique_ptr<ChartProgress> local;
    std::unique_ptr<ChartProgress>& slot = progress ? *progress : local;
    if (!dynamic_cast<ToolRunProgress*>(slot.get()))
      slot = std::make_unique<ToolRunProgress>(startTool(*tool, scene));
    ToolRun& run = *static_cast<ToolRunProgress&>(*slot).run;
    const bool finished = run.advance(control);
    ToolResult result = run.result();
    result.stopped = !finished;
    return toolResultChart(*tool, scene, result);
  }
  std::string known;
  for (const auto& v : chartViews())
    known += " " + v;
  throw InputError("--view " + view + ": unknown (views:" + known + ")");
}

std::unique_ptr<PoincareChart> sessionMapChart(const Session& s) {
  const Scene scene = sceneFromJson(s.scene, s.scenePath.empty() ? "session" : s.scenePath);
  const auto names = PoincareMap(*scene.model, scene.startIntegrator(), scene.poincare).coordinateNames();
  auto chart = std::make_unique<PoincareChart>(names.at(0), names.size() > 1 ? names[1] : "t");
  for (const auto& t : s.trajectories) {
    // the range the window showed (Set range): points first..last, 1-based
    const auto n = static_cast<long>(t.x.size());
    const long from = std::min(n, t.first - 1), to = t.last > 0 ? std::min(n, t.last) : n;
    const std::vector<double> x(t.x.begin() + from, t.x.begin() + std::max(from, to));
    const std::vector<double> y(t.y.begin() + from, t.y.begin() + std::max(from, to));
    chart->addSeries(x, y, t.colour);
  }
  for (const auto& t : s.tools) {
    if (t.found.empty()) { // a family, a separatrix branch, a tree: their points
      chart->addSeries(t.x, t.y, t.colour);
      continue;
    }
    // a search found its point: the path it took, its steps, and a cross where it ended (as the window drew
    // it)
    chart->addCurve(t.x, t.y, t.colour, 1.5);
    chart->addSeries(t.x, t.y, t.colour);
    chart->addMarkers({t.found[0]}, {t.found[1]}, t.colour);
  }
  return chart;
}

} // namespace rv
