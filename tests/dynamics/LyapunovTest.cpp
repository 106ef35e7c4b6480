// Lyapunov exponents against known answers: Lorenz (0.906, 0, -14.572, sum -(sigma + 1 + beta) = -41/3), the
// Henon map (sum ln b, largest 0.419), and the integrable Chaplygin ball (all exponents tend to zero).
#include "dynamics/tools/Lyapunov.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/integrators/Verner9.h"
#include "tests/dynamics/TestSupport.h"

#include <cmath>
#include <gtest/gtest.h>

namespace rv {
namespace {

Eigen::VectorXd lorenzStart() {
  Eigen::VectorXd x(3);
  x << 1, 1, 20;
  return x;
}

// the published values (Sprott, Chaos and Time-Series Analysis, 2003) and the exact sum -(sigma + 1 + beta)
void expectLorenzExponents(const char* mode, const LyapunovResult& r) {
  ASSERT_EQ(r.last.exponents.size(), 3u);
  std::printf("  lorenz %s: %.5f %.5f %.5f sum %.8f\n", mode, r.last.exponents[0], r.last.exponents[1],
              r.last.exponents[2], r.last.sum());
  EXPECT_NEAR(r.last.exponents[0], 0.906, test::tol(0.01));
  EXPECT_NEAR(r.last.exponents[1], 0.0, test::tol(0.005));
  EXPECT_NEAR(r.last.exponents[2], -14.572, test::tol(0.03));
  EXPECT_NEAR(r.last.sum(), -41.0 / 3.0, test::tol(1e-3));
}

TEST(Lyapunov, LorenzTangentMode) {
  const auto m = test::makeModel("lorenz", {});
  LyapunovSettings s;
  s.interval = 0.5;
  s.maxTime = 10000;
  const auto r = lyapunovExponents(
      *m, [] { return std::make_unique<Rk4>(0.005); }, lorenzStart(), s);
  expectLorenzExponents("tangent", r);
}

TEST(Lyapunov, LorenzPerturbedMode) {
  const auto m = test::makeModel("lorenz", {});
  LyapunovSettings s;
  s.mode = LyapunovSettings::Mode::Perturbed;
  s.interval = 0.1;
  s.perturbation = 1e-7;
  s.maxPerturbation = 1e-4;
  s.maxTime = 10000;
  const auto r = lyapunovExponents(
      *m, [] { return std::make_unique<Rk4>(0.005); }, lorenzStart(), s);
  expectLorenzExponents("perturbed", r);
}

TEST(Lyapunov, HenonMap) {
  const auto m = test::makeModel("henon_map", {{"a", 1.4}, {"b", 0.3}});
  LyapunovSettings s;
  s.interval = 1;
  s.maxTime = 1e6;
  s.outputPeriod = 1e5;
  Eigen::VectorXd x0(2);
  x0 << 0.1, 0.1;
  const auto r = lyapunovExponents(*m, {}, x0, s);
  std::printf("  henon: %.6f %.6f sum %.10f (ln 0.3 = %.10f)\n", r.last.exponents[0], r.last.exponents[1],
              r.last.sum(), std::log(0.3));
  EXPECT_NEAR(r.last.sum(), std::log(0.3), 1e-6);
  EXPECT_NEAR(r.last.exponents[0], 0.419, test::tol(0.003));
}

TEST(Lyapunov, TheIntegrableChaplyginBallHasOnlyVanishingExponents) {
  const auto m = test::makeModel("chaplygin_ball", {{"K1", 0.2}, {"K2", 0.1}, {"K3", 0.3}});
  const Eigen::VectorXd x0 = m->stateFromMap({0.5, 0.2}, {}, "t");
  LyapunovSettings s;
  s.interval = 1;
  s.maxTime = 10000;
  s.outputPeriod = 1000;
  s.renormalizeIntegrals = true;
  s.count = 2; // six coordinates, four integrals: two exponents left
  const auto r = lyapunovExponents(
      *m, [] { return std::make_unique<Everhart>(0.4, 15, 12); }, x0, s);
  std::printf("  chaplygin: %.2e %.2e\n", r.last.exponents[0], r.last.exponents[1]);
  for (double e : r.last.exponents)
    EXPECT_LT(std::abs(e), 1e-2);
}

TEST(Lyapunov, StopsWhenAskedAndConvergesByItsCriterion) {
  const auto m = test::makeModel("lorenz", {});
  LyapunovSettings s;
  s.maxTime = 1e9;
  int polls = 0;
  ToolControl control;
  control.stopRequested = [&] { return ++polls > 2000; };
  const auto r = lyapunovExponents(
      *m, [] { return std::make_unique<Rk4>(0.01); }, lorenzStart(), s, {}, control);
  EXPECT_TRUE(r.stopped);
  s.successes = 5;
  s.accuracy = 1e-2;
  s.estimateEvery = 50;
  const auto c = lyapunovExponents(
      *m, [] { return std::make_unique<Rk4>(0.01); }, lorenzStart(), s);
  EXPECT_TRUE(c.converged);
  EXPECT_LT(c.last.time, 1e9);
}

// Issue 39: with an adaptive integrator the steps follow the orbit alone (Integrator::controlBy), so the
// orbit -- and with it the first exponent, whose vector Gram-Schmidt never mixes with the others -- is the
// same bit for bit however many exponents are asked for. Before, Everhart's corrector and the step control
// saw the tangent vectors: lambda1 of one chaotic Henon-Heiles orbit at T = 2e4 was 0.0553 alone and 0.0610
// with all four.
TEST(Lyapunov, TheOrbitDoesNotDependOnHowManyExponentsRideAlong) {
  const auto m = test::makeModel("henon_heiles", {{"energy", 0.125}});
  const Eigen::VectorXd x0 = m->stateFromMap({-0.2, 0.0}, MapPointSpec{}, "test"); // in the chaotic sea
  const std::vector<std::pair<const char*, IntegratorFactory>> methods = {
      {"everhart adaptive", [] { return std::make_unique<Everhart>(0.1, 15, 12, 1e-10); }},
      {"verner9", [] { return std::make_unique<Verner9>(1e-11, 0.1); }},
  };
  for (const auto& [name, make] : methods) {
    LyapunovSettings s;
    s.interval = 1;
    s.maxTime = 500;
    s.count = 1;
    const auto one = lyapunovExponents(*m, make, x0, s);
    s.count = 4;
    const auto all = lyapunovExponents(*m, make, x0, s);
    ASSERT_EQ(all.last.exponents.size(), 4u) << name;
    EXPECT_EQ(one.last.exponents[0], all.last.exponents[0]) << name;
    EXPECT_GT(one.last.exponents[0], 0.01) << name; // a chaotic orbit: the test means something
  }
}

} // namespace
} // namespace rv
