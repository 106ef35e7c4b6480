// ImageCompare.h -- picture checks for render tests (F3D-style baselines with a tolerance).
#pragma once
#include "render/Snapshot.h"

#include <string>

namespace rv::test {

/// A real picture: not one flat colour (standard deviation > 5 and more than 50 distinct colours).
bool isVaried(const Image& image);

struct ImageDifference {
  double meanAbs = 0;      ///< mean |a - b| over all channels, in 0..255
  double fractionOver = 0; ///< fraction of pixels where some channel differs by more than 48
  Image diff;              ///< |a - b| amplified, for inspection
};

/// Compares two pictures of the same size (throws std::runtime_error when the sizes differ).
ImageDifference compareImages(const Image& a, const Image& b);

/// Compares `actual` with assets/baselines/<name>.png. With ROLLVIZ_UPDATE_BASELINES=1 it writes the
/// baseline instead. On failure writes <name>.actual.png and <name>.diff.png into ROLLVIZ_TEST_OUTPUT.
/// Returns an empty string when they agree, else the reason.
std::string matchesBaseline(const Image& actual, const std::string& name, double maxMeanAbs = 2.0,
                            double maxFractionOver = 0.01);

} // namespace rv::test
