// ParaboloidOnPlane.h -- an elliptic paraboloid rolling on a plane: manual §3.1, equations (2), integrals
// (3), surface and Gauss map (5) with the erratum r3 = -h + (p g1^2 + q g2^2) / (2 g3^2), inertia rotated by
// delta (6).
#pragma once
#include "dynamics/models/RigidBodyOnPlane.h"

namespace rv {

class ParaboloidOnPlane final : public RigidBodyOnPlane<ParaboloidOnPlane> {
public:
  explicit ParaboloidOnPlane(const ParameterValues& params);
  static const ModelInfo& staticInfo();

  /// (5): the contact point of the surface whose outer normal is -gamma (needs gamma3 > 0).
  template <class S> V3<S> contact(const V3<S>& g) const {
    return V3<S>(-p_ * g[0] / g[2], -q_ * g[1] / g[2],
                 -h_ + (p_ * g[0] * g[0] + q_ * g[1] * g[1]) / (2 * g[2] * g[2]));
  }
  template <class S> V3<S> contactRate(const V3<S>& g, const V3<S>& dg) const {
    const S& g3 = g[2];
    const S g32 = g3 * g3;
    return V3<S>(-p_ * (dg[0] * g3 - g[0] * dg[2]) / g32, -q_ * (dg[1] * g3 - g[1] * dg[2]) / g32,
                 (p_ * g[0] * dg[0] + q_ * g[1] * dg[1]) / g32 -
                     (p_ * g[0] * g[0] + q_ * g[1] * g[1]) * dg[2] / (g32 * g3));
  }
  /// The paraboloid touches the plane only while its axis points up (gamma3 > 0).
  bool touches(const Eigen::Vector3d& g) const { return g[2] > 1e-6; }
  std::optional<BodyGeometry> geometry() const override {
    return BodyGeometry{.shape = BodyShape::Paraboloid,
                        .centre = Eigen::Vector3d(0, 0, -h_),
                        .p = p_,
                        .q = q_,
                        .height = 1.5 * std::max(std::max(p_, q_), h_)};
  }

  double p() const { return p_; }
  double q() const { return q_; }
  double h() const { return h_; }

private:
  double p_, q_, h_;
};

} // namespace rv
