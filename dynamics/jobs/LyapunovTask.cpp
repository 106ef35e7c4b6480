#include "dynamics/jobs/LyapunovTask.h"

namespace rv {

LyapunovTask::LyapunovTask(RunSpec spec, LyapunovSettings settings)
    : spec_(std::move(spec)), settings_(settings) {
  reset();
}

void LyapunovTask::reset() {
  run_.reset();
  model_ = spec_.makeModel();
  estimates_.clear();
  const Model* m = model_.get();
  run_ = std::make_unique<LyapunovRun>(
      *model_, [this, m] { return spec_.makeIntegrator(*m); }, spec_.initialState, settings_);
}

bool LyapunovTask::run(const ToolControl& control) {
  return run_->run([this](const LyapunovEstimate& e) { estimates_.push(e); }, control);
}

} // namespace rv
