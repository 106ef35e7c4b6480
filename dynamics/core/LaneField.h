// LaneField.h -- what a model offers to integrate kLanes trajectories at once (dynamics/core/Lanes.h): its
// right-hand side and the derivative along one tangent vector at kLanes states in one evaluation. Models with
// a templated field (ModelWithField) that declare `static constexpr bool kLaneField = true` (a field with no
// branch on a value) have it; the batched tools (dynamics/tools/MegnoLanes.h) find it by dynamic_cast.
#pragma once
#include "dynamics/core/Lanes.h"

namespace rv {

class LaneField {
public:
  virtual ~LaneField() = default;
  /// f(x) and J(x) w at kLanes states at once, component-major: x[c * kLanes + l] for the n state components
  /// and then the m core components of w (m = coreDimension), out likewise (f, then J w). False, writing
  /// nothing, where the model has no lane kernel.
  virtual bool laneTangentRhs(const double* x, double* out) const = 0;
};

} // namespace rv
