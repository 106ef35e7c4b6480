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
  static constexpr bool kLaneField = true; ///< no branch on a value: runs on lanes (Lanes.h)

  /// The surface as the equations read it, as T (double, or one value per lane): the squared semi-axes b2 and
  /// the offset a; its Gauss map (8) with the erratum and that map's rate along gamma-dot.
  template <class T> struct Surface {
    std::array<T, 3> b2, a;
    template <class S> [[gnu::always_inline]] ThreeVector<S> contact(const ThreeVector<S>& g) const {
      using std::sqrt;
      const ThreeVector<S> b2g = times(b2, g);
      return -b2g / sqrt(dot(g, b2g)) - ThreeVector<S>::of(a);
    }
    template <class S>
    [[gnu::always_inline]] ThreeVector<S> contactRate(const ThreeVector<S>& g,
                                                      const ThreeVector<S>& dg) const {
      using std::sqrt;
      const ThreeVector<S> b2g = times(b2, g);
      const S s2 = dot(g, b2g), s = sqrt(s2);
      return -times(b2, dg) / s + (dot(b2g, dg) / (s2 * s)) * b2g;
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
  bool touches(const Eigen::Vector3d&) const { return true; }
  std::optional<BodyGeometry> geometry() const override {
    return BodyGeometry{.shape = BodyShape::Ellipsoid, .centre = geometricCentre(), .semiAxes = semiAxes()};
  }

  /// Semi-axes and the geometric centre seen from the centre of mass (-a), for drawing.
  Eigen::Vector3d semiAxes() const {
    return Eigen::Map<const Eigen::Vector3d>(surface_.b2.data()).cwiseSqrt();
  }
  Eigen::Vector3d geometricCentre() const { return -Eigen::Map<const Eigen::Vector3d>(surface_.a.data()); }
  /// (9)
  static Eigen::Matrix3d eulerRotation(double phi, double theta, double psi);

private:
  Surface<double> surface_;
};

// compiled once, in EllipsoidOnPlane.cpp: constructing the model elsewhere does not compile its kernels again
// (ModelWithField.h)
extern template class ModelWithField<EllipsoidOnPlane, 16, 6>;
extern template class RigidBodyOnPlane<EllipsoidOnPlane>;

} // namespace rv
