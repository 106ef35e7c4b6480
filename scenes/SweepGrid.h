// SweepGrid.h -- a sweep's grid indices, shared by its refinement (SweepRefine.cpp) and the CSV read back
// (SweepOutput.cpp).
#pragma once
#include "scenes/Sweep.h"

#include <vector>

namespace rv {

/// The grid indices of point `index`, the first axis fastest (an axis of count 1 has index 0).
std::vector<long> sweepGridIndices(const SweepSpec& spec, long index);
/// The point at grid indices `k`.
long sweepGridIndex(const SweepSpec& spec, const std::vector<long>& k);

} // namespace rv
