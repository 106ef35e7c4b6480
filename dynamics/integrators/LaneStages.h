// LaneStages.h -- an explicit Runge-Kutta stage on orbits stacked on lanes, each lane with a step of its own
// (an adaptive method whose lanes step alone, Integrator::takeLaneSteps): out = x + a_l (c_0 k_0 + c_1 k_1 +
// ... + c_(m-1) k_(m-1)) for every component of lane l, the sum in the terms' order. A method's vector
// expression such as (h / 2) * (k1 - 3 * k3 + 4 * k4) is that stage with a = h / 2 and c = (1, -3, 4): a
// product by 1 and a negation are exact, so each lane gets the scalar expression's bits. Lanes in groups of
// 8 or 4 run in AVX-512 or AVX2 registers where the CPU has them (checked at run time, the build stays
// baseline x86-64, as dynamics/integrators/EverhartKernels.h); every path does each element's operations in
// one order with no fused multiply-add.
#pragma once
#include "dynamics/integrators/EverhartKernels.h"

#include <Eigen/Core>

namespace rv::lanes {

/// Which code runs (the widest this CPU has, or one of them for tests): Everhart's passes' choice.
using everhart::Path;

/// The orbits' components as `rows` rows of `width` lanes (component c of lane l at c width + l): for each,
/// out = (x +) a_l * sum_j c_j k_j, with x omitted where it is null. `a` holds a factor per lane, `k` the
/// `terms` vectors the coefficients `c` weight. out may be x or one of k only where every element reads its
/// own position alone (it does).
void stage(const double* x, const double* a, const double* c, const double* const* k, int terms,
           Eigen::Index rows, int width, double* out, Path path = Path::widest);

} // namespace rv::lanes
