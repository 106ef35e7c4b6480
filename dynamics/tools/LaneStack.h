// LaneStack.h -- W orbits' systems stacked component-major into one Model (component c of lane l at
// c * W + l): what an integrator steps when a batched tool (MegnoLanes.h, LyapunovLanes.h) integrates W
// orbits at once on SIMD lanes, with Integrator::stepLanesAlone(W) so that each lane steps as alone.
#pragma once
#include "dynamics/core/LaneField.h"
#include "dynamics/core/Model.h"

#include <string>
#include <utility>
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
  /// The lane's own system where the derived class gave them (setLaneSystems), else null.
  const Model* laneSystem(int lane) const override;

protected:
  /// Each lane's orbit as a system of its own (its field that lane's, bit for bit), one per lane.
  void setLaneSystems(std::vector<const Model*> systems) { laneSystems_ = std::move(systems); }

  const LaneKernel& kernel_;
  const int lanes_; ///< W

private:
  std::vector<const Model*> laneSystems_;
};

} // namespace rv
