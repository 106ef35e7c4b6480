// MegnoLanes.h -- MEGNO and FLI (Megno.h) of up to 8 orbits of one flow at once, one per SIMD lane
// (dynamics/core/Lanes.h): the lanes' MEGNO systems (x, w, tau, A, B) stacked component-major into one system
// whose right-hand side is the model's lane kernel, integrated by the scene's integrator with one step for
// all, renormalised lane by lane every interval as MegnoRun does. What a sweep of MEGNO over initial points
// computes (issue 40).
//
// The same numbers: with a fixed step that needs no iteration (rk4) each lane is the scalar MegnoRun bit for
// bit; a method whose step or iteration count reads the whole state (everhart's corrector stops when every
// lane has converged, adams starts with an adaptive method, the adaptive ones) gives each lane the steps of
// the batch, the same answer to the method's accuracy -- on a chaotic orbit, the same chaos indicator, not
// its digits. An orbit that fails in the batch (a blow-up, a degenerate tangent vector) sends the batch's
// orbits to the scalar run, each failing (or not) as it would alone.
#pragma once
#include "dynamics/tools/Megno.h"

#include <exception>
#include <vector>

namespace rv {

/// Whether megnoOnLanes can run orbits of these models (one per orbit) together: flows of one class whose
/// field runs on lanes with these parameters (laneKernelFor, LaneField.h), integrated by a method that steps
/// each lane as alone (Integrator::stepLanesAlone: rk4, everhart at a fixed step).
bool megnoRunsOnLanes(const std::vector<const Model*>& models, const IntegratorFactory& makeIntegrator);

struct MegnoLaneResult {
  MegnoEstimate last;         ///< at the end of the time
  std::exception_ptr failure; ///< what the scalar run threw for this orbit (then `last` is empty)
};

/// MEGNO and FLI from each of `x0s` (1 to kMaxLanes states, of the models `models`, one per state: they may
/// differ in their parameters where megnoRunsOnLanes) to settings.maxTime. Returns one result per state, or
/// nothing when stopped by request. InputError for bad settings (as MegnoRun).
std::vector<MegnoLaneResult> megnoOnLanes(const std::vector<const Model*>& models,
                                          const IntegratorFactory& makeIntegrator,
                                          const std::vector<Eigen::VectorXd>& x0s,
                                          const MegnoSettings& settings, const ToolControl& control = {});

} // namespace rv
