// Balls rolling on an ellipsoid and in a perturbed paraboloid bowl (manual §3.3, §3.4). Checks that do not
// trust the equations under test: an independent Newton-Euler model of the ball (reaction solved from the
// rolling constraint, the normal's rate by differentiating the surface numerically), the erratum to (22), the
// integrals (14), (20) with its erratum, (24) + gravity term, the measures (17), (23), and the completion of
// map points.
#include "dynamics/core/Errors.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/kinematics/AndoyerDeprit.h"
#include "dynamics/models/BallOnEllipsoid.h"
#include "dynamics/models/BallOnParaboloid.h"
#include "tests/dynamics/TestSupport.h"

#include <cmath>
#include <gtest/gtest.h>

namespace rv {
namespace {

struct BallData {
  double mu, D, R;
};

// Newton-Euler in the fixed frame: m v' = N + F, mu w' = (-R n) x N, v = R w x n  =>  M' = d/dt (mu w + D n x
// (w x n))
Eigen::Vector3d newtonEulerMomentumRate(const BallData& b, const Eigen::Vector3d& M, const Eigen::Vector3d& n,
                                        const Eigen::Vector3d& dn, const Eigen::Vector3d& F) {
  const Eigen::Vector3d w = (M + (b.D / b.mu) * n.dot(M) * n) / (b.mu + b.D);
  const Eigen::Matrix3d A = (b.mu + b.D) * Eigen::Matrix3d::Identity() - b.D * n * n.transpose();
  const Eigen::Vector3d dw = A.lu().solve(Eigen::Vector3d(-b.D * n.cross(w.cross(dn)) + b.R * n.cross(F)));
  return (b.mu + b.D) * dw - b.D * dn * n.dot(w) - b.D * n * (dn.dot(w) + n.dot(dw));
}

TEST(BallOnEllipsoid, EquationsSixteenAgreeWithNewtonEuler) {
  const auto m = test::makeModel("ball_on_ellipsoid", {{"k", 0.4}, {"c1", 0.01}, {"c2", 0.02}, {"c3", 0.03}});
  const auto& ball = static_cast<const BallOnEllipsoid&>(*m);
  const BallData b{m->parameters()["mu"], m->parameters()["D"], m->parameters()["R"]};
  const Eigen::Vector3d semi(1.5, 1.1, 0.8);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 20; ++i) {
    const Eigen::VectorXd s = m->stateFromNamed({{"M1", u(rng)},
                                                 {"M2", u(rng)},
                                                 {"M3", u(rng)},
                                                 {"gamma1", u(rng)},
                                                 {"gamma2", u(rng)},
                                                 {"gamma3", 0.5 + u(rng)}},
                                                "t");
    Eigen::VectorXd ds(12);
    m->rhs(s.data(), ds.data());
    const Eigen::Vector3d M = s.head<3>(), g = s.segment<3>(3);
    const Eigen::Vector3d x = ball.centre(g);
    EXPECT_NEAR((x.array() / semi.array()).matrix().squaredNorm(), 1.0, 1e-14)
        << "the centre is on its ellipsoid";
    // the normal of the centre's ellipsoid, differentiated numerically along the rolling velocity R w x n
    const auto normal = [&](const Eigen::Vector3d& y) {
      return Eigen::Vector3d((y.array() / (semi.array() * semi.array())).matrix().normalized());
    };
    EXPECT_NEAR((normal(x) - g).norm(), 0, 1e-14);
    const Eigen::Vector3d w = (M + (b.D / b.mu) * g.dot(M) * g) / (b.mu + b.D), dx = b.R * w.cross(g);
    const double h = 1e-6;
    const Eigen::Vector3d dn = (normal(x + h * dx) - normal(x - h * dx)) / (2 * h);
    EXPECT_LT((ds.segment<3>(3) - dn).norm(), 1e-8) << "gamma' of (16)";
    // field (19): U = k |x|^2 / 2 + sum c_i / x_i^2, F = -grad U
    Eigen::Vector3d F = -0.4 * x;
    const double c[3] = {0.01, 0.02, 0.03};
    for (int k = 0; k < 3; ++k)
      F[k] += 2 * c[k] / std::pow(x[k], 3);
    EXPECT_LT((ds.head<3>() - newtonEulerMomentumRate(b, M, g, dn, F)).norm(), 1e-7) << "M'";
  }
}

TEST(BallOnParaboloid, EquationsAgreeWithNewtonEulerAndTheErratumToTwentyTwo) {
  const auto m = test::makeModel("ball_on_paraboloid",
                                 {{"Lambda1", 0.3}, {"Lambda2", -0.2}, {"Lambda3", 0.1}, {"Lambda4", 0.25}});
  const auto flat = test::makeModel("ball_on_paraboloid", {});
  const BallData b{m->parameters()["mu"], m->parameters()["D"], m->parameters()["R"]};
  const double mg = m->parameters()["m"] * m->parameters()["g"], p = 1.0, q = 2.0;
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 20; ++i) {
    for (const Model* model : {m.get(), flat.get()}) {
      const auto& ball = static_cast<const BallOnParaboloid&>(*model);
      const Eigen::VectorXd s = model->stateFromNamed({{"omega1", u(rng)},
                                                       {"omega2", u(rng)},
                                                       {"omega3", u(rng)},
                                                       {"x1", 0.4 * u(rng)},
                                                       {"x2", 0.4 * u(rng)}},
                                                      "t");
      Eigen::VectorXd ds(11);
      model->rhs(s.data(), ds.data());
      const Eigen::Vector3d M = s.head<3>(), n = ball.normalAt(s[3], s[4]);
      // the rolling velocity of the centre lies in the tangent plane and moves (u, v)
      const Eigen::Vector3d w = (M + (b.D / b.mu) * n.dot(M) * n) / (b.mu + b.D), dx = b.R * w.cross(n);
      EXPECT_NEAR(ds[3], dx[0], 1e-15);
      EXPECT_NEAR(ds[4], dx[1], 1e-15);
      const double h = 1e-6;
      const Eigen::Vector3d dn = (ball.normalAt(s[3] + h * dx[0], s[4] + h * dx[1]) -
                                  ball.normalAt(s[3] - h * dx[0], s[4] - h * dx[1])) /
                                 (2 * h);
      EXPECT_LT((ds.head<3>() - newtonEulerMomentumRate(b, M, n, dn, Eigen::Vector3d(0, 0, -mg))).norm(),
                1e-7);
      if (model == flat.get()) {
        // design.md erratum to (22): gamma' = -R g3 / (mu + D) g x (g x B'(g x M)), B' = diag(1/b1, 1/b2, 0)
        const Eigen::Vector3d Bp(1 / p, 1 / q, 0);
        const Eigen::Vector3d erratum =
            -b.R * n[2] / (b.mu + b.D) * n.cross(n.cross(Bp.cwiseProduct(n.cross(M))));
        EXPECT_LT((dn - erratum).norm(), 1e-8);
        EXPECT_GT((dn + erratum).norm(), 1e-3) << "the printed sign is the other one (when the ball moves)";
      }
    }
  }
}

TEST(BallOnSurfaces, EverhartConservesTheirIntegralsOverAThousand) {
  const auto check = [](const Model& m, const Eigen::VectorXd& s0, double h, std::vector<int> which) {
    const Eigen::VectorXd I0 = m.integrals(s0.data());
    Everhart e(h, 15, 12);
    e.start(m, 0, s0);
    Eigen::VectorXd worst = Eigen::VectorXd::Zero(I0.size());
    while (e.time() < 1000 - 1e-9) {
      e.step();
      const Eigen::VectorXd I = m.integrals(e.state().data());
      for (int k : which)
        worst[k] = std::max(worst[k], std::abs(I[k] - I0[k]) / std::abs(I0[k]));
    }
    for (int k : which)
      EXPECT_LE(worst[k], test::tol(1e-12)) << m.info().id << " " << m.info().integralNames[k];
  };
  const std::map<std::string, double> start{{"M1", 0.3},     {"M2", 0.8},      {"M3", 0.2},
                                            {"gamma1", 0.3}, {"gamma2", -0.2}, {"gamma3", 0.9}};
  for (const auto& m :
       {test::makeModel("ball_on_ellipsoid", {}),
        test::makeModel("ball_on_ellipsoid", {{"k", 0.5}, {"c1", 0.01}, {"c2", 0.02}, {"c3", 0.005}})})
    check(*m, m->stateFromNamed(start, "t"), 0.02, {0, 1, 2});
  const auto bowl = test::makeModel("ball_on_paraboloid", {});
  check(*bowl, bowl->stateFromMap({0.2, 0.1, 0.3}, {}, "t"), 0.05, {0, 1});
  const auto bumpy = test::makeModel("ball_on_paraboloid", {{"Lambda1", 0.1}, {"Lambda3", 0.05}});
  check(*bumpy, bumpy->stateFromMap({0.2, 0.1, 0.3}, {}, "t"), 0.05, {0});
}

// A ball on the top of the ellipsoid (gamma along an axis, the centre on two coordinate planes) with no
// barrier c_i / x_i^2: the field, the energy and K are finite (the barrier's term vanishes with c_i, not 0 /
// 0), and a ball at rest there stays at rest; turning about the normal, it spins in place
TEST(BallOnEllipsoid, OnTopOfTheEllipsoidWithoutABarrierItsFieldIsFinite) {
  for (const auto& m : {test::makeModel("ball_on_ellipsoid", {}),
                        test::makeModel("ball_on_ellipsoid", {{"k", 0.3}, {"c1", 0.01}})}) {
    const std::map<std::string, double> top{{"M1", 0},     {"M2", 0},     {"M3", 0.25},
                                            {"gamma1", 0}, {"gamma2", 0}, {"gamma3", 1}};
    const Eigen::VectorXd s = m->stateFromNamed(top, "t");
    Eigen::VectorXd ds(s.size());
    m->rhs(s.data(), ds.data());
    const bool barrier1 = m->parameters()["c1"] != 0;
    for (int i = 0; i < 6; ++i) {
      if (barrier1 && i < 3) continue; // c1 / x1^2 is infinite at x1 = 0: the model says so, as it should
      EXPECT_TRUE(std::isfinite(ds[i])) << i;
      EXPECT_EQ(ds[i], 0.0) << i; // spinning about the normal at the top: M and gamma stay
    }
    if (!barrier1) {
      const Eigen::VectorXd I = m->integrals(s.data());
      EXPECT_TRUE(I.allFinite()) << I.transpose();
    }
  }
}

TEST(BallOnSurfaces, MapPointsAreCompletedOnTheirIntegrals) {
  const auto m = test::makeModel("ball_on_ellipsoid", {{"energy", 0.5}, {"integral", 0.2}});
  const Eigen::VectorXd s = m->stateFromMap({0.5, 0.3}, {.sectionValue = 0.2}, "t");
  const Eigen::VectorXd I = m->integrals(s.data());
  EXPECT_NEAR(I[0], 0.5, 1e-12);
  EXPECT_NEAR(I[2], 0.2, 1e-10);
  const AndoyerDeprit ad = toAndoyerDeprit(s.head<3>(), s.segment<3>(3));
  EXPECT_NEAR(ad.l, 0.5, 1e-12);
  EXPECT_NEAR(ad.L / ad.G, 0.3, 1e-12);
  EXPECT_NEAR(ad.g, 0.2, 1e-12);
  EXPECT_THROW(test::makeModel("ball_on_ellipsoid", {{"energy", 0.5}, {"integral", 50}})
                   ->stateFromMap({0.5, 0.3}, {}, "t"),
               InputError);

  const auto bowl = test::makeModel("ball_on_paraboloid", {{"energy", 0.05}});
  for (int root : {1, 2}) {
    const Eigen::VectorXd b = bowl->stateFromMap({0.2, 0.1, 0.3}, {.sectionValue = -0.05, .root = root}, "t");
    EXPECT_NEAR(bowl->integrals(b.data())[0], 0.05, 1e-14);
    EXPECT_EQ(b[3], 0.2);
    EXPECT_EQ(b[4], -0.05);
    EXPECT_NEAR(bowl->observables()[bowl->findObservable("omega1")].value(0, b.data()), 0.1, 1e-14);
  }
  EXPECT_THROW(bowl->stateFromMap({0.9, 1.0, 1.0}, {}, "t"), InputError);
}

TEST(BallOnSurfaces, RejectBallsThatCannotRollThere) {
  EXPECT_THROW(test::makeModel("ball_on_ellipsoid", {{"R", 2.0}}), InputError);
  EXPECT_THROW(test::makeModel("ball_on_ellipsoid", {{"b2", 0}}), InputError);
  EXPECT_THROW(test::makeModel("ball_on_paraboloid", {{"R", 1.5}}), InputError);
  EXPECT_THROW(test::makeModel("ball_on_paraboloid", {{"mu", 0}}), InputError);
}

} // namespace
} // namespace rv
