// ChartTask.h -- a chart view of a scene (SceneCharts) computed as a Task, so that every long computation
// runs as a Job in the job tree: listed in the tool manager with its progress, stopped, continued, edited and
// deleted there like the map's tools. After a stop, Continue goes on from the stop point where the view keeps
// its computation (SceneCharts.h ChartProgress: the Poincare map, Map3D, Lyapunov, MEGNO, surface, RAM) and
// computes the rest again from the start (the same result: every computation here is deterministic); what
// was computed before a stop is kept as a partial chart where the view can draw one.
#pragma once
#include "dynamics/jobs/Task.h"
#include "render/charts/Chart.h"
#include "scenes/Scene.h"
#include "scenes/SceneCharts.h"

#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>

namespace rv {

class ChartTask final : public Task {
public:
  /// `document` is the scene after its edits; `source` names it in messages; `diagram` picks the bifurcation
  /// view's diagram (empty: the problem's first).
  ChartTask(const nlohmann::json& document, std::string source, std::string view, std::string diagram = "");
  std::string name() const override;
  std::string describe() const override { return describe_; }
  /// Computes the chart; false when stopped on request (a partial chart may be kept). Throws InputError or
  /// ComputationError when the view cannot be computed (the job records the reason).
  bool run(const ToolControl& control) override;
  void reset() override;
  /// Takes a new scene document (the control panel's values); the next run computes with it.
  void edit(const nlohmann::json& document);
  /// Edit properties: the edited scene's document; the chart is computed again (returns false).
  bool edit(const TaskEdit& e) override;
  bool ownsItsScene() const override { return true; }

  const std::string& view() const { return view_; }
  const std::string& diagram() const { return diagram_; }
  /// The chart of the last run (finished, or partial after a stop); nullptr before. Thread-safe; the caller
  /// may attach it to a window once the job does not run.
  std::shared_ptr<Chart> chart() const;
  /// How many times the chart was computed to its end (tests).
  int completed() const;

private:
  std::string source_, view_, diagram_, describe_;
  Scene
      scene_; ///< parsed once per edit; read by run() only while the job runs, changed only while it does not
  mutable std::mutex mutex_;
  std::shared_ptr<Chart> chart_;
  std::unique_ptr<ChartProgress> progress_; ///< a stopped resumable view's computation; used by run() only
  int completed_ = 0;
};

} // namespace rv
