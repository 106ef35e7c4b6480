// Separatrix.h -- the invariant manifolds of a hyperbolic fixed point of a 2D map (manual §2.3.6), grown by
// iterating a fundamental segment of the linear approximation and refining it adaptively where neighbouring
// points lie too far apart or the curve turns too sharply (Krauskopf & Osinga, J. Comput. Phys. 146 (1998)
// 404; Parker & Chua, Practical Numerical Algorithms for Chaotic Systems (1989) §6.3). Every point on the
// curve is an image F^k(y(s)) of a point y(s) = x* + delta Lambda^s v of the fundamental segment, so inserted
// points are exact images, not interpolations. Branches 1, 2 follow the first multiplier (+v, -v), 3, 4 the
// second; a stable branch is grown with the inverse map.
#pragma once
#include "dynamics/tools/FixedPoint.h"

namespace rv {

struct SeparatrixSettings {
  int branch = 1; ///< 1, 2: first multiplier (+v, -v); 3, 4: second; v has a positive first component
  double linearRegion = 1e-3;     ///< initial length of the linear segment (halved until accurate)
  double linearAccuracy = 1e-4;   ///< allowed angle (radians) between v and Map(x* + delta v) - x*
  double maxDistance = 0.01;      ///< between neighbouring points
  double maxAngle = 0.1;          ///< turn (radians) between consecutive segments
  double minAngleDistance = 1e-7; ///< segments shorter than this are not refined for their angle
  int segmentPoints = 16;         ///< initial points on the fundamental segment
  int maxIterations = 20;         ///< images of the fundamental segment (levels)
  long maxPoints = 20000;
  double fixedPointAccuracy = 1e-10; ///< the linear region may not shrink below this
};

struct SeparatrixResult {
  std::vector<Eigen::VectorXd> points; ///< along the branch, from the fixed point outward
  std::vector<double> parameters;      ///< of each point: k + s for F^k(x* + delta Lambda^s v), s in [0, 1)
  double multiplier = 0;               ///< the branch's multiplier
  bool unstable = true;                ///< outgoing (|multiplier| > 1) or incoming
  Eigen::VectorXd direction;           ///< the branch's unit eigenvector (with its sign)
  double linearRegion = 0;             ///< the length of the linear segment used
  std::string stoppedBecause;          ///< why growth ended ("points", "iterations", a failure, "stopped")
};

/// Grows one branch of the fixed point `fp` of `map` (which must be hyperbolic; ComputationError otherwise).
/// `onPoints` sees each batch of new points (each level, after refinement).
SeparatrixResult
growSeparatrix(const ReturnMap& map, const FixedPointResult& fp, const SeparatrixSettings& settings,
               const ToolControl& control = {},
               const std::function<void(const std::vector<Eigen::VectorXd>&)>& onPoints = {});

} // namespace rv
