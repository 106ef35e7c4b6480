// MEGNO and FLI against known answers (Cincotta & Simo 2000): <Y> -> 2 on quasi-periodic orbits (a
// Henon-Heiles torus at E = 1/12, the standard map's invariant curve at small K, the free shear K = 0 where
// |w| grows exactly linearly), -> 0 at an elliptic fixed point of a map, and <Y> / (t/2) -> the largest
// Lyapunov exponent on chaotic orbits (Lorenz: 0.906, Sprott 2003; the Henon map: 0.419). A stopped, saved
// and restored run goes on bit-identically.
#include "dynamics/tools/Megno.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Rk4.h"
#include "tests/dynamics/TestSupport.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace rv {
namespace {

Eigen::VectorXd point(std::initializer_list<double> v) {
  Eigen::VectorXd x(static_cast<Eigen::Index>(v.size()));
  int i = 0;
  for (double c : v)
    x[i++] = c;
  return x;
}

MegnoResult mapMegno(const Model& m, const Eigen::VectorXd& x0, double iterations) {
  MegnoSettings s;
  s.maxTime = iterations;
  s.outputPeriod = iterations;
  return megno(m, {}, x0, s);
}

TEST(Megno, FreeShearGrowsLinearly) {
  // K = 0: theta' = theta + p, p' = p; the tangent vector from (1, 1/2) is (1 + k/2, 1/2) after k iterations,
  // so the definition's sums can be written down without the map: <Y>(N) = 2 - O(ln N / N)
  const auto m = test::makeModel("standard_map", {{"K", 0.0}});
  const long n = 100000;
  const auto r = mapMegno(*m, point({0.3, 0.7}), static_cast<double>(n));
  const auto delta = [](long k) { return std::hypot(1 + 0.5 * static_cast<double>(k), 0.5); };
  double a = 0, b = 0;
  for (long k = 1; k <= n; ++k) {
    a += static_cast<double>(k) * std::log(delta(k) / delta(k - 1));
    b += 2 * a / static_cast<double>(k);
  }
  std::printf("  shear: <Y> = %.12f (by the definition %.12f), FLI = %.5f\n", r.last.megno, b / n,
              r.last.fli);
  EXPECT_NEAR(r.last.megno, b / static_cast<double>(n), 1e-9);
  EXPECT_NEAR(r.last.megno, 2.0, 0.01);
  EXPECT_NEAR(r.last.fli, std::log(delta(n) / delta(0)), 1e-9);
}

TEST(Megno, StandardMapInvariantCurveIsTwo) {
  const auto m = test::makeModel("standard_map", {{"K", 0.3}});
  const auto r = mapMegno(*m, point({1.0, 2.5}), 2e5);
  std::printf("  standard map K = 0.3: <Y> = %.6f\n", r.last.megno);
  EXPECT_NEAR(r.last.megno, 2.0, test::tol(0.05));
}

TEST(Megno, EllipticFixedPointIsZero) {
  // (pi, 0) is elliptic for 0 < K < 4 (trace 2 - K): the tangent vector turns and stays bounded
  const auto m = test::makeModel("standard_map", {{"K", 1.0}});
  const auto r = mapMegno(*m, point({std::numbers::pi, 0.0}), 1e5);
  std::printf("  elliptic point: <Y> = %.3g\n", r.last.megno);
  EXPECT_NEAR(r.last.megno, 0.0, test::tol(0.01));
}

TEST(Megno, HenonMapRateIsTheLyapunovExponent) {
  const auto m = test::makeModel("henon_map", {{"a", 1.4}, {"b", 0.3}});
  const auto r = mapMegno(*m, point({0.1, 0.1}), 1e5);
  std::printf("  henon map: <Y> = %.1f, rate %.5f, FLI / N %.5f\n", r.last.megno, r.last.megnoRate,
              r.last.fli / 1e5);
  EXPECT_NEAR(r.last.megnoRate, 0.419, test::tol(0.01));
  EXPECT_NEAR(r.last.fli / 1e5, 0.419, test::tol(0.01)); // ln |w| / N -> lambda as well
}

TEST(Megno, HenonHeilesTorusIsTwo) {
  const auto m = test::makeModel("henon_heiles", {{"energy", 1.0 / 12}});
  const Eigen::VectorXd x0 = m->stateFromMap({0.1, 0.1}, {}, "test");
  MegnoSettings s;
  s.maxTime = 5000;
  s.outputPeriod = 100;
  std::vector<double> trace;
  const auto r = megno(
      *m, [] { return std::make_unique<Everhart>(0.05, 15, 2); }, x0, s,
      [&](const MegnoEstimate& e) { trace.push_back(e.megno); });
  std::printf("  henon-heiles E = 1/12: <Y> = %.5f, Y = %.4f\n", r.last.megno, r.last.y);
  EXPECT_NEAR(r.last.megno, 2.0, test::tol(0.1));
  EXPECT_EQ(trace.size(), 50u);
  EXPECT_EQ(trace.back(), r.last.megno);
}

TEST(Megno, LorenzRateIsTheLargestExponent) {
  const auto m = test::makeModel("lorenz", {});
  MegnoSettings s;
  s.maxTime = 4000;
  s.interval = 1;
  const auto r = megno(
      *m, [] { return std::make_unique<Rk4>(0.005); }, point({1, 1, 20}), s);
  std::printf("  lorenz: <Y> = %.1f, rate %.5f, FLI / t %.5f\n", r.last.megno, r.last.megnoRate,
              r.last.fli / r.last.time);
  EXPECT_NEAR(r.last.megnoRate, 0.906, test::tol(0.03));
  EXPECT_NEAR(r.last.fli / r.last.time, 0.906, test::tol(0.03));
}

TEST(Megno, StoppedSavedAndRestoredGoesOnBitIdentically) {
  const auto m = test::makeModel("lorenz", {});
  MegnoSettings s;
  s.maxTime = 200;
  s.interval = 2;
  const IntegratorFactory rk4 = [] { return std::make_unique<Rk4>(0.01); };
  const auto whole = megno(*m, rk4, point({1, 1, 20}), s);
  MegnoRun first(*m, rk4, point({1, 1, 20}), s);
  int polls = 0;
  ToolControl stopSoon;
  stopSoon.stopRequested = [&] { return ++polls > 5000; };
  EXPECT_FALSE(first.run({}, stopSoon));
  EXPECT_TRUE(first.result().stopped);
  Snapshot saved;
  first.save(saved);
  MegnoRun second(*m, rk4, point({1, 1, 20}), s);
  second.restore(saved);
  EXPECT_TRUE(second.run());
  EXPECT_EQ(second.result().last.megno, whole.last.megno);
  EXPECT_EQ(second.result().last.fli, whole.last.fli);
  EXPECT_EQ(second.result().last.time, 200);
}

TEST(Megno, BadSettingsAreInputErrors) {
  const auto m = test::makeModel("lorenz", {});
  MegnoSettings s;
  s.interval = 0;
  EXPECT_THROW(MegnoRun(*m, {}, point({1, 1, 1}), s), InputError);
  s = {};
  s.maxTime = -1;
  EXPECT_THROW(MegnoRun(*m, {}, point({1, 1, 1}), s), InputError);
}

} // namespace
} // namespace rv
