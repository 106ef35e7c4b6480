// LaneStack.h -- W orbits' systems stacked component-major into one Model (component c of lane l at
// c * W + l): what an integrator steps when a batched tool (MegnoLanes.h, LyapunovLanes.h) integrates W
// orbits at once on SIMD lanes, with Integrator::stepLanesAlone(W) so that each lane steps as alone.
#pragma once
#include "dynamics/core/LaneField.h"
#include "dynamics/core/Model.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rv {

namespace detail {
struct LaneStackInfo {
  ModelInfo stackInfo;
};
} // namespace detail

/// The base of a stacked system: its ModelInfo (W lanes of `perLane` components each, `what` naming it) and
/// the lanes' kernel; the derived class writes rhs().
class LaneStack : private detail::LaneStackInfo, public Model {
public:
  LaneStack(const Model& base, const LaneKernel& kernel, int perLane, const std::string& what);
  /// Not available: the stacked systems are stepped by explicit or fixed-point methods only.
  void jacobian(const double*, double*) const override;
  /// The lane's own system where the derived class gave them (ownLaneSystems), else null.
  const Model* laneSystem(int lane) const override;

protected:
  /// Gives each lane its orbit as a system of its own, `alone(model)` of the lane's model (the last of
  /// `models` repeated into lanes left over): its field must be that lane's, bit for bit.
  void ownLaneSystems(const std::vector<const Model*>& models,
                      const std::function<std::unique_ptr<Model>(const Model&)>& alone);

  const LaneKernel& kernel_;
  const int lanes_; ///< W

private:
  std::vector<std::unique_ptr<Model>> laneSystems_;
};

} // namespace rv
