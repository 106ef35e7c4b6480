// TimeSampler.h -- the state at evenly spaced (or given) times, taken from the integrator's dense output
// (never by adjusting the step), so that CSV rows and video frames land exactly on the requested times.
#pragma once
#include "dynamics/integrators/Integrator.h"

#include <functional>
#include <vector>

namespace rv {

/// Calls visit(t_k, x(t_k)) for t_k = t0 + direction * k * every, k = 0 .. count - 1, where t0 is the
/// integrator's current time. Stops early (returns false) when visit returns false.
bool sampleUniform(Integrator& integrator, double every, long count,
                   const std::function<bool(double, const Eigen::VectorXd&)>& visit);

/// Calls visit(t, x(t)) for each of `times`, which run in the integrator's direction from the start of its
/// last step (InputError otherwise). Stops early (returns false) when visit returns false.
bool sampleAt(Integrator& integrator, const std::vector<double>& times,
              const std::function<bool(double, const Eigen::VectorXd&)>& visit);

} // namespace rv
