// PlotTap.h -- a plot filter opened on a running trajectory (manual §2.4: "creating a filter starts no
// thread; the base tools output into every open filter window as well"). The trajectory's job samples its
// own steps by the filter's rule (PlotSampler, built on the job's model) and streams the kept points to the
// window through the tap's channel.
#pragma once
#include "dynamics/jobs/Channel.h"
#include "dynamics/tools/PlotFilter.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

namespace rv {

struct PlotTap {
  explicit PlotTap(PlotSettings s) : settings(std::move(s)) {}
  const PlotSettings settings;
  /// The points kept (the axes' values), streamed to the window.
  Channel<std::vector<double>> points;
  /// Set by the window when it closes: the job then drops the tap.
  std::atomic<bool> closed{false};
};

/// The taps of one trajectory. add() from any thread; offer() and restart() on the job's thread (or while it
/// does not run).
class PlotTaps {
public:
  void add(std::shared_ptr<PlotTap> tap);
  /// Samples the integrator's last step for every open tap (samplers built on `model`; built again when the
  /// job's model is another one, after an edit).
  void offer(const Model& model, const Integrator& integrator);
  /// A new run: the samplers start again and the taps drop the old run's points not yet taken.
  void restart();

private:
  std::mutex mutex_;
  std::vector<std::shared_ptr<PlotTap>> added_; ///< guarded by mutex_
  std::atomic<bool> pending_{false};            ///< added_ is not empty
  struct Sampling {
    std::shared_ptr<PlotTap> tap;
    PlotSampler sampler;
  };
  std::vector<Sampling> sampling_; ///< the job thread's own
  const Model* model_ = nullptr;   ///< the samplers' (their observables point into it)
};

} // namespace rv
