// RigidBodyOnPlane.inl -- the template members of RigidBodyOnPlane that are not the equations.
#pragma once
#include "dynamics/core/Errors.h"
#include "dynamics/kinematics/AndoyerDeprit.h"
#include "dynamics/models/BodyState.h"

#include <cmath>
#include <sstream>

namespace rv {

template <class Derived> void RigidBodyOnPlane<Derived>::addRigidBodyObservables() {
  this->addStandardObservables();
  const auto M = [](const double* x) { return Eigen::Vector3d(x[0], x[1], x[2]); };
  const auto gam = [](const double* x) { return Eigen::Vector3d(x[3], x[4], x[5]); };
  const auto omega = [this, M, gam](const double* x) {
    return angularVelocity<double>(M(x), self().template contact<double>(gam(x)));
  };
  this->addObservables(body_state::kinematicObservables(omega, M, [this, omega, gam](const double* x) {
    return Eigen::Vector3d(-omega(x).cross(self().template contact<double>(gam(x))));
  }));
  this->addObservable(
      "Z", "height of the centre of mass above the plane",
      [this, gam](double, const double* x) { return -self().template contact<double>(gam(x)).dot(gam(x)); });
}

template <class Derived>
Eigen::VectorXd RigidBodyOnPlane<Derived>::stateFrom(const Eigen::Vector3d& M,
                                                     const Eigen::Vector3d& gamma) const {
  return body_state::fromMomentumAndVertical(M, gamma);
}

template <class Derived>
Eigen::VectorXd RigidBodyOnPlane<Derived>::stateFromNamed(const std::map<std::string, double>& named,
                                                          const std::string& context) const {
  const auto [M, g] = body_state::momentumAndVertical(named, context);
  if (!self().touches(g.normalized()))
    throw InputError(context + ": the body cannot touch the plane with this gamma");
  Eigen::VectorXd x = stateFrom(M, g);
  this->assignNamed(named, context, x);
  x.template segment<3>(3).normalize();
  return x;
}

template <class Derived>
Eigen::VectorXd RigidBodyOnPlane<Derived>::stateFromMap(const std::vector<double>& point,
                                                        const MapPointSpec& spec,
                                                        const std::string& context) const {
  if (point.size() != 3)
    throw InputError(context + ": map points of " + this->info().id + " are (l, L/G, H/G)");
  const double l = point[0], LG = point[1], HG = point[2], E = this->params_["energy"];
  if (!(std::abs(LG) <= 1)) throw InputError(context + ": L/G must lie in [-1, 1]");
  if (!(std::abs(HG) <= 1)) throw InputError(context + ": H/G must lie in [-1, 1]");
  // with G = 1 the angles fix gamma and the direction of M; the energy is quadratic in G
  Eigen::Vector3d e, g;
  fromAndoyerDeprit({.L = LG, .G = 1, .H = HG, .l = l, .g = spec.sectionValue}, e, g);
  std::ostringstream where;
  where << context << ": no state at (l, L/G, H/G) = (" << l << ", " << LG << ", " << HG << ") with energy "
        << E;
  if (!self().touches(g))
    throw InputError(where.str() + " (the body cannot touch the plane with that vertical)");
  const double kinetic = E - potential(g);
  const double unit = 0.5 * e.dot(angularVelocity<double>(e, self().template contact<double>(g)));
  if (!(kinetic >= 0))
    throw InputError(where.str() + " (the point lies outside the region of allowed motion)");
  if (spec.root != 1)
    throw InputError(where.str() + " with root " + std::to_string(spec.root) + " (there is 1)");
  return stateFrom(std::sqrt(kinetic / unit) * e, g);
}

} // namespace rv
