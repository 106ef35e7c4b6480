#include "dynamics/jobs/MegnoTask.h"

namespace rv {

MegnoTask::MegnoTask(RunSpec spec, MegnoSettings settings) : spec_(std::move(spec)), settings_(settings) {
  reset();
}

void MegnoTask::reset() {
  run_.reset();
  model_ = spec_.makeModel();
  const Model* m = model_.get();
  run_ = std::make_unique<MegnoRun>(
      *model_, [this, m] { return spec_.makeIntegrator(*m); }, spec_.initialState, settings_);
}

bool MegnoTask::run(const ToolControl& control) {
  return run_->run({}, control);
}

} // namespace rv
