#include "scenes/SceneCharts.h"
#include "scenes/ScenePage.h"

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

} // namespace

const std::vector<std::string>& chartViews() {
  static const std::vector<std::string> v = [] {
    std::vector<std::string> names;
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
  if (points > 0) // the map's points, for this chart
    return sceneChart(
        sceneFromJson(scene.document, scene.source, {{"poincare.points", std::to_string(points)}}), view,
        control, 0, "", progress);
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
  const PageMap map = sessionPageMap(s); // one definition of what a session's map draws
  auto chart = std::make_unique<PoincareChart>(map.xName, map.yName);
  for (const auto& series : map.series)
    switch (series.kind) {
    case PageMapSeries::Kind::Points:
      chart->addSeries(series.x, series.y, series.colour);
      break;
    case PageMapSeries::Kind::Curve:
      chart->addCurve(series.x, series.y, series.colour, 1.5);
      break;
    case PageMapSeries::Kind::Markers:
      chart->addMarkers(series.x, series.y, series.colour);
      break;
    }
  return chart;
}

} // namespace rv
