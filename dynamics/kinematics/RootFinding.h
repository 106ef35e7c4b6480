// RootFinding.h -- roots of a scalar function on an interval: bracketed by a scan with a fixed step (the
// manual's "step of root finding"), each refined by bisection to the requested accuracy.
#pragma once
#include <functional>
#include <vector>

namespace rv {

/// The most intervals a scan takes: a smaller step over a wider range is coarsened to (b - a) / this.
inline constexpr double kMaxScanIntervals = 1e5;

/// All sign changes of f on [a, b] found by scanning with `step` (at most kMaxScanIntervals intervals),
/// refined to |interval| <= accuracy (relative to max(1, |x|)). Sorted ascending. A root touched without a
/// sign change is missed, and so is a pair of roots closer than the step.
std::vector<double> findRoots(const std::function<double(double)>& f, double a, double b, double step,
                              double accuracy);

} // namespace rv
