// FixedPointTasks.h -- the fixed-point family of tools as jobs (manual §2.3.4-§2.3.9): each streams its
// results through channels while it runs, stops promptly (the tools poll between map evaluations), and goes
// on from where it stopped: a fixed-point search from its last point, a continuation from its last step; a
// separatrix or a bifurcation tree starts again. Failures (no convergence, a non-hyperbolic point, ...) end
// the job with the reason in its status. (The map window runs them; every front end else runs the tools'
// runners, scenes/MapTools.cpp.)
#pragma once
#include "dynamics/jobs/Channel.h"
#include "dynamics/jobs/RunSpec.h"
#include "dynamics/jobs/Task.h"
#include "dynamics/tools/BifurcationTree.h"
#include "dynamics/tools/Separatrix.h"

#include <mutex>
#include <optional>

namespace rv {

/// What every task of the family starts from: the problem and method, the map (section with its order) and
/// the search settings.
struct MapTaskSpec {
  RunSpec run;
  SectionSettings section;
  FixedPointSettings search;
  Eigen::VectorXd guess;
  std::string describe() const;
};

/// A model and its map, built from a MapTaskSpec (the map refers to the model).
class MapHolder {
public:
  explicit MapHolder(const MapTaskSpec& spec);
  const ReturnMap& map() const { return *map_; }

private:
  std::unique_ptr<Model> model_;
  std::unique_ptr<ReturnMap> map_;
};

class FixedPointTask final : public Task {
public:
  explicit FixedPointTask(MapTaskSpec spec);
  std::string name() const override { return "Fixed point"; }
  std::string describe() const override { return spec_.describe(); }
  bool run(const ToolControl& control) override;
  void reset() override;
  /// New problem, method, map and search settings (while the job does not run): the search goes on from the
  /// point where it stopped (its guess is kept).
  void edit(MapTaskSpec spec);
  bool edit(const TaskEdit& e) override;
  const MapTaskSpec& spec() const { return spec_; }
  /// The search path, streamed.
  Channel<SearchPoint>& path() { return path_; }
  /// The result once finished (thread-safe).
  std::optional<FixedPointResult> result() const;

private:
  MapTaskSpec spec_;
  Eigen::VectorXd from_; ///< where the search goes on from
  Channel<SearchPoint> path_;
  mutable std::mutex mutex_;
  std::optional<FixedPointResult> result_;
};

class ContinuationTask final : public Task {
public:
  ContinuationTask(MapTaskSpec spec, ContinuationSettings settings);
  std::string name() const override { return "Fixed point continuation"; }
  std::string describe() const override;
  bool run(const ToolControl& control) override;
  void reset() override;
  /// New values (while the job does not run): the family is continued again from the task's own guess.
  void edit(MapTaskSpec spec, ContinuationSettings settings);
  bool edit(const TaskEdit& e) override;
  Channel<ContinuationPoint>& points() { return points_; }
  Channel<TypeChange>& changes() { return changes_; }

private:
  MapTaskSpec spec_;
  ContinuationSettings settings_;
  std::unique_ptr<Continuation> continuation_;
  Channel<ContinuationPoint> points_;
  Channel<TypeChange> changes_;
};

class SeparatrixTask final : public Task {
public:
  SeparatrixTask(MapTaskSpec spec, SeparatrixSettings settings);
  std::string name() const override { return "Separatrix"; }
  std::string describe() const override { return spec_.describe(); }
  bool run(const ToolControl& control) override;
  void reset() override { points_.clear(); }
  /// New values (while the job does not run): the branch (kept) grows again from the task's own guess.
  void edit(MapTaskSpec spec, SeparatrixSettings settings);
  bool edit(const TaskEdit& e) override;
  const SeparatrixSettings& settings() const { return settings_; }
  /// Batches of new points along the branch.
  Channel<std::vector<Eigen::VectorXd>>& points() { return points_; }

private:
  MapTaskSpec spec_;
  SeparatrixSettings settings_;
  Channel<std::vector<Eigen::VectorXd>> points_;
};

/// A point of a bifurcation tree, with its family's level and order.
struct TreePoint {
  int level = 0, order = 1;
  ContinuationPoint point;
};

class BifurcationTreeTask final : public Task {
public:
  BifurcationTreeTask(MapTaskSpec spec, BifurcationTreeSettings settings);
  std::string name() const override { return "Bifurcation tree"; }
  std::string describe() const override { return spec_.describe(); }
  bool run(const ToolControl& control) override;
  void reset() override;
  /// New values (while the job does not run): the tree grows again from the task's own guess.
  void edit(MapTaskSpec spec, BifurcationTreeSettings settings);
  bool edit(const TaskEdit& e) override;
  Channel<TreePoint>& points() { return points_; }
  Channel<PeriodDoubling>& doublings() { return doublings_; }
  /// Why the tree ended (BifurcationTreeResult::end), once it has.
  Channel<std::string>& ends() { return ends_; }

private:
  MapTaskSpec spec_;
  BifurcationTreeSettings settings_;
  Channel<TreePoint> points_;
  Channel<PeriodDoubling> doublings_;
  Channel<std::string> ends_;
};

} // namespace rv
