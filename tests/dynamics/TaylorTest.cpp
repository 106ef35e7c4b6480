// The Taylor method: its series arithmetic against Cauchy's integral formula, its order with a fixed step,
// its adaptive step against the tolerance, Poincare crossings located on the series, and its errors.
#include "dynamics/integrators/Taylor.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelWithField.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/tools/PoincareMap.h"
#include "dynamics/tools/TangentSystem.h"
#include "tests/dynamics/TestModels.h"
#include "tests/dynamics/TestSupport.h"

#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <numbers>

namespace rv {
namespace {

// every operation the tape knows, each on a series that is not trivial (x = x0 + t)
template <class S> S everyOperation(const S& x) {
  using std::cos, std::exp, std::log, std::pow, std::sin, std::sqrt;
  const S y = 2.0 - x, z = x * x + 0.5;
  return sqrt(1.0 + x) * exp(x) / y + sin(x) * cos(2.0 * x) - 3.0 / z + log(1.0 + x * x) + pow(1.0 + x, 1.5) +
         z * z * x - (-x) / 4.0 + cos(x) * 0.5 + x / (y * z);
}

// The k-th Taylor coefficient of f(x0 + t) at t = 0 by Cauchy's integral on a circle of radius r (the
// trapezoidal rule converges geometrically for an analytic f): an independent check of every recurrence.
double cauchyCoefficient(double x0, int k, double r = 0.6, int points = 256) {
  std::complex<double> sum = 0;
  for (int m = 0; m < points; ++m) {
    const double theta = 2 * std::numbers::pi * m / points;
    const std::complex<double> t = std::polar(r, theta);
    sum += everyOperation(std::complex<double>(x0) + t) * std::polar(1.0, -k * theta);
  }
  return (sum / static_cast<double>(points)).real() / std::pow(r, k);
}

TEST(TaylorTape, EveryRecurrenceMatchesCauchysIntegral) {
  const double x0 = 0.4;
  const int order = 12;
  taylor::Tape tape;
  taylor::Var out;
  {
    taylor::Recording recording(tape, 1);
    out = everyOperation(tape.input(0, x0));
  }
  tape.setOutput(0, out);
  tape.prepare(order);
  EXPECT_NEAR(tape.output(0, 0), everyOperation(x0), 1e-14);
  for (int k = 1; k <= order; ++k) {
    tape.coefficients(0)[k] = k == 1 ? 1.0 : 0.0; // x(t) = x0 + t
    tape.evaluate(k);
    const double expected = cauchyCoefficient(x0, k);
    EXPECT_NEAR(tape.output(0, k), expected, 1e-10 * std::max(1.0, std::abs(expected))) << "order " << k;
  }
  // constants fold: no node for an operation between constants, none for x + 0 or 1 * x
  taylor::Tape small;
  taylor::Var w;
  {
    taylor::Recording recording(small, 1);
    const taylor::Var x = small.input(0, 2.0);
    w = (x + 0.0) * 1.0 + taylor::Var(3.0) * taylor::Var(4.0);
  }
  EXPECT_EQ(small.nodeCount(), 2); // the input and one AddC
  EXPECT_EQ(w.v, 14.0);
}

// A tape without branches is recorded once: new input values recompute every node's value, and the series
// at the new state are Cauchy's again; operations no output uses are not evaluated; a branch on a value
// (valueOf) marks the tape as holding for its recorded state only.
TEST(TaylorTape, ARecordingServesOtherStatesUnlessItBranched) {
  const int order = 12;
  taylor::Tape tape;
  taylor::Var out, unused;
  {
    taylor::Recording recording(tape, 1);
    const taylor::Var x = tape.input(0, 0.4);
    unused = sin(x * x) / (x + 3.0); // recorded, but no output uses it
    out = everyOperation(x);
  }
  tape.setOutput(0, out);
  EXPECT_FALSE(tape.branches());
  tape.prepare(order);
  EXPECT_EQ(tape.usedCount(), tape.nodeCount() - 1 - 5); // the input and the five unused operations
  for (const double x0 : {0.7, -0.2}) {
    tape.setInputs(&x0);
    EXPECT_NEAR(tape.output(0, 0), everyOperation(x0), 1e-14);
    for (int k = 1; k <= order; ++k) {
      tape.coefficients(0)[k] = k == 1 ? 1.0 : 0.0;
      tape.evaluate(k);
      const double expected = cauchyCoefficient(x0, k);
      EXPECT_NEAR(tape.output(0, k), expected, 1e-10 * std::max(1.0, std::abs(expected)))
          << "x0 " << x0 << ", order " << k;
    }
  }
  taylor::Tape branching;
  {
    taylor::Recording recording(branching, 1);
    const taylor::Var x = branching.input(0, 0.4);
    EXPECT_EQ(valueOf(taylor::Var(2.0)), 2.0);
    EXPECT_FALSE(branching.branches()); // a constant's value decides nothing about the state
    branching.setOutput(0, valueOf(x) > 0 ? x : -x);
  }
  EXPECT_TRUE(branching.branches());
}

class TaylorOrder : public ::testing::TestWithParam<int> {};

// With a fixed step the global error falls by 2^p when the step is halved (IntegratorOrderTest's measure).
TEST_P(TaylorOrder, FixedStepIsOfItsOrder) {
  const int p = GetParam();
  const double T = 40, h1 = p <= 2 ? 0.1 : p <= 4 ? 0.2 : p <= 8 ? 0.8 : 2.0, h2 = h1 / 2;
  test::CoupledOscillator m;
  const auto error = [&](double h) {
    Taylor taylor(1e-15, p, h);
    EXPECT_TRUE(taylor.fixedStep());
    taylor.start(m, 0, test::CoupledOscillator::exact(0));
    for (long i = 0; i < std::lround(T / h); ++i)
      taylor.step();
    EXPECT_NEAR(taylor.time(), T, 1e-12);
    return (taylor.state() - test::CoupledOscillator::exact(T)).norm();
  };
  const double e1 = error(h1), e2 = error(h2);
  std::printf("  order %d: h %.3g -> %.3e, h %.3g -> %.3e\n", p, h1, e1, h2, e2);
  EXPECT_NEAR(std::log(e1 / e2) / std::log(2.0), p, 0.3);
}
INSTANTIATE_TEST_SUITE_P(Orders, TaylorOrder, ::testing::Values(2, 4, 8, 12));

// The adaptive step keeps the error near the tolerance (Jorba and Zou: the tolerance sets the order, the
// step follows the series' radius of convergence): the default reaches rounding, looser ones trade accuracy
// for a lower order.
TEST(TaylorAdaptive, TheErrorFollowsTheTolerance) {
  test::CoupledOscillator m;
  const double T = 40;
  const auto run = [&](double tolerance) {
    Taylor taylor(tolerance, 0);
    EXPECT_FALSE(taylor.fixedStep());
    taylor.start(m, 0, test::CoupledOscillator::exact(0));
    long steps = 0;
    while (taylor.time() < T)
      taylor.step(), ++steps;
    Eigen::VectorXd x(3);
    taylor.interpolate(T, x);
    return std::pair<double, long>((x - test::CoupledOscillator::exact(T)).norm(), steps);
  };
  const auto [e6, n6] = run(1e-6);
  const auto [e9, n9] = run(1e-9);
  const auto [e15, n15] = run(1e-15);
  std::printf("  tolerance 1e-6: %ld steps, %.3e; 1e-9: %ld, %.3e; 1e-15: %ld, %.3e\n", n6, e6, n9, e9, n15,
              e15);
  EXPECT_LT(e6, 1e-4);
  EXPECT_GT(e6, 1e-10); // it does trade accuracy for work
  EXPECT_LT(e9, 1e-7);
  EXPECT_LT(e9, e6 / 30);
  EXPECT_LT(e15, 1e-13);
  EXPECT_LT(n15, 100); // long steps: about half a time unit, against 0.01 of the reference runs
  EXPECT_LT(n15, n6);  // an entire solution: a higher order reaches further
  EXPECT_EQ(Taylor::orderFor(1e-15), 19);
  EXPECT_EQ(Taylor::orderFor(1e-6), 8);
}

// A Poincare map with long Taylor steps (several crossings' worth of arc per few steps) finds the same
// points as small Everhart steps: the crossing is located on the series polynomial.
TEST(TaylorAdaptive, PoincareCrossingsAreLocatedOnTheSeries) {
  const auto m = test::makeModel("henon_heiles", {{"energy", 1.0 / 8}});
  const Eigen::VectorXd x0 = m->stateFromMap({0.1, 0.2}, {}, "t");
  auto taylor = std::make_unique<Taylor>(1e-15, 0);
  taylor->start(*m, 0, x0);
  auto everhart = std::make_unique<Everhart>(0.01, 15, 20);
  everhart->start(*m, 0, x0);
  PoincareMap a(*m, std::move(taylor), {}), b(*m, std::move(everhart), {});
  double worst = 0;
  for (int i = 0; i < 20; ++i) {
    const auto pa = a.next(), pb = b.next();
    ASSERT_TRUE(pa && pb);
    EXPECT_NEAR(pa->time, pb->time, 1e-10) << "crossing " << i;
    for (int k = 0; k < 2; ++k)
      worst = std::max(worst, std::abs(pa->coordinates[k] - pb->coordinates[k]));
  }
  EXPECT_LT(worst, 1e-11);
  const double meanStep = a.integrator().time() / (static_cast<double>(a.integrator().evaluations()) / 19.0);
  EXPECT_GT(meanStep, 0.3); // steps of a good part of a crossing's period (~6.5), not small ones
}

TEST(Taylor, RefusesWhatItCannotExpand) {
  EXPECT_THROW(Taylor(1e-15, Taylor::kMaxOrder + 1), InputError);
  EXPECT_THROW(Taylor(0, 0), InputError);
  const auto henon = test::makeModel("henon_map", {});
  Taylor taylor(1e-15, 0);
  EXPECT_THROW(taylor.start(*henon, 0, Eigen::VectorXd::Zero(2)), InputError); // a map
  // a model without a templated field (the variational system of the tangent tools)
  const auto lorenz = test::makeModel("lorenz", {});
  TangentSystem tangent(*lorenz, 1);
  try {
    taylor.start(tangent, 0, Eigen::VectorXd::Constant(tangent.dimension(), 0.5));
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("taylor"), std::string::npos) << e.what();
  }
}

TEST(Taylor, AStateThatStopsBeingFiniteIsAComputationError) {
  test::Blowup m;
  Taylor taylor(1e-15, 0, 0.6);
  taylor.start(m, 0, Eigen::VectorXd::Constant(1, 1.0));
  EXPECT_THROW(
      {
        for (int i = 0; i < 10; ++i)
          taylor.step();
      },
      ComputationError);
}

} // namespace
} // namespace rv
