// Bodies rolling on a plane (manual §3.1, §3.2). Checks that do not trust the equations under test:
// - equation (2) against an independent Newton-Euler model (reaction force solved from the constraint);
// - a ball through the generic rigid-body code equals the Chaplygin ball of §3.5 (another formulation);
// - the Gauss maps: the contact point lies on the surface, the normal there is -gamma, and the rate agrees
//   with a finite difference;
// - the rattleback reverses a spin in one direction only.
#include "dynamics/core/Errors.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/kinematics/AndoyerDeprit.h"
#include "dynamics/models/BodyState.h"
#include "dynamics/models/EllipsoidOnPlane.h"
#include "dynamics/models/ParaboloidOnPlane.h"
#include "dynamics/tools/TangentSystem.h"
#include "tests/dynamics/TestSupport.h"

#include <gtest/gtest.h>

namespace rv {
namespace {

std::unique_ptr<Model> offsetEllipsoid() { // offset centre of mass, turned axes, a field
  return test::makeModel("ellipsoid_on_plane", {{"b1", 1.3},
                                                {"b2", 0.9},
                                                {"b3", 0.6},
                                                {"a1", 0.05},
                                                {"a2", -0.04},
                                                {"a3", -0.12},
                                                {"phi", 0.3},
                                                {"theta", 0.2},
                                                {"psi", 0.4},
                                                {"I1", 0.5},
                                                {"I2", 0.7},
                                                {"I3", 0.9},
                                                {"m", 1.3},
                                                {"g", 2.0},
                                                {"B11", 0.3},
                                                {"B12", 0.1},
                                                {"B22", 0.2},
                                                {"B33", 0.1}});
}
std::unique_ptr<Model> turnedParaboloid() {
  return test::makeModel("paraboloid_on_plane", {{"p", 0.8},
                                                 {"q", 1.7},
                                                 {"h", 0.4},
                                                 {"delta", 0.5},
                                                 {"I1", 1.1},
                                                 {"I2", 1.4},
                                                 {"I3", 2.1},
                                                 {"m", 0.9},
                                                 {"g", 1.5},
                                                 {"B13", 0.05},
                                                 {"B11", 0.2},
                                                 {"B33", 0.1}});
}

Eigen::VectorXd randomState(std::mt19937& rng, bool upper) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::Vector3d M(u(rng), u(rng), u(rng)), g(0.5 * u(rng), 0.5 * u(rng), upper ? 1.0 : u(rng));
  return body_state::fromMomentumAndVertical(M, g);
}

// omega-dot from Newton-Euler in the body frame with the reaction F at the contact point as unknown:
//   m (v' + w x v) = F - m g gamma,  I w' + w x I w = r x F + gamma x B gamma,  v = -w x r
template <class Body> Eigen::Vector3d newtonEulerOmegaDot(const Body& body, const Eigen::VectorXd& x) {
  const RigidBodyConstants& c = body.constants();
  const Eigen::Vector3d M = x.head<3>(), g = x.segment<3>(3);
  const Eigen::Vector3d r = body.template contact<double>(g);
  const Eigen::Vector3d w = body.template angularVelocity<double>(M, r);
  const Eigen::Vector3d dr = body.template contactRate<double>(g, g.cross(w));
  const Eigen::Vector3d v = -w.cross(r);
  // F = m (r x w') + m (-w x r' + w x v + g gamma); substitute into the moment equation
  const Eigen::Vector3d Fknown = c.mass * (-w.cross(dr) + w.cross(v) + c.gravity * g);
  Eigen::Matrix3d A =
      c.inertia + c.mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  const Eigen::Vector3d rhs = -w.cross(c.inertia * w) + r.cross(Fknown) + g.cross(c.field * g);
  return A.lu().solve(rhs);
}

// omega-dot from (2): M = A(r) w  =>  w' = A^-1 (M' - A' w)
template <class Body> Eigen::Vector3d equationTwoOmegaDot(const Body& body, const Eigen::VectorXd& x) {
  const RigidBodyConstants& c = body.constants();
  Eigen::VectorXd dx(x.size());
  body.rhs(x.data(), dx.data());
  const Eigen::Vector3d M = x.head<3>(), g = x.segment<3>(3);
  const Eigen::Vector3d r = body.template contact<double>(g);
  const Eigen::Vector3d w = body.template angularVelocity<double>(M, r);
  const Eigen::Vector3d dr = body.template contactRate<double>(g, dx.segment<3>(3));
  const Eigen::Matrix3d A =
      c.inertia + c.mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
  const Eigen::Matrix3d dA =
      c.mass * (2 * r.dot(dr) * Eigen::Matrix3d::Identity() - dr * r.transpose() - r * dr.transpose());
  return A.lu().solve(Eigen::Vector3d(dx.head<3>() - dA * w));
}

TEST(RigidBodyOnPlane, EquationTwoAgreesWithNewtonEuler) {
  std::mt19937 rng(11);
  const auto e = offsetEllipsoid();
  const auto p = turnedParaboloid();
  const auto& ell = static_cast<const EllipsoidOnPlane&>(*e);
  const auto& par = static_cast<const ParaboloidOnPlane&>(*p);
  for (int i = 0; i < 25; ++i) {
    const Eigen::VectorXd xe = randomState(rng, false), xp = randomState(rng, true);
    EXPECT_LT((newtonEulerOmegaDot(ell, xe) - equationTwoOmegaDot(ell, xe)).norm(), 1e-12) << i;
    EXPECT_LT((newtonEulerOmegaDot(par, xp) - equationTwoOmegaDot(par, xp)).norm(), 1e-12) << i;
  }
}

// a balanced ball of radius R as a generic rigid body: must move exactly as the Chaplygin ball (K = 0)
const ModelInfo& sphereInfo() {
  static const ModelInfo info{.id = "sphere_test",
                              .stateNames = body_state::names(),
                              .coreDimension = 6,
                              .integralNames = {"E", "geometric"}};
  return info;
}
struct SphereOnPlane final : RigidBodyOnPlane<SphereOnPlane> {
  SphereOnPlane(double R, const RigidBodyConstants& c)
      : RigidBodyOnPlane(sphereInfo(), ParameterValues(sphereInfo().parameters), c), R_(R) {}
  template <class S> V3<S> contact(const V3<S>& g) const { return -R_ * g; }
  template <class S> V3<S> contactRate(const V3<S>&, const V3<S>& dg) const { return -R_ * dg; }
  bool touches(const Eigen::Vector3d&) const { return true; }
  double R_;
};

TEST(RigidBodyOnPlane, ABallMovesAsTheChaplyginBall) {
  const auto chaplygin =
      test::makeModel("chaplygin_ball", {{"I1", 1.0}, {"I2", 1.4}, {"I3", 1.9}, {"m", 1.3}, {"R", 0.8}});
  RigidBodyConstants c;
  c.inertia = Eigen::Vector3d(1.0, 1.4, 1.9).asDiagonal();
  c.mass = 1.3, c.gravity = 9.8; // gravity exerts no torque on a balanced ball
  SphereOnPlane sphere(0.8, c);
  const Eigen::VectorXd x0 =
      body_state::fromMomentumAndVertical(Eigen::Vector3d(0.7, -0.4, 0.9), Eigen::Vector3d(0.3, 0.5, 0.8));
  Everhart a(0.02, 15, 20), b(0.02, 15, 20);
  a.start(*chaplygin, 0, x0);
  b.start(sphere, 0, x0);
  for (int i = 0; i < 2500; ++i)
    a.step(), b.step();
  EXPECT_LT((a.state() - b.state()).norm(), 1e-10) << "t = 50";
  EXPECT_GT((a.state() - x0).norm(), 0.5) << "and it did move";
}

// The sphere's field is large and has no recorded program (no kLaneField): ModelWithField compiles its pass
// for 1 and 6 directions only; every other count runs the 6-direction pass with zero directions added, and
// the Jacobians go in passes of it. Each count must give the derivatives a finite difference of the field
// gives, and the same bits whatever the count (a direction's arithmetic does not depend on the others).
TEST(RigidBodyOnPlane, APlainFieldsDerivativesAreRightForEveryCount) {
  RigidBodyConstants c;
  c.inertia = Eigen::Vector3d(1.0, 1.4, 1.9).asDiagonal();
  c.mass = 1.3, c.gravity = 9.8;
  const SphereOnPlane sphere(0.8, c);
  const Eigen::VectorXd x =
      body_state::fromMomentumAndVertical(Eigen::Vector3d(0.7, -0.4, 0.9), Eigen::Vector3d(0.3, 0.5, 0.8));
  const int n = sphere.dimension(), m = sphere.info().coreDimension;
  Eigen::MatrixXd V(m, 13);
  for (Eigen::Index i = 0; i < V.size(); ++i)
    V.data()[i] = std::sin(1.7 * static_cast<double>(i) + 0.3);
  const auto derivatives = [&](int k) {
    Eigen::VectorXd dx(n);
    Eigen::MatrixXd dV(m, k);
    sphere.tangentRhs(x.data(), V.data(), k, dx.data(), dV.data());
    return dV;
  };
  const Eigen::MatrixXd all = derivatives(13); // passes of 6, 6 and 1
  for (int j = 0; j < 13; ++j) {               // each column against a central difference of the field
    const double h = 1e-6;
    Eigen::VectorXd plus = x, minus = x, fPlus(n), fMinus(n);
    plus.head(m) += h * V.col(j), minus.head(m) -= h * V.col(j);
    sphere.rhs(plus.data(), fPlus.data());
    sphere.rhs(minus.data(), fMinus.data());
    const Eigen::VectorXd difference = (fPlus - fMinus).head(m) / (2 * h);
    EXPECT_LT((all.col(j) - difference).cwiseAbs().maxCoeff(), 1e-7 * std::max(1.0, difference.norm()))
        << "direction " << j;
  }
  EXPECT_GT(all.cwiseAbs().maxCoeff(), 1e-3) << "the derivatives are not all zero";
  for (const int k : {1, 2, 3, 5, 6, 7}) // compiled, padded, and two passes
    EXPECT_EQ(derivatives(k), all.leftCols(k)) << "k = " << k;
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  RowMajor J(n, n), core(m, m);
  sphere.jacobian(x.data(), J.data());
  sphere.coreJacobian(x.data(), core.data());
  EXPECT_EQ(core, J.topLeftCorner(m, m)) << "the core block of the Jacobian, bit for bit";
  const Eigen::MatrixXd JV = core * V;
  EXPECT_LT((JV - all).cwiseAbs().maxCoeff(), 1e-13 * std::max(1.0, all.cwiseAbs().maxCoeff()));
  // the fused steps of a count not compiled (4) are the rk4 integrator's on the variational system
  TangentSystem tangent(sphere, 4);
  Eigen::VectorXd state(tangent.dimension());
  state.head(n) = x;
  for (Eigen::Index i = n; i < state.size(); ++i)
    state[i] = std::cos(0.9 * static_cast<double>(i));
  Eigen::VectorXd fused = state;
  ASSERT_TRUE(tangent.rk4Steps(fused, 0.01, 25));
  Rk4 rk4(0.01);
  rk4.start(tangent, 0, state);
  for (int s = 0; s < 25; ++s)
    rk4.step();
  EXPECT_LT((fused - rk4.state()).cwiseAbs().maxCoeff(),
            1e-14 * std::max(1.0, rk4.state().cwiseAbs().maxCoeff()));
  EXPECT_GT((fused - state).cwiseAbs().maxCoeff(), 1e-6) << "it moved";
}

TEST(RigidBodyOnPlane, GaussMapsPutTheContactOnTheSurfaceWithNormalMinusGamma) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto e = offsetEllipsoid();
  const auto p = turnedParaboloid();
  const auto& ell = static_cast<const EllipsoidOnPlane&>(*e);
  const auto& par = static_cast<const ParaboloidOnPlane&>(*p);
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector3d g = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    // ellipsoid (8): sum (r + a)_i^2 / b_i^2 = 1 with gradient along -gamma
    const Eigen::Vector3d r = ell.contact<double>(g), y = r - ell.geometricCentre(), b = ell.semiAxes();
    EXPECT_NEAR((y.array() / b.array()).matrix().squaredNorm(), 1.0, 1e-13);
    const Eigen::Vector3d grad = (y.array() / (b.array() * b.array())).matrix();
    EXPECT_NEAR((grad.normalized() + g).norm(), 0, 1e-12);
    // paraboloid (5): (r1^2/p + r2^2/q)/2 - (r3 + h) = 0 with gradient along -gamma (gamma3 > 0)
    const Eigen::Vector3d gp = Eigen::Vector3d(0.6 * u(rng), 0.6 * u(rng), 1.0).normalized();
    const Eigen::Vector3d rp = par.contact<double>(gp);
    EXPECT_NEAR(0.5 * (rp[0] * rp[0] / par.p() + rp[1] * rp[1] / par.q()) - (rp[2] + par.h()), 0, 1e-13);
    const Eigen::Vector3d gradp(rp[0] / par.p(), rp[1] / par.q(), -1.0);
    EXPECT_NEAR((gradp.normalized() + gp).norm(), 0, 1e-12);
    // the rates are the derivatives of the maps
    const Eigen::Vector3d dg = g.cross(Eigen::Vector3d(u(rng), u(rng), u(rng))),
                          dgp = gp.cross(Eigen::Vector3d(u(rng), u(rng), u(rng)));
    const double h = 1e-6;
    EXPECT_LT((ell.contactRate<double>(g, dg) -
               (ell.contact<double>(g + h * dg) - ell.contact<double>(g - h * dg)) / (2 * h))
                  .norm(),
              1e-8);
    EXPECT_LT((par.contactRate<double>(gp, dgp) -
               (par.contact<double>(gp + h * dgp) - par.contact<double>(gp - h * dgp)) / (2 * h))
                  .norm(),
              1e-8);
  }
}

TEST(RigidBodyOnPlane, EverhartConservesEnergyToTwelveDigitsOverAThousand) {
  const auto run = [](const Model& m, const Eigen::VectorXd& x0, double h) {
    const double E0 = m.integrals(x0.data())[0];
    Everhart e(h, 15, 12);
    e.start(m, 0, x0);
    double worst = 0, worstGeo = 0;
    while (e.time() < 1000 - 1e-9) {
      e.step();
      const Eigen::VectorXd I = m.integrals(e.state().data());
      worst = std::max(worst, std::abs(I[0] - E0) / std::abs(E0));
      worstGeo = std::max(worstGeo, std::abs(I[1] - 1));
    }
    EXPECT_LE(worst, test::tol(1e-12)) << m.info().id;
    EXPECT_LE(worstGeo, test::tol(1e-12)) << m.info().id;
  };
  for (const auto& m : {offsetEllipsoid(), test::makeModel("ellipsoid_on_plane", {})}) {
    const Eigen::VectorXd x0 = m->stateFromNamed(
        {{"M1", 0.1}, {"M2", 0.05}, {"M3", -0.4}, {"gamma1", 0.05}, {"gamma2", 0.1}, {"gamma3", 1}}, "t");
    run(*m, x0, 0.01);
  }
  for (const auto& m : {turnedParaboloid(), test::makeModel("paraboloid_on_plane", {{"energy", 1.0}})}) {
    const Eigen::VectorXd x0 = m->stateFromNamed(
        {{"M1", 0.2}, {"M2", -0.1}, {"M3", 0.5}, {"gamma1", 0.1}, {"gamma2", 0.15}, {"gamma3", 1}}, "t");
    run(*m, x0, 0.02);
  }
}

TEST(RigidBodyOnPlane, MapPointsAreCompletedOnTheEnergyWithTheirAndoyerDepritCoordinates) {
  const auto m = test::makeModel("paraboloid_on_plane", {{"energy", 1.0}});
  const Eigen::VectorXd x = m->stateFromMap({0.5, 0.95, 0.97}, {.sectionValue = 0.3}, "t");
  EXPECT_NEAR(m->integrals(x.data())[0], 1.0, 1e-13);
  const AndoyerDeprit ad = toAndoyerDeprit(x.head<3>(), x.segment<3>(3));
  EXPECT_NEAR(ad.l, 0.5, 1e-13);
  EXPECT_NEAR(ad.L / ad.G, 0.95, 1e-13);
  EXPECT_NEAR(ad.H / ad.G, 0.97, 1e-13);
  EXPECT_NEAR(ad.g, 0.3, 1e-12);
  // below the potential energy of that tilt there is no state: outside the region of allowed motion
  const auto low = test::makeModel("paraboloid_on_plane", {{"energy", 0.1}});
  EXPECT_THROW(low->stateFromMap({0.5, 0.95, 0.97}, {}, "t"), InputError);
  // a vertical the paraboloid cannot stand on (gamma3 < 0)
  EXPECT_THROW(m->stateFromMap({0.5, 0.3, 0.9}, {}, "t"), InputError);
}

TEST(RigidBodyOnPlane, TheRattlebackReversesOnlyOneSpin) {
  const auto m = test::makeModel("ellipsoid_on_plane", {});
  const auto spin = [&](double M3) {
    const Eigen::VectorXd x0 = m->stateFromNamed(
        {{"M1", 0}, {"M2", 0}, {"M3", M3}, {"gamma1", 0}, {"gamma2", 0.02}, {"gamma3", 1}}, "t");
    const int w3 = m->findObservable("omega3");
    Everhart e(0.01, 15, 12);
    e.start(*m, 0, x0);
    double lo = 1e9, hi = -1e9;
    while (e.time() < 40) {
      e.step();
      const double w = m->observables()[w3].value(e.time(), e.state().data());
      lo = std::min(lo, w), hi = std::max(hi, w);
    }
    return std::pair{lo, hi};
  };
  const auto [loNeg, hiNeg] = spin(-0.3);
  EXPECT_GT(hiNeg, 0.3) << "spun clockwise, it turns back";
  const auto [loPos, hiPos] = spin(+0.3);
  EXPECT_GT(loPos, 0.2) << "spun the other way, it keeps spinning";
}

TEST(RigidBodyOnPlane, RejectsImpossibleBodies) {
  EXPECT_THROW(test::makeModel("ellipsoid_on_plane", {{"b1", -1}}), InputError);
  EXPECT_THROW(test::makeModel("ellipsoid_on_plane", {{"a3", -0.5}}), InputError); // centre of mass outside
  EXPECT_THROW(test::makeModel("ellipsoid_on_plane", {{"B11", 1}, {"B12", 2}, {"B22", 1}}), InputError);
  EXPECT_THROW(test::makeModel("paraboloid_on_plane", {{"p", 0}}), InputError);
  EXPECT_THROW(test::makeModel("paraboloid_on_plane", {{"I1", 1}, {"I2", 1}, {"I3", 3}}), InputError);
}

} // namespace
} // namespace rv
