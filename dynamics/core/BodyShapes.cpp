#include "dynamics/core/BodyShapes.h"

#include <cmath>
#include <numbers>

namespace rv {

Eigen::Vector3d shapePoint(const BodyGeometry& g, double u, double v) {
  constexpr double pi = std::numbers::pi;
  const double lon = 2 * pi * u;
  if (g.shape == BodyShape::Ball || g.shape == BodyShape::Ellipsoid) {
    const double lat = pi * (v - 0.5);
    return g.centre + Eigen::Vector3d(g.semiAxes[0] * std::cos(lat) * std::cos(lon),
                                      g.semiAxes[1] * std::cos(lat) * std::sin(lon),
                                      g.semiAxes[2] * std::sin(lat));
  }
  if (g.shape == BodyShape::Paraboloid) {     // r3 = vertex + (r1^2 / p + r2^2 / q) / 2, up to `height`
    const double s = v * std::sqrt(g.height); // s^2 = height above the vertex
    return g.centre + Eigen::Vector3d(std::sqrt(2 * g.p) * s * std::cos(lon),
                                      std::sqrt(2 * g.q) * s * std::sin(lon), s * s);
  }
  return Eigen::Vector3d::Zero();
}

Eigen::Vector3d shapeNormal(const BodyGeometry& g, const Eigen::Vector3d& x) {
  const Eigen::Vector3d r = x - g.centre;
  Eigen::Vector3d n = Eigen::Vector3d::UnitZ();
  if (g.shape == BodyShape::Ball || g.shape == BodyShape::Ellipsoid)
    n = r.cwiseQuotient(g.semiAxes.cwiseProduct(g.semiAxes)); // the gradient of sum (r_i / a_i)^2
  else if (g.shape == BodyShape::Paraboloid)
    n = Eigen::Vector3d(-r[0] / g.p, -r[1] / g.q, 1); // -grad of (r1^2 / p + r2^2 / q) / 2 - r3
  const double norm = n.norm();
  return norm > 0 ? Eigen::Vector3d(n / norm) : Eigen::Vector3d::UnitZ();
}

} // namespace rv
