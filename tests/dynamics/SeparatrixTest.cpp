// Separatrices of the standard map's saddle at the origin: they leave along the analytic eigenvectors and are
// invariant (the image of every point lies on the same branch).
#include "dynamics/tools/Separatrix.h"
#include "dynamics/core/Errors.h"
#include "dynamics/integrators/Everhart.h"
#include "tests/dynamics/TestSupport.h"

#include <cmath>
#include <gtest/gtest.h>

namespace rv {
namespace {

IntegratorFactory noIntegrator() {
  return [] { return std::make_unique<Everhart>(0.05, 15, 12); };
}

// distance from p to the polyline through `curve` (differences taken on the torus)
double distanceToCurve(const ReturnMap& map, const std::vector<Eigen::VectorXd>& curve,
                       const Eigen::VectorXd& p) {
  double best = 1e300;
  for (std::size_t i = 0; i + 1 < curve.size(); ++i) {
    const Eigen::VectorXd a = map.difference(p, curve[i]);
    const Eigen::VectorXd seg = map.difference(curve[i + 1], curve[i]);
    const double t = std::clamp(a.dot(seg) / seg.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a - t * seg).norm());
  }
  return best;
}

TEST(Separatrix, StandardMapSaddleBranchesAreInvariantAndLeaveAlongEigenvectors) {
  const double K = 1.5;
  const auto m = test::makeModel("standard_map", {{"K", K}});
  SectionSettings sec;
  const ReturnMap map(*m, noIntegrator(), sec);
  const auto fp = findFixedPoint(map, Eigen::Vector2d(0.01, 0.01), {});
  ASSERT_EQ(fp.type, FixedPointType::Hyperbolic);
  // J = [[1 + K, 1], [K, 1]]: eigenvalues (2 + K +- sqrt((2 + K)^2 - 4)) / 2, eigenvectors (1, lambda - 1 -
  // K)
  const double disc = std::sqrt((2 + K) * (2 + K) - 4);
  const double lu = (2 + K + disc) / 2, ls = (2 + K - disc) / 2;
  SeparatrixSettings s;
  s.maxDistance = 0.005;
  s.maxAngle = 0.02;
  s.maxIterations = 8;
  s.maxPoints = 100000;
  for (int branch = 1; branch <= 4; ++branch) {
    s.branch = branch;
    const auto r = growSeparatrix(map, fp, s);
    const double lambda = branch <= 2 ? lu : ls;
    EXPECT_NEAR(r.multiplier, lambda, 1e-10);
    EXPECT_EQ(r.unstable, branch <= 2);
    Eigen::Vector2d v(1, lambda - 1 - K);
    v.normalize();
    if (branch % 2 == 0) v = -v;
    ASSERT_GT(r.points.size(), 200u) << "branch " << branch << ": " << r.stoppedBecause;
    EXPECT_EQ(r.stoppedBecause, "iterations");
    // the first point leaves along the (signed) eigenvector
    const Eigen::VectorXd first = map.difference(r.points[0], fp.point);
    EXPECT_NEAR(first.normalized().dot(v), 1.0, 1e-8) << "branch " << branch;
    // invariance: the image (unstable) or preimage (stable) of each point lies on the curve
    const ReturnMap step = r.unstable ? map : map.inverse();
    double worst = 0;
    for (std::size_t i = s.segmentPoints; i + 1 < r.points.size(); i += 7) {
      const Eigen::VectorXd image = map.canonical(step(r.points[i]));
      if (r.parameters[i] + 1 > r.parameters.back()) break; // its image lies beyond the grown part
      worst = std::max(worst, distanceToCurve(map, r.points, image));
    }
    EXPECT_LT(worst, 2e-5) << "branch " << branch;
    // neighbouring points within the maximal distance
    for (std::size_t i = 0; i + 1 < r.points.size(); ++i)
      ASSERT_LE(map.difference(r.points[i + 1], r.points[i]).norm(), s.maxDistance * 1.0000001) << i;
  }
}

TEST(Separatrix, RefusesAnEllipticPoint) {
  const auto m = test::makeModel("standard_map", {{"K", 1.5}});
  const ReturnMap map(*m, noIntegrator(), {});
  const auto fp = findFixedPoint(map, Eigen::Vector2d(3.1, 0.0), {});
  try {
    growSeparatrix(map, fp, {});
    FAIL();
  } catch (const ComputationError& e) {
    EXPECT_NE(std::string(e.what()).find("not hyperbolic"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace rv
