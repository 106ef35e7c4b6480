#include "dynamics/models/EllipsoidOnPlane.h"

#include <cmath>

namespace rv {

const ModelInfo& EllipsoidOnPlane::staticInfo() {
  static const ModelInfo info = [] {
    ModelInfo i{
        .id = "ellipsoid_on_plane",
        .title = "Triaxial ellipsoid rolling on a plane: the rattleback (manual §3.2)",
        .reference = "Borisov, Mamaev, Strange attractors in rattleback dynamics, Physics-Uspekhi 46 (2003); "
                     "manual §3.2 with the erratum to (8)",
        .stateNames = body_state::names(),
        .coreDimension = 6,
        .integralNames = {"E", "geometric"},
        .mapCoordinates = {"l", "L/G", "H/G"},
        .section = "g",
    };
    // a solid-looking rattleback: long and flat, centre of mass below the centre, axes turned by psi
    std::vector<ParameterSpec> specs = rigid_body::massParameters(0.082, 0.832, 0.85);
    const char* axis[3] = {"1", "2", "3"};
    const double b[3] = {2.0, 0.5, 0.4};
    for (int k = 0; k < 3; ++k)
      specs.push_back({.id = std::string("b") + axis[k],
                       .label = std::string("b") + axis[k],
                       .defaultValue = b[k],
                       .min = 0,
                       .description = std::string("semi-axis of the ellipsoid, body axis ") + axis[k]});
    const double a[3] = {0, 0, -0.1};
    for (int k = 0; k < 3; ++k)
      specs.push_back(
          {.id = std::string("a") + axis[k],
           .label = std::string("a") + axis[k],
           .defaultValue = a[k],
           .description =
               std::string("centre of mass offset from the geometric centre (the centre lies at -a), axis ") +
               axis[k]});
    specs.push_back({.id = "phi",
                     .label = "Phi",
                     .defaultValue = 0,
                     .unit = "rad",
                     .description = "Euler angle of the dynamical axes (9)"});
    specs.push_back({.id = "theta",
                     .label = "Theta",
                     .defaultValue = 0,
                     .unit = "rad",
                     .description = "Euler angle of the dynamical axes (9)"});
    specs.push_back({.id = "psi",
                     .label = "Psi",
                     .defaultValue = 0.1,
                     .unit = "rad",
                     .description = "Euler angle of the dynamical axes (9)"});
    for (auto& s : rigid_body::fieldParameters())
      specs.push_back(s);
    i.parameters = ParameterTable(specs);
    return i;
  }();
  return info;
}

Eigen::Matrix3d EllipsoidOnPlane::eulerRotation(double phi, double theta, double psi) {
  const double cf = std::cos(phi), sf = std::sin(phi), ct = std::cos(theta), st = std::sin(theta);
  const double cp = std::cos(psi), sp = std::sin(psi);
  Eigen::Matrix3d Q;
  Q << cf * cp - ct * sp * sf, cf * sp + ct * cp * sf, sf * st,  //
      -sf * cp - ct * sp * cf, -sf * sp + ct * cp * cf, cf * st, //
      st * sp, -st * cp, ct;
  return Q;
}

namespace {
RigidBodyConstants ellipsoidConstants(const ParameterValues& p) {
  const Eigen::Vector3d I = rigid_body::principalMoments(p);
  for (const char* b : {"b1", "b2", "b3"})
    if (!(p[b] > 0)) throw InputError(std::string(b) + ": a semi-axis must be positive");
  const Eigen::Matrix3d Q = EllipsoidOnPlane::eulerRotation(p["phi"], p["theta"], p["psi"]);
  RigidBodyConstants k;
  k.inertia = Q.transpose() * I.asDiagonal() * Q;
  k.mass = p["m"], k.gravity = p["g"];
  k.field = rigid_body::fieldMatrix(p);
  return k;
}
} // namespace

EllipsoidOnPlane::EllipsoidOnPlane(const ParameterValues& p)
    : RigidBodyOnPlane(staticInfo(), p, ellipsoidConstants(p)), surface_{.b2 = {p["b1"] * p["b1"],
                                                                                p["b2"] * p["b2"],
                                                                                p["b3"] * p["b3"]},
                                                                         .a = {p["a1"], p["a2"], p["a3"]}} {
  if (!((geometricCentre().array() / semiAxes().array()).matrix().norm() < 1))
    throw InputError("a1..a3: the centre of mass must lie inside the ellipsoid");
  addRigidBodyObservables();
}

template class ModelWithField<EllipsoidOnPlane, 16, 6>;
template class RigidBodyOnPlane<EllipsoidOnPlane>;

} // namespace rv
