// EverhartKernels.h -- the passes of an Everhart step over its node values F (dim x n, column-major): the
// weighted sums of the columns (node sums, the predictor), the step's increment, and the corrector's scan of
// orbits stacked on lanes. They are most of a step's own arithmetic when many orbits are stacked (a sweep's
// lanes, issue 40), so they run 8 components wide where the CPU has AVX-512 and 4 wide with AVX2 (checked at
// run time: the build targets baseline x86-64). Every path does each component's operations in one order
// with no fused multiply-add, so the results are bit-identical whatever the width, the CPU, or the number of
// orbits stacked: an orbit's rounding does not depend on its neighbours.
#pragma once
#include <Eigen/Core>
#include <cstdint>

namespace rv::everhart {

/// Which code the passes run: the widest this CPU has (what the integrator uses), or one of them (tests).
enum class Path { widest, avx512, avx2, baseline };

/// Whether this CPU runs `path`.
bool available(Path path);

/// out_i = ((F_0i c_0 + F_1i c_1) + ... + F_(n-1)i c_(n-1)) + x_i, over d components (x may be null: no x).
/// Column l of F starts at F + l d.
void combine(const double* F, Eigen::Index d, int n, const double* c, const double* x, double* out,
             Path path = Path::widest);

/// out_i = h (F_0i + sum_(1<=j<n) b_j (F_ji - F_0i)), summed in j's order: the step's increment as f(x0) plus
/// the weighted differences (Everhart.cpp says why).
void increment(const double* F, Eigen::Index d, int n, const double* b, double h, double* out,
               Path path = Path::widest);

/// One node's new values f on `width` orbits stacked component-major (component c of orbit l at
/// c width + l): for each open lane (open[l] != 0), change_l and scale_l grow to the largest |f - Fj| and |f|
/// over its first `controlled` components, and Fj takes f; a closed lane's values stay as they are.
void scanLanes(const double* f, double* Fj, Eigen::Index components, Eigen::Index controlled, int width,
               const std::int64_t* open, double* change, double* scale, Path path = Path::widest);

} // namespace rv::everhart
