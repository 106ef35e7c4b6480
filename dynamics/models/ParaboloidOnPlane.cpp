#include "dynamics/models/ParaboloidOnPlane.h"

#include <cmath>

namespace rv {

const ModelInfo& ParaboloidOnPlane::staticInfo() {
  static const ModelInfo info = [] {
    ModelInfo i{
        .id = "paraboloid_on_plane",
        .title = "Elliptic paraboloid rolling on a plane (manual §3.1)",
        .reference =
            "Borisov, Mamaev, Nonholonomic dynamical systems (2002); manual §3.1 with the erratum to (5)",
        .stateNames = body_state::names(),
        .coreDimension = 6,
        .integralNames = {"E", "geometric"},
        .mapCoordinates = {"l", "L/G", "H/G"},
        .section = "g",
    };
    std::vector<ParameterSpec> specs = rigid_body::massParameters(1.0, 1.5, 2.0);
    specs.push_back({.id = "p",
                     .label = "p",
                     .defaultValue = 1.0,
                     .min = 0,
                     .description = "principal radius of curvature at the vertex, axis 1"});
    specs.push_back({.id = "q",
                     .label = "q",
                     .defaultValue = 2.0,
                     .min = 0,
                     .description = "principal radius of curvature at the vertex, axis 2"});
    specs.push_back({.id = "h",
                     .label = "h",
                     .defaultValue = 0.5,
                     .description = "height of the centre of mass above the vertex, on the axis"});
    specs.push_back({.id = "delta",
                     .label = "delta",
                     .defaultValue = 0.2,
                     .unit = "rad",
                     .description = "angle of the dynamical axes from the geometric ones about the axis"});
    for (auto& s : rigid_body::fieldParameters())
      specs.push_back(s);
    i.parameters = ParameterTable(specs);
    return i;
  }();
  return info;
}

namespace {
RigidBodyConstants paraboloidConstants(const ParameterValues& p) {
  const Eigen::Vector3d I = rigid_body::principalMoments(p);
  const double c = std::cos(p["delta"]), s = std::sin(p["delta"]);
  RigidBodyConstants k;
  k.inertia << I[0] * c * c + I[1] * s * s, (I[0] - I[1]) * c * s, 0, (I[0] - I[1]) * c * s,
      I[0] * s * s + I[1] * c * c, 0, 0, 0, I[2]; // (6)
  k.mass = p["m"], k.gravity = p["g"];
  k.field = rigid_body::fieldMatrix(p);
  return k;
}
} // namespace

ParaboloidOnPlane::ParaboloidOnPlane(const ParameterValues& p)
    : RigidBodyOnPlane(staticInfo(), p, paraboloidConstants(p)), surface_{
                                                                     .p = p["p"], .q = p["q"], .h = p["h"]} {
  if (!(surface_.p > 0)) throw InputError("p: the radius of curvature must be positive");
  if (!(surface_.q > 0)) throw InputError("q: the radius of curvature must be positive");
  addRigidBodyObservables();
}

template class ModelWithField<ParaboloidOnPlane, 16, 6>;
template class RigidBodyOnPlane<ParaboloidOnPlane>;

} // namespace rv
