#include "dynamics/jobs/PlotTap.h"

#include "dynamics/core/Errors.h"

#include <algorithm>

namespace rv {

void PlotTaps::add(std::shared_ptr<PlotTap> tap) {
  std::lock_guard lock(mutex_);
  added_.push_back(std::move(tap));
  pending_ = true;
}

void PlotTaps::offer(const Model& model, const Integrator& integrator) {
  if (&model != model_) { // a new model (an edit): the samplers read the old one's observables
    model_ = &model;
    std::vector<Sampling> rebuilt;
    for (auto& s : sampling_)
      try {
        rebuilt.push_back({s.tap, PlotSampler(model, s.tap->settings)});
      } catch (const InputError&) { // cannot happen for the same problem; the tap is dropped if it does
      }
    sampling_ = std::move(rebuilt);
  }
  if (pending_.load(std::memory_order_acquire)) {
    std::vector<std::shared_ptr<PlotTap>> added;
    {
      std::lock_guard lock(mutex_);
      std::swap(added, added_);
      pending_ = false;
    }
    for (auto& tap : added) {
      try {
        sampling_.push_back({tap, PlotSampler(model, tap->settings)});
      } catch (const InputError&) { // the window checked its settings on the scene's model: nothing to do
      }
    }
  }
  if (sampling_.empty()) return;
  std::erase_if(sampling_, [](const Sampling& s) { return s.tap->closed.load() || s.sampler.full(); });
  for (auto& s : sampling_)
    s.sampler.offerStep(integrator, [&](const std::vector<double>& v) { s.tap->points.push(v); });
}

void PlotTaps::restart() {
  for (auto& s : sampling_) {
    s.sampler.clear();
    s.tap->points.clear(); // the old run's points not yet taken
  }
}

} // namespace rv
