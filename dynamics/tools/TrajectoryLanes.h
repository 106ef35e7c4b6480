// TrajectoryLanes.h -- the plain orbits of up to 8 points of a flow integrated at once, one per SIMD lane
// (dynamics/core/Lanes.h): what a sweep of a trajectory quantity (an observable's value or time average, the
// rattleback's reversal; scenes/builtin/SweepTool.cpp) reads step by step, and where each crosses a Poincare
// section (an orbit diagram), located lane by lane. The orbits' fields are stacked component-major into one
// system whose right-hand side is the models' lane kernel, stepped by a method that steps each lane as alone
// with one time for all (Integrator::stepLanesAlone: rk4, everhart at a fixed step, adams): each lane's steps
// are those of its orbit integrated alone, bit for bit, so what a sweep reads of a point cannot depend on the
// points beside it.
#pragma once
#include "dynamics/integrators/Integrator.h"
#include "dynamics/tools/PoincareMap.h"
#include "dynamics/tools/ToolControl.h"

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <vector>

namespace rv {

/// Whether integrateOnLanes can take orbits of these models (one per orbit) together: flows of one class
/// whose field runs on lanes with these parameters (laneKernelFor), and a method that steps each lane as
/// alone with one time for all.
bool trajectoriesRunOnLanes(const std::vector<const Model*>& models, const IntegratorFactory& makeIntegrator);

/// A step of one orbit: its start (t0, x0) and end (t1, x1).
using LaneStep =
    std::function<void(int lane, double t0, const Eigen::VectorXd& x0, double t1, const Eigen::VectorXd& x1)>;

/// Integrates each orbit of `models` from its state in `x0s` (1 to kMaxLanes, one model each) from t = 0 to
/// `time`, handing every step of every orbit to onStep as integrating that orbit alone would (the step's
/// start and end; the last step cut at `time` by the dense output). False when stopped by request. Throws
/// ComputationError when a step of the batch fails (an orbit blows up): the caller then integrates each orbit
/// alone, where it fails, or not, as it would.
bool integrateOnLanes(const std::vector<const Model*>& models, const IntegratorFactory& makeIntegrator,
                      const std::vector<Eigen::VectorXd>& x0s, double time, const ToolControl& control,
                      const LaneStep& onStep);

/// The points where each orbit of `models` from its state in `x0s` crosses the section of `settings`, as a
/// PoincareMap of that orbit alone finds them (SectionCrossings on each lane, located on the stack's dense
/// output read at that lane), bit for bit: settings.maxPoints of them (> 0), or fewer where the maps end at
/// settings.maxTime; integrating backward where the settings say. Nothing when stopped by request. Throws
/// ComputationError when a step of the batch fails.
std::optional<std::vector<std::vector<MapPoint>>> mapPointsOnLanes(const std::vector<const Model*>& models,
                                                                   const IntegratorFactory& makeIntegrator,
                                                                   const std::vector<Eigen::VectorXd>& x0s,
                                                                   const SectionSettings& settings,
                                                                   const ToolControl& control = {});

} // namespace rv
