// Chaplygin ball (manual §3.5): integrals (26), measure (27), exact Jacobian, completion of map points,
// and checks that do not come from the equations being tested: M + K is a vector fixed in space (the
// reaction passes through the contact point), and a ball rolling on a plane leaves traces of equal length
// on the plane and on itself.
#include "dynamics/models/ChaplyginBall.h"
#include "dynamics/core/Errors.h"
#include "dynamics/integrators/Adams.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/integrators/Taylor.h"
#include "dynamics/integrators/Verner9.h"
#include "dynamics/kinematics/AndoyerDeprit.h"
#include "dynamics/models/BodyState.h"
#include "tests/dynamics/TestSupport.h"

#include <functional>
#include <gtest/gtest.h>

namespace rv {
namespace {

std::unique_ptr<Model> asymmetricBall() {
  return test::makeModel("chaplygin_ball", {{"I1", 1.0},
                                            {"I2", 1.4},
                                            {"I3", 1.9},
                                            {"m", 1.3},
                                            {"R", 0.8},
                                            {"K1", 0.2},
                                            {"K2", -0.1},
                                            {"K3", 0.3}});
}

Eigen::VectorXd genericBallState(const Model& m) {
  return m.stateFromNamed(
      {{"M1", 0.7}, {"M2", -0.4}, {"M3", 0.9}, {"gamma1", 0.3}, {"gamma2", 0.5}, {"gamma3", 0.8}}, "test");
}

Eigen::Matrix3d spaceFrame(const Eigen::VectorXd& x) { // rows: alpha, beta, gamma in the body frame
  Eigen::Matrix3d Q;
  Q.row(0) = x.segment<3>(6).transpose(), Q.row(1) = x.segment<3>(9).transpose(),
  Q.row(2) = x.segment<3>(3).transpose();
  return Q;
}

TEST(ChaplyginBall, Rk4ConservesAllFourIntegralsOverT100) {
  const auto model = asymmetricBall();
  const Eigen::VectorXd x0 = genericBallState(*model);
  const Eigen::VectorXd I0 = model->integrals(x0.data());
  ASSERT_EQ(I0.size(), 4);
  for (int k = 0; k < 4; ++k)
    ASSERT_GT(std::abs(I0[k]), 0.1) << "integral " << k << " too small to test relatively";
  Rk4 rk4(1e-3);
  rk4.start(*model, 0, x0);
  double worst[4] = {0, 0, 0, 0};
  while (rk4.time() < 100 - 1e-9) {
    rk4.step();
    const Eigen::VectorXd I = model->integrals(rk4.state().data());
    for (int k = 0; k < 4; ++k)
      worst[k] = std::max(worst[k], std::abs(I[k] - I0[k]) / std::abs(I0[k]));
  }
  for (int k = 0; k < 4; ++k)
    EXPECT_LE(worst[k], test::tol(1e-9)) << model->info().integralNames[k];
  // the motion is not trivial: the ball turned and travelled
  EXPECT_GT((rk4.state().segment<3>(3) - x0.segment<3>(3)).norm(), 0.1);
  EXPECT_GT(rk4.state()[14], 1.0);
}

TEST(ChaplyginBall, MomentumPlusGyrostatIsFixedInSpace) {
  const auto model = asymmetricBall();
  const Eigen::VectorXd x0 = genericBallState(*model);
  const Eigen::Vector3d K(0.2, -0.1, 0.3);
  const Eigen::Vector3d P0 = spaceFrame(x0) * (x0.head<3>() + K);
  Rk4 rk4(1e-3);
  rk4.start(*model, 0, x0);
  double worst = 0;
  while (rk4.time() < 50 - 1e-9) {
    rk4.step();
    const Eigen::VectorXd& x = rk4.state();
    worst = std::max(worst, (spaceFrame(x) * (x.head<3>() + K) - P0).norm());
  }
  EXPECT_LE(worst, test::tol(1e-9) * P0.norm());
  EXPECT_NEAR(
      (spaceFrame(rk4.state()) * spaceFrame(rk4.state()).transpose() - Eigen::Matrix3d::Identity()).norm(), 0,
      1e-9)
      << "alpha, beta, gamma stay an orthonormal frame";
}

TEST(ChaplyginBall, TracesOnPlaneAndBallHaveEqualLength) {
  const auto model = asymmetricBall();
  Rk4 rk4(1e-3);
  rk4.start(*model, 0, genericBallState(*model));
  while (rk4.time() < 20 - 1e-9)
    rk4.step();
  const double* x = rk4.state().data();
  EXPECT_GT(x[14], 1.0);
  EXPECT_NEAR(x[14], x[15], 1e-9 * x[14]);
  // and the plane trace's length is at least the distance travelled
  EXPECT_GE(x[14], std::hypot(x[12], x[13]));
}

TEST(ChaplyginBall, InvariantMeasureHasZeroDivergence) {
  const auto model = asymmetricBall();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::Vector3d M(u(rng), u(rng), u(rng)), g(u(rng), u(rng), u(rng));
    const Eigen::VectorXd x = body_state::fromMomentumAndVertical(M, g);
    EXPECT_NEAR(test::divergenceOfDensityFlow(*model, x), 0, test::tol(1e-7)) << "trial " << trial;
  }
}

TEST(ChaplyginBall, WithoutTheDensityTheFlowIsNotDivergenceFree) {
  // the test above has teeth: the plain volume is not preserved (D != 0)
  const auto model = asymmetricBall();
  const Eigen::VectorXd x = genericBallState(*model);
  EXPECT_GT(std::abs(test::divergenceOfDensityFlow(*model, x, 1e-6, false)), 1e-3);
}

TEST(ChaplyginBall, AutoDiffJacobianMatchesFiniteDifferences) {
  const auto model = asymmetricBall();
  const Eigen::VectorXd x = genericBallState(*model);
  const int n = model->dimension();
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> J(n, n);
  model->jacobian(x.data(), J.data());
  Eigen::VectorXd xp, xm, fp(n), fm(n);
  const double h = 1e-6;
  for (int j = 0; j < n; ++j) {
    xp = x, xm = x;
    xp[j] += h, xm[j] -= h;
    model->rhs(xp.data(), fp.data());
    model->rhs(xm.data(), fm.data());
    for (int i = 0; i < n; ++i)
      EXPECT_NEAR(J(i, j), (fp[i] - fm[i]) / (2 * h), 1e-7) << i << "," << j;
  }
}

TEST(ChaplyginBall, MapPointIsCompletedOnTheRequestedEnergyAndArea) {
  const auto model =
      test::makeModel("chaplygin_ball", {{"energy", 0.5}, {"c", 0.3}, {"K1", 0.2}, {"K2", 0.1}, {"K3", 0.3}});
  const MapPointSpec spec{.sectionValue = 0.4, .root = 1};
  const Eigen::VectorXd x = model->stateFromMap({0.5, 0.2}, spec, "test");
  const Eigen::VectorXd I = model->integrals(x.data());
  EXPECT_NEAR(I[0], 0.5, test::tol(1e-12) * 0.5);
  EXPECT_NEAR(I[1], 0.3, 1e-13);
  EXPECT_NEAR(I[2], 1.0, 1e-14);
  const AndoyerDeprit ad = toAndoyerDeprit(x.head<3>() + Eigen::Vector3d(0.2, 0.1, 0.3), x.segment<3>(3));
  EXPECT_NEAR(ad.l, 0.5, 1e-13);
  EXPECT_NEAR(ad.L / ad.G, 0.2, 1e-13);
  EXPECT_NEAR(ad.g, 0.4, 1e-12);
}

TEST(ChaplyginBall, MapPointOutsideTheAllowedRegionIsAnInputError) {
  // at zero energy only M = 0 is allowed, so G = |K| and L/G is fixed by K: (l, L/G) = (0, 0.9) is not it
  const auto model = test::makeModel("chaplygin_ball", {{"energy", 1e-9}, {"c", 0.0}, {"K3", 1.0}});
  EXPECT_THROW(model->stateFromMap({0.0, -0.9}, {}, "test"), InputError);
}

TEST(ChaplyginBall, RejectsImpossibleInertiaMassAndRadius) {
  EXPECT_THROW(test::makeModel("chaplygin_ball", {{"I1", 1}, {"I2", 1}, {"I3", 5}}), InputError);
  EXPECT_THROW(test::makeModel("chaplygin_ball", {{"m", 0}}), InputError);
  EXPECT_THROW(test::makeModel("chaplygin_ball", {{"R", 0}}), InputError);
  EXPECT_NO_THROW(
      test::makeModel("chaplygin_ball", {{"I1", 1}, {"I2", 1}, {"I3", 2}})); // a flat disc is a body
}

} // namespace
} // namespace rv

namespace rv {
namespace {

TEST(ChaplyginBall, EverhartTaylorVernerAndAdamsConserveAllFourIntegralsToTwelveDigitsOverAThousand) {
  // two parameter sets: the default scene's, and a heavier ball with a larger, oblique gyrostat
  const std::vector<std::pair<std::unique_ptr<Model>, std::vector<double>>> cases = [] {
    std::vector<std::pair<std::unique_ptr<Model>, std::vector<double>>> c;
    c.emplace_back(test::makeModel("chaplygin_ball", {{"K1", 0.2}, {"K2", 0.1}, {"K3", 0.3}}),
                   std::vector<double>{0.5, 0.2});
    c.emplace_back(test::makeModel("chaplygin_ball", {{"I1", 0.8},
                                                      {"I2", 1.1},
                                                      {"I3", 1.5},
                                                      {"m", 2.0},
                                                      {"R", 0.7},
                                                      {"K1", -0.4},
                                                      {"K2", 0.5},
                                                      {"K3", 0.2},
                                                      {"energy", 0.8},
                                                      {"c", -0.2}}),
                   std::vector<double>{1.0, -0.3});
    return c;
  }();
  for (const auto& [model, point] : cases) {
    const Eigen::VectorXd x0 = model->stateFromMap(point, {}, "t");
    const Eigen::VectorXd I0 = model->integrals(x0.data());
    // the fixed step of the manual, IAS15's adaptive step at its default tolerance, the Taylor method at its
    // default tolerance, Verner's pair, and Adams PECE of order 13 at h = 0.03 (at 0.05 the second set leaves
    // its stability region: a blow-up at t ~ 145)
    const std::vector<std::pair<std::string, std::function<std::unique_ptr<Integrator>()>>> methods = {
        {"everhart", [] { return std::make_unique<Everhart>(0.1, 15, 12); }},
        {"everhart adaptive", [] { return std::make_unique<Everhart>(0.1, 15, 12, 1e-9); }},
        {"taylor", [] { return std::make_unique<Taylor>(1e-15, 0); }},
        {"verner9", [] { return std::make_unique<Verner9>(1e-14, 0.1); }},
        {"adams", [] { return std::make_unique<Adams>(0.03, 13); }}};
    for (const auto& [name, make] : methods) {
      const auto e = make();
      e->start(*model, 0, x0);
      Eigen::VectorXd worst = Eigen::VectorXd::Zero(4);
      while (e->time() < 1000 - 1e-9) {
        e->step();
        const Eigen::VectorXd I = model->integrals(e->state().data());
        worst = worst.cwiseMax(((I - I0).array().abs() / I0.array().abs()).matrix());
      }
      for (int k = 0; k < 4; ++k)
        EXPECT_LE(worst[k], test::tol(1e-12)) << model->info().integralNames[k] << ", " << name;
    }
  }
}

} // namespace
} // namespace rv

#include "dynamics/tools/Continuation.h"

namespace rv {
namespace {

// A steady rotation about the vertical of the scene's ball (I = (1, 1.4, 1.9), m = R = 1, K = (K1, 0.1,
// 0.3)), found independently of the model's code: omega from M = J omega - D (gamma, omega) gamma by a linear
// solve (the model uses a closed form), and Newton on (theta, phi, K1) for gamma x omega = 0 with M + K = c
// gamma (then dM/dt = (M + K) x omega = 0 too) at the energy h. Returns (gamma, K1).
std::pair<Eigen::Vector3d, double> steadyRotationAtEnergy(double c, double h, Eigen::Vector3d gamma,
                                                          double k1) {
  const Eigen::Vector3d I(1.0, 1.4, 1.9);
  const double D = 1.0;
  const auto unitOf = [](double th, double ph) {
    return Eigen::Vector3d(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
  };
  const auto residual = [&](const Eigen::Vector3d& u) {
    const Eigen::Vector3d g = unitOf(u[0], u[1]), K(u[2], 0.1, 0.3), M = c * g - K;
    const Eigen::Matrix3d A =
        Eigen::Matrix3d(I.asDiagonal()) + D * (Eigen::Matrix3d::Identity() - g * g.transpose());
    const Eigen::Vector3d w = A.partialPivLu().solve(M), e = g.cross(w);
    const Eigen::Vector3d t1 = unitOf(u[0] + M_PI / 2, u[1]), t2 = g.cross(t1);
    return Eigen::Vector3d(e.dot(t1), e.dot(t2), 0.5 * M.dot(w) - h);
  };
  Eigen::Vector3d u(std::acos(gamma.normalized()[2]), std::atan2(gamma[1], gamma[0]), k1);
  for (int it = 0; it < 30; ++it) {
    const Eigen::Vector3d r = residual(u);
    Eigen::Matrix3d jac;
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d v = u;
      v[j] += 1e-7;
      jac.col(j) = (residual(v) - r) / 1e-7;
    }
    u -= jac.partialPivLu().solve(r);
  }
  EXPECT_LT(residual(u).norm(), 1e-13);
  return {unitOf(u[0], u[1]), u[2]};
}

// The shipped scene's elliptic point (scenes/chaplygin_ball.json) continued up in K1 (issue 41). Every orbit
// keeps G = |M + K| (G^2 is an integral) and G >= |c| by Cauchy-Schwarz, equal only where M + K = c gamma.
// Along this family G falls to |c|: the periodic orbit shrinks onto a steady rotation about the vertical
// (omega || gamma, M + K = c gamma) whose energy is the scene's h at K1* = 0.6665998 -- a Lyapunov family
// ending at its centre, which the section g = 0 cannot hold (g is undefined where M + K is vertical). It is
// no fold: the multipliers stay on the unit circle near -1. The completion scans sqrt(G^2 - c^2), where the
// two roots near the pole stay apart (in G they crowd closer than the scan step and the family stopped at K1
// = 0.66648). This test pins down the end against the steady rotation found independently.
TEST(ChaplyginBall, TheShippedFixedPointsFamilyInK1ShrinksOntoASteadyRotationAboutTheVertical) {
  const Continuation::ModelAt at = [](double k1) {
    return test::makeModel("chaplygin_ball", {{"energy", 0.5},
                                              {"c", 0.3},
                                              {"I1", 1.0},
                                              {"I2", 1.4},
                                              {"I3", 1.9},
                                              {"m", 1.0},
                                              {"R", 1.0},
                                              {"K1", k1},
                                              {"K2", 0.1},
                                              {"K3", 0.3}});
  };
  SectionSettings section;
  section.observable = "g";
  ContinuationSettings s;
  s.parameter = "K1";
  s.to = 0.7;
  s.step = 0.002;
  s.method = ContinuationMethod::Arclength;
  const IntegratorFactory verner = [] { return std::make_unique<Verner9>(1e-13, 0.1); };
  Continuation c(at, verner, section, 0.66, Eigen::Vector2d(-1.6661, 0.1045), s);
  std::string failure;
  try {
    c.run({});
  } catch (const ComputationError& e) {
    failure = e.what();
  }
  ASSERT_FALSE(failure.empty()) << "the family went on to K1 = " << c.points().back().parameter;
  EXPECT_NE(failure.find("not a fold"), std::string::npos) << failure;
  const auto stateAt = [&](std::size_t i) {
    const auto& p = c.points()[i];
    const auto m = at(p.parameter);
    return ReturnMap(*m, verner, section).stateOf(p.fixedPoint.point);
  };
  const std::size_t last = c.points().size() - 1;
  const double end = c.points()[last].parameter;
  const Eigen::VectorXd x = stateAt(last);
  const auto [gamma, kStar] = steadyRotationAtEnergy(0.3, 0.5, x.segment<3>(3), end);
  EXPECT_NEAR(kStar, 0.6666, 1e-4);
  // followed past 0.6665, to within 1e-4 of the steady rotation
  EXPECT_GT(end, 0.6665);
  EXPECT_LT(end, kStar);
  EXPECT_LT(kStar - end, 1e-4);
  // the tool says so, and where: its extrapolation of the flow's speed to zero
  const std::string said = "the orbit shrinks onto an equilibrium";
  ASSERT_NE(failure.find(said), std::string::npos) << failure;
  const std::size_t where = failure.find("K1 = ", failure.find(said));
  ASSERT_NE(where, std::string::npos) << failure;
  EXPECT_NEAR(std::stod(failure.substr(where + 5)), kStar, 1e-7) << failure;
  // natural continuation with a small step gets closer, and its failure says the same, to 1e-8
  ContinuationSettings natural = s;
  natural.method = ContinuationMethod::Natural;
  natural.step = 2e-4;
  Continuation n(at, verner, section, 0.66, Eigen::Vector2d(-1.6661, 0.1045), natural);
  std::string naturalFailure;
  try {
    n.run({});
  } catch (const ComputationError& e) {
    naturalFailure = e.what();
  }
  EXPECT_LT(kStar - n.points().back().parameter, 1e-5);
  const std::size_t naturalSays = naturalFailure.find(said);
  ASSERT_NE(naturalSays, std::string::npos) << naturalFailure;
  EXPECT_NEAR(std::stod(naturalFailure.substr(naturalFailure.find("K1 = ", naturalSays) + 5)), kStar, 1e-8)
      << naturalFailure;
  // the last point's state lies near the steady rotation, and G near |c|
  EXPECT_LT((x.segment<3>(3) - gamma).norm(), 0.05);
  EXPECT_LT((x.head<3>() - (0.3 * gamma - Eigen::Vector3d(kStar, 0.1, 0.3))).norm(), 0.05);
  double lastG = 1e9;
  for (std::size_t i = 0; i <= last; i += 10) {
    const auto& p = c.points()[i];
    // elliptic all along, the multipliers far from +1
    for (const auto& m : p.fixedPoint.multipliers) {
      EXPECT_NEAR(std::abs(m), 1, 1e-6) << p.parameter;
      EXPECT_GT(std::abs(m - 1.0), 1.9) << p.parameter;
    }
    // G of the point's state (constant along its orbit) falls toward |c|
    const double G = (stateAt(i).head<3>() + Eigen::Vector3d(p.parameter, 0.1, 0.3)).norm();
    EXPECT_LT(G, lastG) << p.parameter;
    lastG = G;
  }
  EXPECT_LT((x.head<3>() + Eigen::Vector3d(end, 0.1, 0.3)).norm() - 0.3, 3e-4);
}

} // namespace
} // namespace rv
