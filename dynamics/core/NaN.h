// NaN.h -- the value of a quantity that has none: a sweep's cell whose orbit failed or was stopped, a
// coordinate a map's point lacks (written "nan" in CSV files).
#pragma once
#include <limits>

namespace rv {

/// Quiet NaN: "no value".
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

} // namespace rv
