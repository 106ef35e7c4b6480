// The |Map(x) - x| surface and the regions of allowed motion on grids: values against direct evaluation and
// analytic regions, thread counts giving identical grids, and resumption after a stop.
#include "dynamics/tools/MapGrid.h"
#include "dynamics/core/Errors.h"
#include "tests/dynamics/TestSupport.h"

#include <atomic>
#include <cmath>
#include <gtest/gtest.h>

namespace rv {
namespace {

GridSettings grid(double x0, double x1, double dx, double y0, double y1, double dy, int threads) {
  GridSettings g;
  g.axes[0] = {x0, x1, dx};
  g.axes[1] = {y0, y1, dy};
  g.threads = threads;
  return g;
}

TEST(MapGrid, SurfaceVanishesAtTheHenonFixedPointAndMatchesDirectEvaluation) {
  const auto m = test::makeModel("henon_map", {});
  const ReturnMap map(*m, test::everhartFactory(), {});
  const double xf = (-0.7 + std::sqrt(0.49 + 5.6)) / 2.8;
  MapGrid one(map, MapGrid::Kind::Surface,
              grid(xf - 0.5, xf + 0.5, 0.01, 0.3 * xf - 0.5, 0.3 * xf + 0.5, 0.01, 1));
  MapGrid two(map, MapGrid::Kind::Surface,
              grid(xf - 0.5, xf + 0.5, 0.01, 0.3 * xf - 0.5, 0.3 * xf + 0.5, 0.01, 2));
  ASSERT_TRUE(one.run());
  ASSERT_TRUE(two.run());
  const auto& a = one.result();
  EXPECT_EQ(a.size[0], 101);
  EXPECT_EQ(a.size[1], 101);
  EXPECT_EQ(a.values, two.result().values);
  // the centre node is the fixed point; the minimum sits there
  const auto minimum = std::min_element(a.values.begin(), a.values.end()) - a.values.begin();
  EXPECT_EQ(minimum, 50 * 101 + 50);
  EXPECT_LT(a.values[minimum], 1e-12);
  for (int j = 0; j < 101; j += 13)
    for (int i = 0; i < 101; i += 17) {
      const Eigen::Vector2d x = one.node(i, j, 0);
      const double direct = std::hypot(1 - 1.4 * x[0] * x[0] + x[1] - x[0], 0.3 * x[0] - x[1]);
      EXPECT_NEAR(a.values[j * 101 + i], direct, 1e-14);
    }
}

TEST(MapGrid, HenonHeilesAllowedRegionIsTheEnergyDisc) {
  const double E = 0.125;
  const auto m = test::makeModel("henon_heiles", {{"energy", E}});
  const ReturnMap map(*m, test::everhartFactory(), {});
  MapGrid ram(map, MapGrid::Kind::AllowedRegion, grid(-0.6, 0.8, 0.02, -0.6, 0.6, 0.02, 2));
  ASSERT_TRUE(ram.run());
  EXPECT_EQ(ram.levelName(), "px");
  const auto& r = ram.result();
  int allowed = 0;
  for (int j = 0; j < r.size[1]; ++j)
    for (int i = 0; i < r.size[0]; ++i) {
      const Eigen::Vector2d x = ram.node(i, j, 0);
      const double y = x[0], py = x[1];
      const double rest = E - 0.5 * py * py - (0.5 * y * y - y * y * y / 3); // px^2 / 2 at x = 0
      const std::size_t at = static_cast<std::size_t>(j) * r.size[0] + i;
      if (std::abs(rest) < 1e-9) continue; // on the boundary
      EXPECT_EQ(r.values[at], rest > 0 ? 1.0 : 0.0) << "y = " << y << ", py = " << py;
      if (rest > 0) {
        ++allowed;
        EXPECT_NEAR(r.level[at], std::sqrt(2 * rest), 1e-12);
      }
    }
  EXPECT_GT(allowed, 500);
}

TEST(MapGrid, StopsAndResumesToTheSameGrid) {
  const auto m = test::makeModel("henon_heiles", {{"energy", 0.125}});
  const ReturnMap map(*m, test::everhartFactory(), {});
  const GridSettings g = grid(-0.3, 0.3, 0.05, -0.3, 0.3, 0.05, 2);
  MapGrid whole(map, MapGrid::Kind::Surface, g);
  ASSERT_TRUE(whole.run());
  MapGrid parts(map, MapGrid::Kind::Surface, g);
  std::atomic<int> rows{0};
  ToolControl stopEarly{.stopRequested = [&] { return rows.load() >= 3; },
                        .progress = [&](double) { ++rows; }};
  EXPECT_FALSE(parts.run(stopEarly));
  EXPECT_LT(parts.result().done, whole.result().done);
  ASSERT_TRUE(parts.run());
  const auto& a = whole.result().values;
  const auto& b = parts.result().values;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(std::isnan(a[i]) && std::isnan(b[i]))) {
      EXPECT_EQ(a[i], b[i]) << i;
    }
}

} // namespace
} // namespace rv
