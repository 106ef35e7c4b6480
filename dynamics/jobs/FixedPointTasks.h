// FixedPointTasks.h -- the map window's fixed-point search as a job (manual §2.3.4): it streams its path
// through a channel while it runs, stops promptly (the search polls between map evaluations), and goes on
// from its last point. A failure (no convergence, ...) ends the job with the reason in its status. (The rest
// of the family -- continuation, separatrices, bifurcation tree -- runs on the map as the registry's runners,
// scenes/ToolTask.h, scenes/MapTools.cpp.)
#pragma once
#include "dynamics/jobs/Channel.h"
#include "dynamics/jobs/RunSpec.h"
#include "dynamics/jobs/Task.h"
#include "dynamics/tools/FixedPoint.h"

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

} // namespace rv
