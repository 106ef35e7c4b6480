// AdamsKernels.h -- the two passes of an Adams PECE step over the backward differences nabla^j f (dim x k,
// column-major): the predictor's weighted sum and the shift of the differences to a new derivative. They are
// most of a step's own arithmetic, so each component block keeps its sums in registers across the k
// differences, and where the CPU has AVX2 (checked at run time: the build targets baseline x86-64) the blocks
// run four lanes wide. Both paths do the same operations in the same order (no fused multiply-add), so their
// results are bit-identical: a run does not depend on the machine it ran on.
#pragma once
#include <Eigen/Core>

namespace rv::adams {

/// Whether this CPU runs the AVX2 paths.
bool avx2Available();

/// P: increment = h sum_{j<k} gamma_j D_j, sum = sum_{j<k} D_j, predicted = x + increment (n components).
void predict(const double* D, Eigen::Index n, int k, const double* gamma, double h, const double* x,
             double* increment, double* sum, double* predicted, bool avx2);

/// The differences moved to the new derivative f: D_0 = f, D_j = D_(j-1) (new) - D_(j-1) (old).
void shift(double* D, Eigen::Index n, int k, const double* f, bool avx2);

} // namespace rv::adams
