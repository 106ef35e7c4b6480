// LyapunovLanes.h -- the Lyapunov exponents (Lyapunov.h, tangent mode) of up to 8 orbits at once, one per
// SIMD lane (dynamics/core/Lanes.h): the orbits and their tangent vectors advanced by the models' fused lane
// RK4 (LaneKernel::tangentRk4), or by a method that steps lanes as alone (Integrator::stepLanesAlone:
// everhart at a fixed step) on the stacked tangent systems (LaneKernel::tangentRhs), each orbit's run
// orthonormalising, estimating and stopping as alone. What a sweep of Lyapunov exponents over initial points
// or parameters computes (issue 40).
//
// The same numbers: the lane steps are the scalar steps lane by lane, bit for bit, and each lane's run is a
// LyapunovRun closing its own intervals -- so each orbit's exponents equal the scalar run's bit for bit. An
// interval the fused path does not make (not a whole number of steps) is taken by each run alone, as the
// scalar run takes it; an orbit that fails (a blow-up) is taken alone from its interval's start, and fails as
// it fails alone; a run that converges early stops recording while the others go on.
#pragma once
#include "dynamics/tools/Lyapunov.h"

#include <exception>
#include <optional>
#include <vector>

namespace rv {

struct LyapunovLaneResult {
  LyapunovResult result;      ///< the run's result (empty where it failed)
  std::exception_ptr failure; ///< what the run threw for this orbit
};

/// Whether lyapunovOnLanes runs these orbits together: the tangent mode, on models whose field runs on lanes
/// together (laneKernelFor, LaneField.h), with rk4 (fused) or a method that steps lanes as alone, and an
/// exponent count that has a fixed-size path (up to 6).
bool lyapunovRunsOnLanes(const std::vector<const Model*>& models, const IntegratorFactory& makeIntegrator,
                         const LyapunovSettings& settings);

/// The exponents from each of `x0s` (1 to kMaxLanes states; models: one per state, of one class, parameters
/// possibly differing). Nothing where they cannot run on lanes (lyapunovRunsOnLanes); an empty list when
/// stopped by request. InputError for bad settings (as LyapunovRun).
std::optional<std::vector<LyapunovLaneResult>> lyapunovOnLanes(const std::vector<const Model*>& models,
                                                               const IntegratorFactory& makeIntegrator,
                                                               const std::vector<Eigen::VectorXd>& x0s,
                                                               const LyapunovSettings& settings,
                                                               const ToolControl& control = {});

} // namespace rv
