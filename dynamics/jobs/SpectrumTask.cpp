#include "dynamics/jobs/SpectrumTask.h"

namespace rv {

bool SpectrumTask::run(const ToolControl& control) {
  const auto model = spec_.makeModel();
  auto integ = spec_.makeIntegrator(*model);
  integ->start(*model, 0, spec_.initialState);
  SpectrumResult r = fourierSpectrum(*model, *integ, settings_, control);
  if (control.stopRequested()) return false;
  results_.push(std::move(r));
  return true;
}

} // namespace rv
