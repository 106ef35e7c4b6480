#include "dynamics/tools/LaneStack.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/OneLane.h"

#include <algorithm>

namespace rv {

LaneStack::LaneStack(const Model& base, const LaneKernel& kernel, int perLane, const std::string& what)
    : detail::LaneStackInfo{derivedSystemInfo(base.info(), base.info().id + "+" + what,
                                              kernel.width() * perLane)},
      Model(stackInfo, base.parameters()), kernel_(kernel), lanes_(kernel.width()) {}

void LaneStack::jacobian(const double*, double*) const {
  throw ComputationError("the Jacobian of " + info().id + " is not available");
}

void LaneStack::ownLaneSystems(const std::vector<const Model*>& models,
                               const std::function<std::unique_ptr<Model>(const Model&)>& alone) {
  laneSystems_.clear();
  for (int l = 0; l < lanes_; ++l)
    laneSystems_.push_back(alone(*models[std::min(static_cast<std::size_t>(l), models.size() - 1)]));
}

const Model* LaneStack::laneSystem(int lane) const {
  return lane >= 0 && static_cast<std::size_t>(lane) < laneSystems_.size()
             ? laneSystems_[static_cast<std::size_t>(lane)].get()
             : nullptr;
}

} // namespace rv
