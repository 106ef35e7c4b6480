// LyapunovTask.h -- Lyapunov exponents as a job, started from a trajectory's state; streams the running
// estimates.
#pragma once
#include "dynamics/jobs/Channel.h"
#include "dynamics/jobs/RunSpec.h"
#include "dynamics/jobs/Task.h"
#include "dynamics/tools/Lyapunov.h"

namespace rv {

class LyapunovTask final : public Task {
public:
  LyapunovTask(RunSpec spec, LyapunovSettings settings);
  std::string name() const override { return "Lyapunov exponents"; }
  std::string describe() const override { return spec_.describe(); }
  bool run(const ToolControl& control) override;
  void reset() override;
  Channel<LyapunovEstimate>& estimates() { return estimates_; }
  /// Only while the job does not run.
  const LyapunovResult& result() const { return run_->result(); }

private:
  RunSpec spec_;
  LyapunovSettings settings_;
  std::unique_ptr<Model> model_;
  std::unique_ptr<LyapunovRun> run_;
  Channel<LyapunovEstimate> estimates_;
};

} // namespace rv
