// Reference systems: Henon-Heiles (a Hamiltonian flow), the Henon and standard maps (explicit maps).
#include "dynamics/core/Errors.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/MapIteration.h"
#include "tests/dynamics/TestSupport.h"

#include <cmath>
#include <gtest/gtest.h>

namespace rv {
namespace {

TEST(HenonHeiles, EverhartConservesEnergyAndTheFlowPreservesVolume) {
  const auto m = test::makeModel("henon_heiles", {{"energy", 0.125}});
  const Eigen::VectorXd x0 = m->stateFromMap({0.1, 0.1}, {}, "t");
  EXPECT_NEAR(m->integrals(x0.data())[0], 0.125, 1e-15);
  EXPECT_GT(x0[2], 0) << "the section is crossed with px > 0";
  Everhart e(0.05, 15, 12);
  e.start(*m, 0, x0);
  double worst = 0;
  while (e.time() < 1000 - 1e-9) {
    e.step();
    worst = std::max(worst, std::abs(m->integrals(e.state().data())[0] - 0.125) / 0.125);
  }
  EXPECT_LE(worst, test::tol(1e-12));
  EXPECT_NEAR(test::divergenceOfDensityFlow(*m, e.state()), 0, 1e-8);
}

TEST(HenonHeiles, TheStraightLineOrbitStaysOnItsLine) {
  // the potential has straight-line orbits through the origin along 30, 150 and 270 degrees; at E = 1/8 the
  // one along 30 degrees crosses x = 0 at (y, py) = (0, sqrt(E/2)) = (0, 0.25) with px = sqrt(3) py
  const auto m = test::makeModel("henon_heiles", {{"energy", 0.125}});
  const Eigen::VectorXd x0 = m->stateFromMap({0.0, 0.25}, {}, "t");
  EXPECT_NEAR(x0[2], std::sqrt(3.0) * 0.25, 1e-15);
  Everhart e(0.01, 15, 12);
  e.start(*m, 0, x0);
  double off = 0, reach = 0;
  while (e.time() < 10) {
    e.step();
    const Eigen::VectorXd& s = e.state();
    off = std::max(off, std::abs(s[1] * std::cos(M_PI / 6) - s[0] * std::sin(M_PI / 6)));
    reach = std::max(reach, std::hypot(s[0], s[1]));
  }
  EXPECT_LT(off, 1e-9) << "it stays on the line y = x tan 30";
  EXPECT_GT(reach, 0.3) << "and goes along it";
  EXPECT_THROW(m->stateFromMap({0.0, 0.6}, {}, "t"), InputError) << "py^2 > 2E: no state";
}

TEST(HenonMap, IteratesAndItsJacobianDeterminantIsMinusB) {
  const auto m = test::makeModel("henon_map", {{"a", 1.4}, {"b", 0.3}});
  EXPECT_TRUE(m->isMap());
  const double x[2] = {0.4, -0.2};
  double out[2], J[4];
  m->rhs(x, out);
  EXPECT_DOUBLE_EQ(out[0], 1 - 1.4 * 0.16 - 0.2);
  EXPECT_DOUBLE_EQ(out[1], 0.3 * 0.4);
  m->jacobian(x, J);
  EXPECT_NEAR(J[0] * J[3] - J[1] * J[2], -0.3, 1e-15);
  EXPECT_DOUBLE_EQ(J[0], -2 * 1.4 * 0.4);
}

TEST(StandardMap, IsAreaPreservingAndWrapsToTheTorus) {
  const auto m = test::makeModel("standard_map", {{"K", 1.3}});
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0, 2 * M_PI);
  for (int i = 0; i < 100; ++i) {
    const double x[2] = {u(rng), u(rng)};
    double J[4], out[2];
    m->jacobian(x, J);
    EXPECT_NEAR(J[0] * J[3] - J[1] * J[2], 1.0, 1e-14);
    EXPECT_NEAR(J[0], 1 + 1.3 * std::cos(x[0]), 1e-14); // d theta' / d theta
    m->rhs(x, out);
    EXPECT_GE(out[0], 0);
    EXPECT_LT(out[0], 2 * M_PI);
    EXPECT_GE(out[1], 0);
    EXPECT_LT(out[1], 2 * M_PI);
    const double p = x[1] + 1.3 * std::sin(x[0]);
    EXPECT_NEAR(std::remainder(out[1] - p, 2 * M_PI), 0, 1e-13);
    EXPECT_NEAR(std::remainder(out[0] - x[0] - p, 2 * M_PI), 0, 1e-13);
  }
  // (pi, 0) is fixed, with trace 2 - K
  const double fixed[2] = {M_PI, 0};
  double out[2], J[4];
  m->rhs(fixed, out);
  EXPECT_NEAR(out[0], M_PI, 1e-15);
  EXPECT_NEAR(std::remainder(out[1], 2 * M_PI), 0, 1e-15);
  m->jacobian(fixed, J);
  EXPECT_NEAR(J[0] + J[3], 2 - 1.3, 1e-15);
}

TEST(MapIteration, StepsTheMapOnceATimeUnit) {
  const auto m = test::makeModel("henon_map", {});
  MapIteration it;
  Eigen::VectorXd x0(2), x(2);
  x0 << 0.1, 0.1;
  it.start(*m, 0, x0);
  it.step();
  it.step();
  EXPECT_EQ(it.time(), 2.0);
  it.interpolate(1.5, x);
  EXPECT_NEAR(x[0], 1.086, 1e-15) << "between iterates: the last one";
  EXPECT_THROW(it.start(*m, 0, x0, -1), InputError);
  const auto flow = test::makeModel("lorenz", {});
  Eigen::VectorXd y0 = Eigen::VectorXd::Ones(3);
  EXPECT_THROW(it.start(*flow, 0, y0), InputError);
}

} // namespace
} // namespace rv
