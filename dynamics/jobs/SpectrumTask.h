// SpectrumTask.h -- the Fourier spectrum of an observable along a trajectory, as a job (one result at the
// end).
#pragma once
#include "dynamics/jobs/Channel.h"
#include "dynamics/jobs/RunSpec.h"
#include "dynamics/jobs/Task.h"
#include "dynamics/tools/FourierSpectrum.h"

namespace rv {

class SpectrumTask final : public Task {
public:
  SpectrumTask(RunSpec spec, SpectrumSettings settings)
      : spec_(std::move(spec)), settings_(std::move(settings)) {}
  std::string name() const override { return "Fourier spectrum"; }
  std::string describe() const override { return spec_.describe() + " function(" + settings_.function + ")"; }
  /// Samples from the start each time (a spectrum needs its samples in one piece).
  bool run(const ToolControl& control) override;
  void reset() override { results_.clear(); }
  Channel<SpectrumResult>& results() { return results_; }

private:
  RunSpec spec_;
  SpectrumSettings settings_;
  Channel<SpectrumResult> results_;
};

} // namespace rv
