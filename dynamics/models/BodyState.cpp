#include "dynamics/models/BodyState.h"

#include "dynamics/core/Errors.h"
#include "dynamics/kinematics/AndoyerDeprit.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rv::body_state {

std::vector<std::string> names() {
  return {"M1",     "M2",    "M3",    "gamma1", "gamma2", "gamma3", "alpha1",  "alpha2",
          "alpha3", "beta1", "beta2", "beta3",  "x",      "y",      "s_plane", "s_body"};
}

Eigen::VectorXd fromMomentumAndVertical(const Eigen::Vector3d& M, const Eigen::Vector3d& gamma) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(kSize);
  const Eigen::Vector3d g = gamma.normalized();
  // alpha: the body image of the fixed x-axis, any unit vector orthogonal to gamma; beta = gamma x alpha
  const Eigen::Vector3d seed = std::abs(g[0]) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d a = (seed - seed.dot(g) * g).normalized(), b = g.cross(a);
  x << M, g, a, b, 0, 0, 0, 0;
  return x;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> momentumAndVertical(const std::map<std::string, double>& named,
                                                                const std::string& context) {
  for (const char* n : {"M1", "M2", "M3", "gamma1", "gamma2", "gamma3"})
    if (!named.count(n)) throw InputError(context + ": missing state component '" + n + "'");
  const Eigen::Vector3d g(named.at("gamma1"), named.at("gamma2"), named.at("gamma3"));
  if (!(g.norm() > 1e-12)) throw InputError(context + ".gamma1: gamma must not be zero");
  return {Eigen::Vector3d(named.at("M1"), named.at("M2"), named.at("M3")), g};
}

Eigen::Matrix3d rotation(const double* x) {
  Eigen::Matrix3d Q;
  Q.row(0) = Eigen::Vector3d(x[kAlpha], x[kAlpha + 1], x[kAlpha + 2]).transpose();
  Q.row(1) = Eigen::Vector3d(x[kBeta], x[kBeta + 1], x[kBeta + 2]).transpose();
  Q.row(2) = Eigen::Vector3d(x[kGamma], x[kGamma + 1], x[kGamma + 2]).transpose();
  return Q;
}

std::vector<Observable> kinematicObservables(const VectorOf& omega, const VectorOf& momentum,
                                             const VectorOf& velocity) {
  std::vector<Observable> obs;
  const auto add = [&](std::string id, std::string what, std::function<double(double, const double*)> f) {
    obs.push_back({std::move(id), std::move(what), std::move(f)});
  };
  for (int i = 0; i < 3; ++i)
    add("omega" + std::to_string(i + 1), "angular velocity, body axis " + std::to_string(i + 1),
        [omega, i](double, const double* x) { return omega(x)[i]; });
  add("omega_vertical", "spin about the vertical, omega . gamma (a rattleback's reversal changes its sign)",
      [omega](double, const double* x) {
        return omega(x).dot(Eigen::Vector3d(x[kGamma], x[kGamma + 1], x[kGamma + 2]));
      });
  const auto ad = [momentum](const double* x) {
    return toAndoyerDeprit(momentum(x), Eigen::Vector3d(x[kGamma], x[kGamma + 1], x[kGamma + 2]));
  };
  add("G", "Andoyer-Deprit G", [ad](double, const double* x) { return ad(x).G; });
  add("L", "Andoyer-Deprit L", [ad](double, const double* x) { return ad(x).L; });
  add("l", "Andoyer-Deprit l", [ad](double, const double* x) { return ad(x).l; });
  obs.back().angle = true;
  add("g", "Andoyer-Deprit g", [ad](double, const double* x) { return ad(x).g; });
  obs.back().angle = true;
  add("L/G", "Andoyer-Deprit L/G", [ad](double, const double* x) { return ad(x).L / ad(x).G; });
  add("H/G", "Andoyer-Deprit H/G", [ad](double, const double* x) { return ad(x).H / ad(x).G; });
  // Euler angles: gamma = (sin th sin ph, sin th cos ph, cos th), alpha3 = sin ps sin th, beta3 = -cos ps sin
  // th
  const auto mod2pi = [](double a) { return std::fmod(a + 2 * std::numbers::pi, 2 * std::numbers::pi); };
  add("theta", "Euler angle theta (nutation)",
      [](double, const double* x) { return std::acos(std::clamp(x[kGamma + 2], -1.0, 1.0)); });
  add("phi", "Euler angle phi (proper rotation), mod 2 pi",
      [mod2pi](double, const double* x) { return mod2pi(std::atan2(x[kGamma], x[kGamma + 1])); });
  obs.back().angle = true;
  add("psi", "Euler angle psi (precession), mod 2 pi",
      [mod2pi](double, const double* x) { return mod2pi(std::atan2(x[kAlpha + 2], -x[kBeta + 2])); });
  obs.back().angle = true;
  add("RabsX", "centre of mass on the fixed plane, x", [](double, const double* x) { return x[kX]; });
  add("RabsY", "centre of mass on the fixed plane, y", [](double, const double* x) { return x[kY]; });
  add("Vx", "velocity of the centre of mass, x",
      [velocity](double, const double* x) { return rotation(x).row(0).dot(velocity(x)); });
  add("Vy", "velocity of the centre of mass, y",
      [velocity](double, const double* x) { return rotation(x).row(1).dot(velocity(x)); });
  add("Lplane", "length of the contact point's trace on the plane",
      [](double, const double* x) { return x[kTracePlane]; });
  add("Lbody", "length of the contact point's trace on the body",
      [](double, const double* x) { return x[kTraceBody]; });
  add("Ldiff", "Lplane - Lbody", [](double, const double* x) { return x[kTracePlane] - x[kTraceBody]; });
  return obs;
}

} // namespace rv::body_state
