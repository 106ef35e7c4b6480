// SceneCharts.h -- every chart view of a scene (manual §2.4.1-§2.4.4), computed and drawn: one per
// registered tool that has a chart (its ToolEntry::chartView; chartViews() lists them in menu order,
// `rollviz chart --help` names them; the 2D / 3D plot filter, scene section "plot", among them). One
// definition for `rollviz chart`, the image tests and the GUI.
#pragma once
#include "render/charts/Chart3D.h"
#include "render/charts/PlotChart.h"
#include "render/charts/PoincareChart.h"
#include "scenes/Scene.h"

#include <memory>
#include <string>
#include <vector>

namespace rv {

/// The view names, in menu order.
const std::vector<std::string>& chartViews();
/// A view's title for menus: the title of the registered tool it draws (the view's name when none).
std::string chartTitle(const std::string& view);

/// What a chart's computation keeps between the runs of its job, so that a stopped chart goes on from where
/// it stopped: the Poincare map and Map3D (the map and its points), the Lyapunov exponents and MEGNO (the run
/// and its curves), the surface and the RAM (the grid's rows). The other views compute again.
class ChartProgress {
public:
  virtual ~ChartProgress() = default;
};

/// Computes what `view` shows for the scene and draws it. `points` > 0 overrides poincare.points; `diagram`
/// is the scene's diagram.diagram for this chart: the bifurcation view's diagram (empty: the scene's). Throws
/// InputError for an unknown view or one the problem does not have; Stopped results are drawn as far as they
/// got. With `progress`, a resumable view keeps its computation there and, called again with the same scene
/// after a stop, goes on from it (the caller drops it when the scene changes).
std::unique_ptr<Chart> sceneChart(const Scene& scene, const std::string& view, const ToolControl& control,
                                  long points = 0, const std::string& diagram = "",
                                  std::unique_ptr<ChartProgress>* progress = nullptr);

struct Session;
/// A saved GUI session's map (scenes/Session.h): every trajectory's shown points (its Set range) in its
/// colour, the fixed points and families its tools drew, the axes named by the scene; nothing is computed.
std::unique_ptr<PoincareChart> sessionMapChart(const Session& s);

} // namespace rv
