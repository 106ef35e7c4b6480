// The scan-and-bisect root finder behind the map points' completion (chaplygin_ball, ball_on_ellipsoid).
#include "dynamics/kinematics/RootFinding.h"

#include <cmath>
#include <gtest/gtest.h>

namespace rv {
namespace {

TEST(RootFinding, FindsEverySignChangeToTheAccuracy) {
  long calls = 0;
  const auto f = [&](double x) { return ++calls, std::sin(x); };
  const auto roots = findRoots(f, 0.5, 10.0, 1e-2, 1e-14);
  ASSERT_EQ(roots.size(), 3u);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(roots[static_cast<std::size_t>(i)], (i + 1) * M_PI, 1e-13);
  EXPECT_LT(calls, 1200); // 950 scan points and ~50 bisections per root
}

// a tiny step over a huge range (a fuzzed scene: a gyrostat of 4e5 widened chaplygin_ball's range of G to
// ~4e5 at the default step 1e-3, 4e8 evaluations) is coarsened to kMaxScanIntervals: it ends, and still finds
// a lone root
TEST(RootFinding, ATinyStepOverAHugeRangeIsCoarsenedAndStillFindsTheRoot) {
  long calls = 0;
  const auto f = [&](double x) { return ++calls, x - 123456.789; };
  const auto roots = findRoots(f, 0.0, 4.4e5, 1e-3, 1e-15);
  ASSERT_EQ(roots.size(), 1u);
  EXPECT_NEAR(roots[0], 123456.789, 1e-9);
  EXPECT_LE(calls, static_cast<long>(kMaxScanIntervals) + 300);
}

} // namespace
} // namespace rv
