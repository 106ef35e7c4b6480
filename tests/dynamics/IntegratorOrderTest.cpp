// Every integrator's empirical order of convergence, measured on one smooth problem (Boost.Odeint's
// test/numeric approach): the error at t = T falls by 2^p when the step is halved.
#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelWithField.h"
#include "dynamics/integrators/Adams.h"
#include "dynamics/integrators/AdamsKernels.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/EverhartKernels.h"
#include "dynamics/integrators/LaneStages.h"
#include "dynamics/integrators/Merson.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/integrators/Verner9.h"
#include "tests/dynamics/TestModels.h"
#include "tests/dynamics/TestSupport.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <tuple>

namespace rv {
namespace {

const ModelInfo& pendulumInfo() {
  static const ModelInfo info{.id = "pendulum", .stateNames = {"q", "p", "s"}, .coreDimension = 3};
  return info;
}
// a non-linear, non-polynomial smooth system: pendulum q'' = -sin q, plus s' = q p (couples the components)
struct Pendulum : ModelWithField<Pendulum, 3> {
  Pendulum() : ModelWithField(pendulumInfo(), ParameterValues(pendulumInfo().parameters)) {}
  template <class S> void field(const Vec<S>& x, Vec<S>& dx) const {
    using std::sin;
    dx[0] = x[1], dx[1] = -sin(x[0]), dx[2] = x[0] * x[1];
  }
};

Eigen::VectorXd solveFixed(Integrator& integ, const Model& m, double h, double T) {
  Eigen::VectorXd x0(3);
  x0 << 1.2, 0.3, 0.0;
  integ.start(m, 0, x0);
  const long n = std::lround(T / h);
  for (long i = 0; i < n; ++i)
    integ.step();
  EXPECT_NEAR(integ.time(), T, 1e-9);
  return integ.state();
}

// steps until time T: the shortest and the longest step taken
std::pair<double, double> stepRangeUntil(Integrator& integ, double T) {
  double shortest = 1e300, longest = 0;
  while (integ.time() < T) {
    integ.step();
    const double h = integ.time() - integ.previousTime();
    shortest = std::min(shortest, h), longest = std::max(longest, h);
  }
  return {shortest, longest};
}

double measuredOrder(const std::function<std::unique_ptr<Integrator>(double)>& make, double h1, double h2,
                     double T) {
  Pendulum m;
  Everhart reference(0.01, 27, 30);
  const Eigen::VectorXd exact = solveFixed(reference, m, 0.01, T);
  auto a = make(h1), b = make(h2);
  const double e1 = (solveFixed(*a, m, h1, T) - exact).norm(), e2 = (solveFixed(*b, m, h2, T) - exact).norm();
  std::printf("  h %.4g -> %.3e, h %.4g -> %.3e\n", h1, e1, h2, e2);
  return std::log(e1 / e2) / std::log(h1 / h2);
}

TEST(IntegratorOrder, EverhartFifteenAgainstAnExactSolution) {
  // 2^15 per halving crosses double rounding quickly: an exact solution and a step ratio of 1.25
  test::CoupledOscillator m;
  const Eigen::VectorXd x0 = test::CoupledOscillator::exact(0);
  const double T = 40;
  const Eigen::VectorXd exact = test::CoupledOscillator::exact(T);
  const auto error = [&](double h) {
    Everhart e(h, 15, 40);
    e.start(m, 0, x0);
    for (long i = 0; i < std::lround(T / h); ++i)
      e.step();
    return (e.state() - exact).norm();
  };
  const double e1 = error(2.0), e2 = error(1.6);
  std::printf("  h 2 -> %.3e, h 1.6 -> %.3e\n", e1, e2);
  EXPECT_NEAR(std::log(e1 / e2) / std::log(1.25), 15.0, 0.3);
}

TEST(IntegratorOrder, Rk4IsFourth) {
  EXPECT_NEAR(measuredOrder([](double h) { return std::make_unique<Rk4>(h); }, 0.1, 0.05, 4.0), 4.0, 0.3);
}

TEST(IntegratorOrder, MersonWithAFixedStepIsFourth) {
  // pin the step (min = max) and let no step be rejected: the order of the formula itself
  const auto make = [](double h) { return std::make_unique<Merson>(h, 1.0, h, h); };
  EXPECT_NEAR(measuredOrder(make, 0.1, 0.05, 4.0), 4.0, 0.3);
}

struct EverhartCase {
  int order;
  double h1, h2, T = 8.0;
};
class EverhartOrder : public ::testing::TestWithParam<EverhartCase> {};

TEST_P(EverhartOrder, IsTwoNMinusOne) {
  const auto c = GetParam();
  const auto make = [&](double h) { return std::make_unique<Everhart>(h, c.order, 40); };
  EXPECT_NEAR(measuredOrder(make, c.h1, c.h2, c.T), c.order, 0.3) << "order " << c.order;
}
INSTANTIATE_TEST_SUITE_P(Orders, EverhartOrder,
                         ::testing::Values(EverhartCase{3, 0.1, 0.05}, EverhartCase{7, 0.4, 0.2},
                                           EverhartCase{11, 0.8, 0.4}));

// Adaptive Everhart (IAS15's step rule): the order shows in how the error falls with the number of steps the
// tolerance buys (an adaptive method's convergence is measured against its work, Hairer-Norsett-Wanner
// §II.4), on the pendulum against small fixed steps of order 27, compared where the last step ends (the dense
// output between steps is of lower order).
TEST(IntegratorOrder, AdaptiveEverhartIsFifteenPerStep) {
  Pendulum m;
  Eigen::VectorXd x0(3);
  x0 << 1.2, 0.3, 0.0;
  const auto run = [&](double tolerance) {
    Everhart e(0.1, 15, 40, tolerance);
    EXPECT_FALSE(e.fixedStep());
    e.start(m, 0, x0);
    long steps = 0;
    while (e.time() < 40)
      e.step(), ++steps;
    Everhart reference(0.01, 27, 30);
    reference.start(m, 0, x0);
    while (reference.time() < e.time())
      reference.step();
    Eigen::VectorXd exact(3);
    reference.interpolate(e.time(), exact);
    return std::pair<double, double>((e.state() - exact).norm(), static_cast<double>(steps));
  };
  // steps come in whole numbers, so the slope is taken over a decade of tolerance (33 -> 48 steps here)
  const auto [e1, n1] = run(0.1);
  const auto [e2, n2] = run(0.01);
  std::printf("  tolerance 0.1: %.0f steps -> %.3e, 0.01: %.0f steps -> %.3e\n", n1, e1, n2, e2);
  ASSERT_GT(n2, n1);
  EXPECT_NEAR(std::log(e1 / e2) / std::log(n2 / n1), 15.0, 3.5);
  EXPECT_LT(run(1e-9).first, 1e-12); // the default tolerance: the accuracy of the reference
}

// A first step far too long is redone shorter, and the steps follow the motion's time scale: a pendulum
// swinging close to its separatrix slows down near the top (long steps) and whips through the bottom.
TEST(Everhart, AdaptiveStepRejectsAFirstStepTooLongAndFollowsTheTimeScale) {
  Pendulum m;
  Eigen::VectorXd x0(3);
  x0 << 3.1, 0.0, 0.0; // released near the top: q'' = -sin q
  Everhart adaptive(50.0, 15, 40, 1e-9);
  adaptive.start(m, 0, x0);
  const auto [shortest, longest] = stepRangeUntil(adaptive, 30);
  EXPECT_GE(adaptive.rejectedSteps(), 1);
  EXPECT_GT(longest / shortest, 3.0);
  Everhart fine(0.005, 27, 40); // the reference: small fixed steps of the highest order
  fine.start(m, 0, x0);
  while (fine.time() < adaptive.time() - 1e-12)
    fine.step();
  Eigen::VectorXd a(3), b(3);
  adaptive.interpolate(30, a), fine.interpolate(30, b);
  EXPECT_LT((a - b).norm(), 1e-10);
}

TEST(Everhart, SpacingsAreGaussRadauAndTheWeightsIntegrateExactly) {
  for (int order : {3, 7, 11, 15, 19, 23, 27}) {
    Everhart e(0.1, order, 10);
    const int n = (order + 1) / 2;
    ASSERT_EQ(static_cast<int>(e.spacings().size()), n);
    EXPECT_EQ(e.spacings()[0], 0.0);
    // Radau quadrature with n nodes (one fixed) integrates polynomials of degree 2n - 2 exactly
    for (int k = 0; k <= 2 * n - 2; ++k) {
      double q = 0;
      for (int j = 0; j < n; ++j)
        q += e.weights()[j] * std::pow(e.spacings()[j], k);
      EXPECT_NEAR(q, 1.0 / (k + 1), 1e-14) << "order " << order << ", degree " << k;
    }
  }
  Everhart three(0.1, 3, 10); // the classical 2-point Radau IA spacing: 0, 2/3 with weights 1/4, 3/4
  EXPECT_NEAR(three.spacings()[1], 2.0 / 3.0, 1e-16);
  EXPECT_NEAR(three.weights()[0], 0.25, 1e-16);
}

// Brouwer's law: with compensated summation only random rounding is left, and the error walks like sqrt(t)
// (5e-14 here). Fixed errors made it grow like t: the stored weights summing to 1 + 1.4e-17 (each step went
// that much too far along its chord: 1.6e-12 at t = 1e5), a corrector stopped at an extrapolated rounding
// level (its residual points the same way every step: 1.4e-12), or one that trusted a contraction seen over
// two sweeps (a jump of 1.5e-13 at one step).
TEST(Everhart, LongRunsLeaveNoDriftOfTheInvariant) {
  test::CoupledOscillator m;
  Everhart e(0.5, 15, 12);
  e.start(m, 0, test::CoupledOscillator::exact(0));
  double worst = 0;
  for (long i = 1; i <= 200000; ++i) {
    e.step();
    if (i % 1000 == 0) {
      const double q = e.state()[0], p = e.state()[1];
      worst = std::max(worst, std::abs(q * q + p * p - 1));
    }
  }
  std::printf("  |q^2 + p^2 - 1| up to t = 1e5: %.2e\n", worst);
  EXPECT_LT(worst, 1.2e-13);
}

// On short steps the corrector contracts ~1e-3 a sweep: the first sweep fixes the prediction (whose miss is
// rounding amplified by the continuation), the second reaches rounding, the third confirms it. Four or more
// meant a correction measured against the corrected prediction (it alternated) or a stopping rule that waits
// for the change to stop shrinking when what is left is already ~1e-20.
TEST(Everhart, ShortStepsConvergeInThreeSweeps) {
  test::CoupledOscillator m;
  for (const double h : {0.02, 0.05, 0.1}) {
    Everhart e(h, 15, 12);
    e.start(m, 0, test::CoupledOscillator::exact(0));
    const long before = e.evaluations(), steps = 20000;
    for (long i = 0; i < steps; ++i)
      e.step();
    // 7 evaluations a sweep (8 nodes, the first known) and one at the new point
    const double sweeps = (static_cast<double>(e.evaluations() - before) / steps - 1) / 7;
    EXPECT_LT(sweeps, 3.1) << "h = " << h;
    EXPECT_GE(sweeps, 3.0) << "h = " << h;
    const double q = e.state()[0], p = e.state()[1];
    EXPECT_LT(std::abs(q * q + p * p - 1), 5e-15) << "h = " << h;
  }
}

TEST(Everhart, OrdersAreRoundedDownAsTheManualSays) {
  EXPECT_EQ(Everhart::effectiveOrder(15), 15);
  EXPECT_EQ(Everhart::effectiveOrder(14), 11);
  EXPECT_EQ(Everhart::effectiveOrder(100), 27);
  EXPECT_EQ(Everhart::effectiveOrder(2), 0);
  EXPECT_THROW(Everhart(0.1, 2, 10), InputError);
  EXPECT_EQ(Everhart(0.1, 9, 10).order(), 7);
}

TEST(Everhart, DenseOutputAgreesWithSmallSteps) {
  Pendulum m;
  Everhart big(0.5, 15, 30), fine(0.5 / 64, 15, 30);
  Eigen::VectorXd x0(3), a(3);
  x0 << 1.2, 0.3, 0.0;
  big.start(m, 0, x0);
  fine.start(m, 0, x0);
  for (int i = 0; i < 4; ++i)
    big.step();
  for (int i = 0; i < 3 * 64 + 17; ++i)
    fine.step(); // t = 1.5 + 17/128, inside the last big step
  big.interpolate(fine.time(), a);
  EXPECT_NEAR((a - fine.state()).norm(), 0, 1e-9);
}

TEST(Merson, KeepsTheLocalErrorNearItsPrecisionAndAdaptsTheStep) {
  Pendulum m;
  Everhart reference(0.01, 27, 30);
  const Eigen::VectorXd exact = solveFixed(reference, m, 0.01, 8.0);
  double previous = 1e300;
  for (double precision : {1e-6, 1e-8, 1e-10}) {
    Merson merson(0.01, precision, 1e-12, 1.0);
    Eigen::VectorXd x0(3), x(3);
    x0 << 1.2, 0.3, 0.0;
    merson.start(m, 0, x0);
    long steps = 0;
    while (merson.time() < 8.0)
      merson.step(), ++steps;
    merson.interpolate(8.0, x);
    const double err = (x - exact).norm();
    // the global error is the local ones summed: at most steps * precision (with a margin for the estimate)
    EXPECT_LT(err, 10 * steps * precision) << precision;
    EXPECT_LT(err, previous) << "a tighter precision gives a smaller error";
    previous = err;
  }
}

TEST(Merson, ReachingTheMinimumStepIsAnError) {
  Pendulum m;
  Merson merson(0.1, 1e-15, 0.05, 1.0);
  Eigen::VectorXd x0(3);
  x0 << 1.2, 0.3, 0.0;
  merson.start(m, 0, x0);
  try {
    for (int i = 0; i < 100; ++i)
      merson.step();
    FAIL() << "no error";
  } catch (const ComputationError& e) {
    EXPECT_NE(std::string(e.what()).find("minimum"), std::string::npos);
  }
  EXPECT_THROW(Merson(0.1, 1e-8, 1.0, 0.5), InputError);
}

// Verner's 9(8) pair: the order of the formula with the step pinned (a wrong digit among the first ten of
// any of the 16 stages' coefficients drops it), and the interpolant's: x0 + h sum b_s(theta) K_s must give
// the step's end at theta = 1 (its polynomials sum to the weights) and be of order 8 inside the step (local
// error ~ h^9; its four extra stages test the rest of the tables).
TEST(IntegratorOrder, Verner9WithAFixedStepIsNinth) {
  // Verner chose the pair for its small leading error: down to rounding (5e-14 at h = 0.2) the slope is
  // still above 9 (10.9 at h = 0.5 -> 0.4, 10.4 at 0.4 -> 0.2): at least ninth, and no eighth-order term
  const auto make = [](double h) { return std::make_unique<Verner9>(1.0, h, true); };
  const double order = measuredOrder(make, 0.4, 0.2, 8.0);
  EXPECT_GT(order, 9.0);
  EXPECT_LT(order, 11.5);
}

TEST(Verner9, TheInterpolantEndsOnTheStepAndIsOfOrderEight) {
  Pendulum m;
  Eigen::VectorXd x0(3), at(3), exact(3);
  x0 << 1.2, 0.3, 0.0;
  Everhart reference(0.001, 27, 30);
  const auto midError = [&](double h, double theta) {
    Verner9 v(1.0, h, true);
    v.start(m, 0, x0);
    v.step();
    v.interpolate(v.time(), at);
    EXPECT_LT((at - v.state()).norm(), 1e-15) << "h = " << h;
    v.interpolate(0, at);
    EXPECT_EQ(at, x0);
    reference.start(m, 0, x0);
    while (reference.time() < theta * h)
      reference.step();
    reference.interpolate(theta * h, exact);
    v.interpolate(theta * h, at);
    EXPECT_EQ(v.denseEvaluations(), 4);
    return (at - exact).norm();
  };
  for (const double theta : {0.3, 0.5, 0.8}) {
    const double e1 = midError(0.8, theta), e2 = midError(0.4, theta);
    std::printf("  theta %.1f: h 0.8 -> %.3e, h 0.4 -> %.3e\n", theta, e1, e2);
    // local error ~ h^9 (measured 9.7-10.8 at these steps, as the pair's own slope is above 9)
    EXPECT_GT(std::log(e1 / e2) / std::log(2.0), 8.7) << "theta " << theta;
    EXPECT_LT(std::log(e1 / e2) / std::log(2.0), 11.5) << "theta " << theta;
    EXPECT_LT(e1, 1e-8) << "theta " << theta;
  }
}

// The adaptive step: the error falls with the tolerance at the rate of the order against the steps taken,
// a first step far too long is redone, and near the pendulum's separatrix the steps follow its time scale.
TEST(Verner9, AdaptiveStepMeetsTheToleranceAndFollowsTheTimeScale) {
  Pendulum m;
  Eigen::VectorXd x0(3), x(3), exact(3);
  x0 << 1.2, 0.3, 0.0;
  Everhart reference(0.01, 27, 30);
  const Eigen::VectorXd end = solveFixed(reference, m, 0.01, 40.0);
  const auto run = [&](double tolerance) {
    Verner9 v(tolerance, 0.1);
    EXPECT_FALSE(v.fixedStep());
    v.start(m, 0, x0);
    long steps = 0;
    while (v.time() < 40)
      v.step(), ++steps;
    v.interpolate(40, x);
    return std::pair<double, double>((x - end).norm(), static_cast<double>(steps));
  };
  const auto [e1, n1] = run(1e-8);
  const auto [e2, n2] = run(1e-11);
  std::printf("  tolerance 1e-8: %.0f steps -> %.3e, 1e-11: %.0f steps -> %.3e\n", n1, e1, n2, e2);
  EXPECT_LT(e1, 100 * 1e-8);
  EXPECT_LT(e2, 100 * 1e-11);
  EXPECT_NEAR(std::log(e1 / e2) / std::log(n2 / n1), 9.0, 2.5);

  x0 << 3.1, 0.0, 0.0; // released near the top: slow there, fast through the bottom
  Verner9 adaptive(1e-12, 50.0);
  adaptive.start(m, 0, x0);
  const auto [shortest, longest] = stepRangeUntil(adaptive, 30);
  EXPECT_GE(adaptive.rejectedSteps(), 1);
  EXPECT_GT(longest / shortest, 1.8); // a fixed step: 1 (measured 2.0: the error is relative above |q| = 1)
  Everhart fine(0.005, 27, 40);
  fine.start(m, 0, x0);
  while (fine.time() < 30 - 1e-12)
    fine.step();
  adaptive.interpolate(30, x), fine.interpolate(30, exact);
  std::printf("  near the separatrix: steps %.3g..%.3g, error at t = 30 %.3e\n", shortest, longest,
              (x - exact).norm());
  EXPECT_LT((x - exact).norm(), 1e-8);
  EXPECT_THROW(Verner9(0, 0.1), InputError);
  EXPECT_THROW(Verner9(1e-10, -1), InputError);
}

// Adams-Bashforth-Moulton PECE: order k + 1 from the last k derivatives, measured at five orders where
// the slope has settled (pre-asymptotic it is steeper, at rounding flat; the high orders' stability region
// also bounds the step: order 13 is unstable on this pendulum above h ~ 0.1, order 17 even at 0.03). A
// corrector that is not the predictor plus h gamma_k nabla^k f leaves the predictor's order k; a wrong
// gamma_j lower still.
TEST(IntegratorOrder, AdamsIsOfItsOrder) {
  // measured 2.0, 3.9, 7.9, 10.7, 12.2 (order 13 approaches from below down to rounding)
  for (const auto& [order, h1, h2, atLeast] : {std::tuple{2, 0.05, 0.025, 1.9},
                                               {4, 0.05, 0.025, 3.7},
                                               {8, 0.025, 0.0125, 7.6},
                                               {11, 0.04, 0.032, 10.4},
                                               {13, 0.05, 0.04, 11.9}}) {
    const auto make = [order](double h) { return std::make_unique<Adams>(h, order); };
    const double measured = measuredOrder(make, h1, h2, 8.0);
    std::printf("  order %d: measured %.2f\n", order, measured);
    EXPECT_GT(measured, atLeast) << "order " << order;
    EXPECT_LT(measured, order + 1.0) << "order " << order;
  }
}

// The dense output: exact at the step's end, and inside a step the integrated polynomial through the last k
// derivatives, of order k + 1 -- checked on the first PECE step and among the starting values (where it is
// the polynomial through the starting values' derivatives).
TEST(Adams, TheInterpolantEndsOnTheStepAndHasTheMethodsOrder) {
  Pendulum m;
  Eigen::VectorXd x0(3), at(3), exact(3);
  x0 << 1.2, 0.3, 0.0;
  constexpr int kOrder = 8;
  const auto error = [&](double h, int steps, double theta) {
    Adams a(h, kOrder);
    a.start(m, 0, x0);
    for (int i = 0; i < steps; ++i)
      a.step();
    a.interpolate(a.time(), at);
    EXPECT_EQ(at, a.state());
    const double t = a.previousTime() + theta * h;
    Everhart reference(0.001, 27, 30);
    reference.start(m, 0, x0);
    while (reference.time() < t)
      reference.step();
    reference.interpolate(t, exact);
    a.interpolate(t, at);
    return (at - exact).norm();
  };
  for (const int steps : {3, kOrder}) // among the starting values; the first PECE step
    for (const double theta : {0.0, 0.3, 0.7}) {
      const double e1 = error(0.2, steps, theta), e2 = error(0.1, steps, theta);
      const double slope = std::log(e1 / e2) / std::log(2.0);
      std::printf("  step %d theta %.1f: h 0.2 -> %.3e, h 0.1 -> %.3e (slope %.2f)\n", steps, theta, e1, e2,
                  slope);
      // measured 7.2-7.8 (a cubic Hermite there: 4)
      EXPECT_GT(slope, kOrder - 1.0) << "step " << steps << " theta " << theta;
      EXPECT_LT(e1, 1e-5) << "step " << steps << " theta " << theta;
    }
}

// Integrated forward and back, the motion returns to its start (the method is its own starter both ways);
// a step far outside the stability region is reported, not returned as numbers; bad settings name the field.
TEST(Adams, RunsBackwardStopsOnBlowUpAndRefusesBadSettings) {
  Pendulum m;
  Eigen::VectorXd x0(3);
  x0 << 1.2, 0.3, 0.0;
  Adams forward(0.05, 13);
  forward.start(m, 0, x0);
  for (int i = 0; i < 400; ++i)
    forward.step();
  Adams backward(0.05, 13);
  backward.start(m, forward.time(), forward.state(), -1);
  for (int i = 0; i < 400; ++i)
    backward.step();
  EXPECT_NEAR(backward.time(), 0, 1e-12);
  EXPECT_LT((backward.state() - x0).norm(), 1e-11);
  EXPECT_EQ(forward.evaluations() > 2 * 400, true);

  // order 13 went unstable on the pendulum above h ~ 0.1 (the order test); at 0.5 on the oscillator a
  // parasitic root grows until the state is no longer finite
  test::CoupledOscillator oscillator;
  Adams tooLong(0.5, 13);
  tooLong.start(oscillator, 0, test::CoupledOscillator::exact(0));
  try {
    for (int i = 0; i < 20000; ++i)
      tooLong.step();
    ADD_FAILURE() << "a step of 0.5 at order 13 should blow up";
  } catch (const ComputationError& e) {
    EXPECT_NE(std::string(e.what()).find("stopped being finite"), std::string::npos) << e.what();
  }
  EXPECT_THROW(Adams(0.1, 1), InputError);
  EXPECT_THROW(Adams(0.1, Adams::kMaxOrder + 1), InputError);
  EXPECT_THROW(Adams(0, 13), InputError);
  EXPECT_THROW(Adams(-0.1, 13), InputError);
}

// The step's two passes run four lanes wide where the CPU has AVX2 and on SSE2 arrays elsewhere, doing the
// same operations in the same order: bit-identical, at every dimension (blocks of 16, 8, 4 and single
// components).
TEST(Adams, TheAvx2KernelsEqualThePortableOnesBitForBit) {
  if (!adams::avx2Available()) GTEST_SKIP() << "this CPU has no AVX2";
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-1, 1);
  for (const int k : {1, 6, 12})
    for (Eigen::Index n = 1; n <= 37; ++n) {
      const Eigen::MatrixXd D = Eigen::MatrixXd::NullaryExpr(n, k, [&] { return value(random); });
      const Eigen::VectorXd x = Eigen::VectorXd::NullaryExpr(n, [&] { return value(random); });
      const Eigen::VectorXd f = Eigen::VectorXd::NullaryExpr(n, [&] { return value(random); });
      std::vector<double> gamma(static_cast<std::size_t>(k));
      for (double& g : gamma)
        g = value(random);
      std::array<Eigen::VectorXd, 2> increment, sum, predicted;
      std::array<Eigen::MatrixXd, 2> shifted{D, D};
      for (const int avx2 : {0, 1}) {
        increment[avx2].resize(n), sum[avx2].resize(n), predicted[avx2].resize(n);
        adams::predict(D.data(), n, k, gamma.data(), 0.037, x.data(), increment[avx2].data(),
                       sum[avx2].data(), predicted[avx2].data(), avx2 == 1);
        adams::shift(shifted[avx2].data(), n, k, f.data(), avx2 == 1);
      }
      EXPECT_EQ(increment[0], increment[1]) << "n " << n << " k " << k;
      EXPECT_EQ(sum[0], sum[1]) << "n " << n << " k " << k;
      EXPECT_EQ(predicted[0], predicted[1]) << "n " << n << " k " << k;
      EXPECT_EQ(shifted[0], shifted[1]) << "n " << n << " k " << k;
      // and what they compute: the shift's first column is f, its second f - D_0; the sum is the row sum
      EXPECT_EQ(shifted[0].col(0), f);
      if (k > 1) {
        EXPECT_EQ(shifted[0].col(1), f - D.col(0));
      }
      EXPECT_LT((sum[0] - D.rowwise().sum()).norm(), 1e-14);
    }
}

// Everhart's passes over its node values run 8 wide (AVX-512), 4 wide (AVX2) or in SSE2 pairs, each
// component's sum in the order written here: every path gives these plain loops' numbers bit for bit, at
// every dimension (blocks of 32 and 8 components and single ones), so an orbit's rounding does not depend
// on the CPU or on the orbits stacked with it.
TEST(Everhart, ItsPassesGiveThePlainLoopsNumbersOnEveryPath) {
  using everhart::Path;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> value(-1, 1);
  for (const Path path : {Path::widest, Path::avx512, Path::avx2, Path::baseline}) {
    if (!everhart::available(path)) continue;
    for (const int n : {2, 8})
      for (Eigen::Index d = 1; d <= 70; ++d) {
        const Eigen::MatrixXd F = Eigen::MatrixXd::NullaryExpr(d, n, [&] { return value(random); });
        const Eigen::VectorXd x = Eigen::VectorXd::NullaryExpr(d, [&] { return value(random); });
        const Eigen::VectorXd c = Eigen::VectorXd::NullaryExpr(n, [&] { return value(random); });
        Eigen::VectorXd sum(d), withX(d), step(d), sumExpected(d), withXExpected(d), stepExpected(d);
        for (Eigen::Index i = 0; i < d; ++i) {
          double s = F(i, 0) * c[0], e = F(i, 0);
          for (int l = 1; l < n; ++l) {
            s = s + F(i, l) * c[l];
            e = e + c[l] * (F(i, l) - F(i, 0));
          }
          sumExpected[i] = s, withXExpected[i] = s + x[i], stepExpected[i] = e * 0.037;
        }
        everhart::combine(F.data(), d, n, c.data(), nullptr, sum.data(), path);
        everhart::combine(F.data(), d, n, c.data(), x.data(), withX.data(), path);
        everhart::increment(F.data(), d, n, c.data(), 0.037, step.data(), path);
        EXPECT_EQ(sum, sumExpected) << "d " << d << " n " << n;
        EXPECT_EQ(withX, withXExpected) << "d " << d << " n " << n;
        EXPECT_EQ(step, stepExpected) << "d " << d << " n " << n;
      }
    // the corrector's scan of stacked orbits: open lanes take the new values and their largest changes,
    // closed ones keep theirs; a NaN, an infinity and a negative zero count as std::max and std::abs count
    // them
    for (const int width : {1, 2, 4, 6, 8, 16})
      for (const Eigen::Index components : {1, 3, 11}) {
        const Eigen::Index rows = components * width, controlled = components - components / 3;
        Eigen::VectorXd f = Eigen::VectorXd::NullaryExpr(rows, [&] { return value(random); });
        Eigen::VectorXd Fj = Eigen::VectorXd::NullaryExpr(rows, [&] { return value(random); });
        f[0] = std::numeric_limits<double>::quiet_NaN();
        if (rows > 2) f[rows - 1] = -std::numeric_limits<double>::infinity(), f[1] = -0.0;
        std::vector<std::int64_t> open(static_cast<std::size_t>(width));
        std::vector<double> change(open.size()), scale(open.size());
        for (std::size_t l = 0; l < open.size(); ++l)
          open[l] = l % 3 == 1 ? 0 : -1, change[l] = 0.25 * value(random) + 0.25, scale[l] = 0.5;
        Eigen::VectorXd FjExpected = Fj;
        std::vector<double> changeExpected = change, scaleExpected = scale;
        for (Eigen::Index r = 0; r < rows; ++r) {
          const auto l = static_cast<std::size_t>(r % width);
          if (open[l] == 0) continue;
          if (r / width < controlled) {
            changeExpected[l] = std::max(changeExpected[l], std::abs(f[r] - Fj[r]));
            scaleExpected[l] = std::max(scaleExpected[l], std::abs(f[r]));
          }
          FjExpected[r] = f[r];
        }
        everhart::scanLanes(f.data(), Fj.data(), components, controlled, width, open.data(), change.data(),
                            scale.data(), path);
        for (Eigen::Index r = 0; r < rows; ++r) // (NaN == NaN is false: compare the bits)
          EXPECT_EQ(std::bit_cast<std::uint64_t>(Fj[r]), std::bit_cast<std::uint64_t>(FjExpected[r]))
              << "width " << width << " row " << r;
        for (std::size_t l = 0; l < open.size(); ++l)
          if (open[l] != 0) {
            EXPECT_EQ(std::bit_cast<std::uint64_t>(change[l]),
                      std::bit_cast<std::uint64_t>(changeExpected[l]))
                << "width " << width << " lane " << l;
            EXPECT_EQ(std::bit_cast<std::uint64_t>(scale[l]), std::bit_cast<std::uint64_t>(scaleExpected[l]))
                << "width " << width << " lane " << l;
          }
      }
  }
}

} // namespace

// A stage on lanes with a step of each lane's own is, on every lane, the scalar method's vector expression
// bit for bit: Merson's (h / 2) * (k1 - 3 * k3 + 4 * k4) added to x, and its error (h / 30) * (2 k1 - 9 k3 +
// 8 k4 - k5), written with Eigen as Merson::step writes them, on widths that take the 8- and 4-wide packets,
// both, and none, on every path this CPU runs.
TEST(LaneStages, EachLaneIsTheScalarExpressionBitForBit) {
  using lanes::Path;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> any(-3, 3);
  for (Path path : {Path::avx512, Path::avx2, Path::baseline}) {
    if (!everhart::available(path)) continue;
    for (int width : {1, 3, 4, 8, 12, 16}) {
      const Eigen::Index rows = 7, d = rows * width;
      std::vector<Eigen::VectorXd> k(4, Eigen::VectorXd(d));
      Eigen::VectorXd x(d), h(width), stage(d), error(d);
      for (auto* v : {&x, &k[0], &k[1], &k[2], &k[3]})
        for (auto& e : *v)
          e = any(random);
      for (auto& e : h)
        e = 0.01 * any(random);
      const Eigen::VectorXd half = h / 2, thirtieth = h / 30;
      const double* three[] = {k[0].data(), k[1].data(), k[2].data()};
      const double* four[] = {k[0].data(), k[1].data(), k[2].data(), k[3].data()};
      const double c3[] = {1, -3, 4}, c4[] = {2, -9, 8, -1};
      lanes::stage(x.data(), half.data(), c3, three, 3, rows, width, stage.data(), path);
      lanes::stage(nullptr, thirtieth.data(), c4, four, 4, rows, width, error.data(), path);
      for (int l = 0; l < width; ++l) {
        // lane l as a vector of its own, and the expressions as the scalar method writes them
        const auto lane = [&](const Eigen::VectorXd& v) {
          return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<>>(
              v.data() + l, rows, Eigen::InnerStride<>(width)));
        };
        const Eigen::VectorXd k1 = lane(k[0]), k3 = lane(k[1]), k4 = lane(k[2]), k5 = lane(k[3]);
        const double hl = h[l];
        const Eigen::VectorXd expected = lane(x) + (hl / 2) * (k1 - 3 * k3 + 4 * k4);
        const Eigen::VectorXd expectedError = (hl / 30) * (2 * k1 - 9 * k3 + 8 * k4 - k5);
        for (Eigen::Index r = 0; r < rows; ++r) {
          ASSERT_EQ(stage[r * width + l], expected[r]) << "width " << width << " lane " << l << " row " << r;
          ASSERT_EQ(error[r * width + l], expectedError[r]) << "width " << width << " lane " << l;
        }
      }
    }
  }
}

} // namespace rv
