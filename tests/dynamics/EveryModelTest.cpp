// Properties every registered model must have: a default scene that loads, an exact Jacobian that agrees with
// finite differences at the scene's initial state, observables that evaluate, and for flows with an invariant
// measure a zero divergence of rho f there.
#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/integrators/Taylor.h"
#include "dynamics/tools/TangentSystem.h"
#include "tests/dynamics/TestSupport.h"

#include <filesystem>
#include <gtest/gtest.h>

namespace rv {
namespace {

class EveryModel : public ::testing::TestWithParam<std::string> {};

// a generic state near the model's scale
Eigen::VectorXd genericState(const Model& m) {
  const int n = m.dimension();
  Eigen::VectorXd x = Eigen::VectorXd::Constant(n, 0.3);
  for (int i = 0; i < n; ++i)
    x[i] += 0.07 * i;
  if (m.info().stateNames.size() >= 6 && m.info().stateNames[3] == "gamma1")
    x = m.stateFromNamed(
        {{"M1", 0.2}, {"M2", -0.3}, {"M3", 0.4}, {"gamma1", 0.1}, {"gamma2", 0.2}, {"gamma3", 1}}, "t");
  if (m.info().id == "ball_on_paraboloid")
    x = m.stateFromNamed({{"M1", 0.02}, {"M2", -0.03}, {"M3", 0.04}, {"x1", 0.2}, {"x2", -0.1}}, "t");
  return x;
}

TEST_P(EveryModel, JacobianMatchesFiniteDifferencesAndObservablesEvaluate) {
  const auto& entry = ModelRegistry::global().get(GetParam());
  const auto m = entry.create(ParameterValues(entry.info->parameters));
  const int n = m->dimension();
  const Eigen::VectorXd x = genericState(*m);
  std::vector<double> J(n * n);
  m->jacobian(x.data(), J.data());
  Eigen::VectorXd xp, xm, fp(n), fm(n);
  const double h = 1e-6;
  for (int j = 0; j < n; ++j) {
    xp = x, xm = x;
    xp[j] += h, xm[j] -= h;
    m->rhs(xp.data(), fp.data());
    m->rhs(xm.data(), fm.data());
    for (int i = 0; i < n; ++i)
      EXPECT_NEAR(J[i * n + j], (fp[i] - fm[i]) / (2 * h), 1e-6 * std::max(1.0, std::abs(J[i * n + j])))
          << GetParam() << " d" << i << "/d" << j;
  }
  // the directional derivatives of the variational equations: f and J_core V in one pass
  const int c = m->info().coreDimension;
  std::vector<double> Jc(c * c), f(n);
  m->coreJacobian(x.data(), Jc.data());
  m->rhs(x.data(), f.data());
  for (int k : {1, 2, c}) {
    std::vector<double> V(k * c), dx(n), dV(k * c);
    for (int i = 0; i < k * c; ++i)
      V[i] = std::sin(1.3 * i + 0.4);
    m->tangentRhs(x.data(), V.data(), k, dx.data(), dV.data());
    for (int i = 0; i < n; ++i)
      EXPECT_NEAR(dx[i], f[i], 1e-14 * std::max(1.0, std::abs(f[i]))) << GetParam();
    for (int col = 0; col < k; ++col)
      for (int i = 0; i < c; ++i) {
        double jv = 0;
        for (int l = 0; l < c; ++l)
          jv += Jc[i * c + l] * V[col * c + l];
        EXPECT_NEAR(dV[col * c + i], jv, 1e-12 * std::max(1.0, std::abs(jv))) << GetParam() << " k = " << k;
      }
  }
  for (const auto& o : m->observables())
    EXPECT_TRUE(std::isfinite(o.value(0.0, x.data()))) << GetParam() << " " << o.id;
  if (m->hasInvariantMeasure()) {
    EXPECT_NEAR(test::divergenceOfDensityFlow(*m, x), 0, 1e-7) << GetParam();
  }
}

// The Taylor method expands every flow from its one templated field, with no code of its own: its steps agree
// with small Everhart steps of another formulation (interpolation polynomials of the right-hand side),
// including inside a step (the series as dense output), and a step back returns to the start.
TEST_P(EveryModel, TaylorExpandsTheFieldWithNoCodeOfItsOwn) {
  const auto& entry = ModelRegistry::global().get(GetParam());
  const auto m = entry.create(ParameterValues(entry.info->parameters));
  Taylor taylor(1e-15, 0);
  if (m->isMap()) {
    EXPECT_THROW(taylor.start(*m, 0, genericState(*m)), InputError);
    return;
  }
  const Eigen::VectorXd x0 = genericState(*m);
  // backward in time Lorenz expands volumes by e^(41/3) per unit time: a short run keeps the return exact
  const double T = GetParam() == "lorenz" ? 0.5 : 3.0;
  taylor.start(*m, 0, x0);
  Everhart reference(T / 600, 15, 20);
  reference.start(*m, 0, x0);
  Eigen::VectorXd expected(x0.size()), dense(x0.size());
  int steps = 0;
  while (taylor.time() < T) {
    taylor.step(), ++steps;
    const double mid = 0.5 * (taylor.previousTime() + taylor.time());
    while (reference.time() < mid)
      reference.step();
    reference.interpolate(mid, expected);
    taylor.interpolate(mid, dense);
    const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
    EXPECT_LT((dense - expected).cwiseAbs().maxCoeff(), 1e-11 * scale)
        << GetParam() << " inside step " << steps;
    while (reference.time() < taylor.time())
      reference.step();
    reference.interpolate(taylor.time(), expected);
    ASSERT_LT((taylor.state() - expected).cwiseAbs().maxCoeff(), 1e-11 * scale)
        << GetParam() << " step " << steps;
  }
  EXPECT_LT(steps, 200) << GetParam(); // long steps, not the reference's 600
  Taylor back(1e-15, 0);
  back.start(*m, taylor.time(), taylor.state(), -1);
  while (back.time() > 1e-12)
    back.step();
  back.interpolate(0, dense);
  EXPECT_LT((dense - x0).cwiseAbs().maxCoeff(), 1e-10 * std::max(1.0, x0.cwiseAbs().maxCoeff()))
      << GetParam();
}

// Lyapunov spectra with rk4 take the fused path (the tangent equations compiled into the steps): it must take
// the very steps the rk4 integrator takes on the variational system, for every number of vectors.
TEST_P(EveryModel, FusedTangentStepsAreTheRk4IntegratorsSteps) {
  const auto& entry = ModelRegistry::global().get(GetParam());
  const auto m = entry.create(ParameterValues(entry.info->parameters));
  const int c = m->info().coreDimension;
  for (int k = 1; k <= c; ++k) {
    TangentSystem tangent(*m, k);
    Eigen::VectorXd state(tangent.dimension());
    state.head(m->dimension()) = genericState(*m);
    for (Eigen::Index i = m->dimension(); i < state.size(); ++i)
      state[i] = std::sin(1.3 * static_cast<double>(i) + 0.4);
    Eigen::VectorXd fused = state;
    const bool hasPath = tangent.rk4Steps(fused, 0.01, 25);
    if (m->isMap()) { // a map has no flow to step
      EXPECT_FALSE(hasPath) << GetParam();
      EXPECT_EQ(fused, state) << GetParam();
      return;
    }
    ASSERT_TRUE(hasPath) << GetParam() << " k = " << k;
    Rk4 rk4(0.01);
    rk4.start(tangent, 0, state);
    for (int s = 0; s < 25; ++s)
      rk4.step();
    const double scale = std::max(1.0, rk4.state().cwiseAbs().maxCoeff());
    EXPECT_LT((fused - rk4.state()).cwiseAbs().maxCoeff(), 1e-14 * scale) << GetParam() << " k = " << k;
    EXPECT_GT((fused - state).cwiseAbs().maxCoeff(), 1e-6) << GetParam(); // it moved
  }
  EXPECT_FALSE(TangentSystem(*m, 1).base().tangentRk4(nullptr, nullptr, c + 1, 0.01, 0)) << "k > core";
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryModel,
                         ::testing::Values("paraboloid_on_plane", "ellipsoid_on_plane", "ball_on_ellipsoid",
                                           "ball_on_paraboloid", "chaplygin_ball", "lorenz", "henon_heiles",
                                           "henon_map", "standard_map"));

TEST(EveryModel, TheListAboveIsTheRegistry) {
  std::vector<std::string> ids;
  for (const auto& e : ModelRegistry::global().entries())
    ids.push_back(e.info->id);
  EXPECT_EQ(ids, (std::vector<std::string>{"paraboloid_on_plane", "ellipsoid_on_plane", "ball_on_ellipsoid",
                                           "ball_on_paraboloid", "chaplygin_ball", "lorenz", "henon_heiles",
                                           "henon_map", "standard_map"}));
}

} // namespace
} // namespace rv
