// PoincareTask.h -- a Poincare map as a job: streams map points; after an edit of the problem, method or
// section parameters it goes on from its last point, completed again through the new integrals where it can
// be.
#pragma once
#include "dynamics/jobs/Channel.h"
#include "dynamics/jobs/PlotTap.h"
#include "dynamics/jobs/RunSpec.h"
#include "dynamics/jobs/Task.h"
#include "dynamics/tools/PoincareMap.h"

namespace rv {

class PoincareTask final : public Task {
public:
  PoincareTask(RunSpec spec, SectionSettings settings);
  std::string name() const override { return "Poincare map"; }
  std::string describe() const override;
  bool run(const ToolControl& control) override;
  void reset() override;

  /// Only while the job does not run (Job::edit). Throws InputError, changing nothing, when the last point
  /// has no state under the new parameters (it lies outside the new region of allowed motion).
  void edit(RunSpec spec, SectionSettings settings);
  /// Goes on from its last point, completed on the new level.
  bool edit(const TaskEdit& e) override;
  const RunSpec& spec() const { return spec_; }
  const SectionSettings& settings() const { return settings_; }
  /// The points as they come (thread-safe). Bounded: a job whose points nobody takes pauses at
  /// kChannelCapacity of them (about 20 MB) until they are taken, so a map streaming 10^7 points holds no
  /// more than that in memory here.
  Channel<MapPoint>& points() { return points_; }
  static constexpr std::size_t kChannelCapacity = 1 << 18;
  /// The plot filters fed by this trajectory's steps (thread-safe to add to while it runs).
  PlotTaps& taps() { return taps_; }
  /// A state on the trajectory's current level of the integrals: where it began or where it went on after
  /// its last edit. Readable while it runs (only reset and edit change it, and the job is stopped for them).
  const Eigen::VectorXd& levelState() const { return levelState_; }
  /// The full state at the last point (the trajectory's "current" state for the tools hung under it); only
  /// while the job does not run.
  Eigen::VectorXd lastState() const;
  const std::vector<std::string>& coordinateNames() const { return map_->coordinateNames(); }
  /// Saves where the trajectory stands (only while the job does not run): restore() into a task made with the
  /// same spec and settings goes on with the same points, bit for bit (the GUI's jobs across a restart).
  void save(Snapshot& s) const;
  void restore(Snapshot& s);
  /// `more` points beyond the limit it has (only while the job does not run; Job::edit): a finished
  /// trajectory goes on from where it stopped, bit for bit as if its limit had been the larger one. Nothing
  /// changes for a trajectory without a limit.
  void extend(long more);
  /// The points it has produced, and how many it makes in all (0: no limit).
  long produced() const { return produced_; }
  long limit() const { return settings_.maxPoints; }

private:
  void build(const Eigen::VectorXd& x0, double t0);
  RunSpec spec_;
  SectionSettings settings_;
  std::unique_ptr<Model> model_;
  std::unique_ptr<PoincareMap> map_;
  std::optional<MapPoint> last_;
  Eigen::VectorXd levelState_;
  long produced_ = 0;
  long builtAt_ = 0; ///< points produced when the map was last built (its point limit counts from there)
  Channel<MapPoint> points_{kChannelCapacity};
  PlotTaps taps_;
};

} // namespace rv
