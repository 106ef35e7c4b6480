// MegnoTask.h -- the chaos indicators MEGNO and FLI (dynamics/tools/Megno.h) as a job, started from a
// trajectory's state: the map window colours the trajectory by its <Y> when the job ends.
#pragma once
#include "dynamics/jobs/RunSpec.h"
#include "dynamics/jobs/Task.h"
#include "dynamics/tools/Megno.h"

#include <memory>

namespace rv {

class MegnoTask final : public Task {
public:
  MegnoTask(RunSpec spec, MegnoSettings settings);
  std::string name() const override { return "MEGNO and FLI"; }
  std::string describe() const override { return spec_.describe(); }
  /// Goes on from where a stop left it (MegnoRun is resumable).
  bool run(const ToolControl& control) override;
  void reset() override;
  /// Only while the job does not run.
  const MegnoResult& result() const { return run_->result(); }

private:
  RunSpec spec_;
  MegnoSettings settings_;
  std::unique_ptr<Model> model_;
  std::unique_ptr<MegnoRun> run_;
};

} // namespace rv
