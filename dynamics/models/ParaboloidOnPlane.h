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
  static constexpr bool kLaneField = true; ///< no branch on a value: runs on lanes (Lanes.h)

  /// The surface as the equations read it, as T (double, or one value per lane): the radii of curvature p, q
  /// and the height h; its contact point (5) with the erratum and that point's rate along gamma-dot (needs
  /// gamma3 > 0).
  template <class T> struct Surface {
    T p, q, h;
    template <class S> [[gnu::always_inline]] ThreeVector<S> contact(const ThreeVector<S>& g) const {
      const S& g3 = g[2];
      return {{-p * g[0] / g3, -q * g[1] / g3, -h + (p * g[0] * g[0] + q * g[1] * g[1]) / ((g3 + g3) * g3)}};
    }
    template <class S>
    [[gnu::always_inline]] ThreeVector<S> contactRate(const ThreeVector<S>& g,
                                                      const ThreeVector<S>& dg) const {
      const S& g3 = g[2];
      const S g32 = g3 * g3;
      return {{-p * (dg[0] * g3 - g[0] * dg[2]) / g32, -q * (dg[1] * g3 - g[1] * dg[2]) / g32,
               (p * g[0] * dg[0] + q * g[1] * dg[1]) / g32 -
                   (p * g[0] * g[0] + q * g[1] * g[1]) * dg[2] / (g32 * g3)}};
    }
  };
  /// What the field reads (LaneField.h): the body's constants and the surface's.
  template <class T> struct Coefficients {
    RigidBodyCoefficients<T> body;
    Surface<T> surface;
  };
  Coefficients<double> coefficients() const { return {body(), surface_}; }
  const Surface<double>& surface() const { return surface_; }

  template <class S> V3<S> contact(const V3<S>& g) const {
    return surface_.template contact<S>(ThreeVector<S>::from(g)).eigen();
  }
  template <class S> V3<S> contactRate(const V3<S>& g, const V3<S>& dg) const {
    return surface_.template contactRate<S>(ThreeVector<S>::from(g), ThreeVector<S>::from(dg)).eigen();
  }
  /// The paraboloid touches the plane only while its axis points up (gamma3 > 0).
  bool touches(const Eigen::Vector3d& g) const { return g[2] > 1e-6; }
  std::optional<BodyGeometry> geometry() const override {
    return BodyGeometry{.shape = BodyShape::Paraboloid,
                        .centre = Eigen::Vector3d(0, 0, -h()),
                        .p = p(),
                        .q = q(),
                        .height = 1.5 * std::max(std::max(p(), q()), h())};
  }

  double p() const { return surface_.p; }
  double q() const { return surface_.q; }
  double h() const { return surface_.h; }

private:
  Surface<double> surface_;
};

// compiled once, in ParaboloidOnPlane.cpp: constructing the model elsewhere does not compile its kernels
// again (ModelWithField.h)
extern template class ModelWithField<ParaboloidOnPlane, 16, 6>;
extern template class RigidBodyOnPlane<ParaboloidOnPlane>;

} // namespace rv
