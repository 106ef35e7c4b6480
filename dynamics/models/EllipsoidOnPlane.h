// EllipsoidOnPlane.h -- a triaxial ellipsoid with an offset centre of mass and rotated principal axes rolling
// on a plane (the rattleback family): manual §3.2, equations (2), integrals (3), Gauss map (8) with the
// erratum r = -B^2 gamma / sqrt(gamma, B^2 gamma) - a, B = diag(b1, b2, b3); inertia Q^T diag(I) Q with Q of
// (9).
#pragma once
#include "dynamics/models/RigidBodyOnPlane.h"

namespace rv {

class EllipsoidOnPlane final : public RigidBodyOnPlane<EllipsoidOnPlane> {
public:
  explicit EllipsoidOnPlane(const ParameterValues& params);
  static const ModelInfo& staticInfo();

  template <class S> V3<S> contact(const V3<S>& g) const {
    using std::sqrt;
    const V3<S> b2g = b2_.cast<S>().cwiseProduct(g);
    return -b2g / sqrt(g.dot(b2g)) - a_.cast<S>();
  }
  template <class S> V3<S> contactRate(const V3<S>& g, const V3<S>& dg) const {
    using std::sqrt;
    const V3<S> b2g = b2_.cast<S>().cwiseProduct(g);
    const S s2 = g.dot(b2g), s = sqrt(s2);
    return -b2_.cast<S>().cwiseProduct(dg) / s + b2g * (b2g.dot(dg) / (s2 * s));
  }
  bool touches(const Eigen::Vector3d&) const { return true; }
  std::optional<BodyGeometry> geometry() const override {
    return BodyGeometry{.shape = BodyShape::Ellipsoid, .centre = -a_, .semiAxes = b2_.cwiseSqrt()};
  }

  /// Semi-axes and the geometric centre seen from the centre of mass (-a), for drawing.
  Eigen::Vector3d semiAxes() const { return b2_.cwiseSqrt(); }
  Eigen::Vector3d geometricCentre() const { return -a_; }
  /// (9)
  static Eigen::Matrix3d eulerRotation(double phi, double theta, double psi);

private:
  Eigen::Vector3d b2_, a_;
};

} // namespace rv
