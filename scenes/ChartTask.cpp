#include "scenes/ChartTask.h"

#include "dynamics/core/Errors.h"
#include "dynamics/tools/ReturnMap.h"
#include "scenes/SceneCharts.h"
#include "scenes/SceneLoader.h"

namespace rv {

ChartTask::ChartTask(const nlohmann::json& document, std::string source, std::string view,
                     std::string diagram)
    : source_(std::move(source)), view_(std::move(view)), diagram_(std::move(diagram)) {
  edit(document);
}

std::string ChartTask::name() const {
  return chartTitle(view_) + (diagram_.empty() ? "" : " " + diagram_);
}

void ChartTask::edit(const nlohmann::json& document) {
  // parsed and validated once, now (bad input is reported to whoever edits); every run computes from it
  Scene next = sceneFromJson(document, source_); // bad input leaves the task as it was
  progress_.reset();                             // computed from the old scene: dropped before it goes
  scene_ = std::move(next);
  describe_ = scene_.runSpec().describe();
}

bool ChartTask::edit(const TaskEdit& e) {
  edit(nlohmann::json::parse(e.document()));
  return false;
}

bool ChartTask::run(const ToolControl& control) {
  std::shared_ptr<Chart> chart;
  try {
    chart = sceneChart(scene_, view_, control, 0, diagram_, &progress_);
  } catch (const Stopped&) {
    return false;
  }
  const bool stopped = control.stopRequested();
  if (!stopped) progress_.reset(); // done: a later run computes afresh
  std::lock_guard lock(mutex_);
  chart_ = std::move(chart);
  if (!stopped) ++completed_;
  return !stopped;
}

void ChartTask::reset() {
  progress_.reset();
  std::lock_guard lock(mutex_);
  chart_.reset();
}

std::shared_ptr<Chart> ChartTask::chart() const {
  std::lock_guard lock(mutex_);
  return chart_;
}

int ChartTask::completed() const {
  std::lock_guard lock(mutex_);
  return completed_;
}

} // namespace rv
