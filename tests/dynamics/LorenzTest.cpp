// Lorenz: the divergence of the flow is -(sigma + 1 + beta) everywhere (checks the exact Jacobian), and
// RK4 converges with order 4 on it.
#include "dynamics/integrators/Rk4.h"
#include "tests/dynamics/TestSupport.h"

#include <cmath>
#include <gtest/gtest.h>

namespace rv {
namespace {

// the states at t = 0.1, 0.2, ..., T (grid points of every step tried), stacked
Eigen::VectorXd solve(const Model& m, double h, double T) {
  Rk4 rk4(h);
  Eigen::VectorXd x0(3);
  x0 << 1, 1, 1;
  rk4.start(m, 0, x0);
  const long every = std::lround(0.1 / h), n = std::lround(T / h);
  Eigen::VectorXd out(3 * (n / every));
  for (long i = 1; i <= n; ++i) {
    rk4.step();
    if (i % every == 0) out.segment<3>(3 * (i / every - 1)) = rk4.state();
  }
  return out;
}

TEST(Lorenz, Rk4ConvergesWithOrderFour) {
  const auto m = test::makeModel("lorenz", {});
  // the largest error along the way, so that a lucky zero of the error at one time cannot fake the order
  const double T = 2.0;
  const Eigen::VectorXd ref = solve(*m, 1e-4, T);
  double previous = 0;
  for (double h : {0.01, 0.005, 0.0025}) {
    const double err = (solve(*m, h, T) - ref).lpNorm<Eigen::Infinity>();
    if (previous > 0) {
      const double order = std::log2(previous / err);
      EXPECT_NEAR(order, 4.0, 0.3) << "h = " << h << ", error ratio " << previous / err;
    }
    previous = err;
  }
}

TEST(Lorenz, JacobianTraceIsMinusSigmaPlusOnePlusBeta) {
  const auto m = test::makeModel("lorenz", {{"sigma", 10}, {"rho", 28}, {"beta", 8.0 / 3.0}});
  const double x[3] = {3.0, -2.0, 17.0};
  double J[9];
  m->jacobian(x, J);
  EXPECT_NEAR(J[0] + J[4] + J[8], -(10 + 1 + 8.0 / 3.0), 1e-14);
  EXPECT_DOUBLE_EQ(J[1 * 3 + 2], -3.0); // d(x(rho - z) - y)/dz = -x
}

} // namespace
} // namespace rv
