// BallOnEllipsoid.h -- a homogeneous ball rolling without slipping on a triaxial ellipsoid, in a field
// U = k |x|^2 / 2 + sum c_i / x_i^2 of its centre x: manual §3.3, equations (16) with the field's torque,
// energy (14), measure (17), and the integral K in its generalised form with the design.md erratum to (20):
//   K = (g x w, B^-1 (g x w)) / (g, B g) - (x, B^-2 x) [k - 2 sum c_i / (B_ii x_i^2)] / (mu + D).
// B = diag(b_i^2): rollviz's b1..b3 are the semi-axes of the ellipsoid the CENTRE moves on, x = B g / sqrt(g,
// B g); the ball touches the parallel surface x - R g.
//
// State (12): M, gamma in the fixed frame; the ball's orientation quaternion q0..q3; trace lengths.
#pragma once
#include "dynamics/core/ModelWithField.h"
#include "dynamics/models/BallOnSurface.h"

namespace rv {

class BallOnEllipsoid final : public ModelWithField<BallOnEllipsoid, 12, 6> {
public:
  template <class S> using V3 = ball_on_surface::V3<S>;
  explicit BallOnEllipsoid(const ParameterValues& params);
  static const ModelInfo& staticInfo();
  static constexpr bool kLaneField = true; ///< no branch on a value: runs on lanes (Lanes.h)

  /// What the field reads, as T: double, or one value per lane (LaneField.h): the ball's coefficients, B =
  /// diag(b_i^2), its inverse, 2 c_i and k of the field.
  template <class T> struct Coefficients {
    ball_on_surface::BallCoefficients<T> ball;
    std::array<T, 3> B, Binv, twoC;
    T k;
  };
  const Coefficients<double>& coefficients() const { return coefficients_; }

  /// The centre x = B g / sqrt(g, B g) on its ellipsoid, for the unit normal g.
  template <class S, class T>
  [[gnu::always_inline]] static inline ThreeVector<S> centreOf(const Coefficients<T>& c,
                                                               const ThreeVector<S>& g) {
    using std::sqrt;
    const ThreeVector<S> Bg = times(c.B, g);
    return (1.0 / sqrt(dot(g, Bg))) * Bg;
  }
  Eigen::Vector3d centre(const Eigen::Vector3d& g) const {
    return centreOf<double>(coefficients_, ThreeVector<double>::from(g)).eigen();
  }
  /// -grad U at the centre x.
  template <class S, class T>
  [[gnu::always_inline]] static inline ThreeVector<S> forceOf(const Coefficients<T>& c,
                                                              const ThreeVector<S>& x) {
    ThreeVector<S> f;
    for (int i = 0; i < 3; ++i)
      f.c[static_cast<std::size_t>(i)] =
          -c.k * x[i] + ball_on_surface::vanishingWith<S>(c.twoC[static_cast<std::size_t>(i)], [&] {
            return c.twoC[static_cast<std::size_t>(i)] / (x[i] * x[i] * x[i]);
          });
    return f;
  }

  /// (16) with the field's torque, on ThreeVector, always inlined: the one statement of the equations, for
  /// one ball and for lanes of balls.
  template <class S, class T>
  [[gnu::always_inline]] static inline void field(const Coefficients<T>& c, const Vec<S>& s, Vec<S>& ds) {
    using std::sqrt;
    using Three = ThreeVector<S>;
    const Three M{{s[0], s[1], s[2]}}, g{{s[3], s[4], s[5]}};
    const Three w = ball_on_surface::omega<S>(c.ball, M, g);
    const Three Bg = times(c.B, g);
    const S root = sqrt(dot(g, Bg));
    const Three dg = (c.ball.RbyMuPlusD * root) * cross(g, cross(g, times(c.Binv, cross(g, M)))); // (16)
    ball_on_surface::rates<S>(c.ball, g, dg, w, forceOf<S>(c, (1.0 / root) * Bg), ball_on_surface::Part{s, 6},
                              ball_on_surface::Part{ds, 0}, ball_on_surface::Part{ds, 6},
                              ball_on_surface::Part{ds, 10});
    for (int i = 0; i < 3; ++i)
      ds[3 + i] = dg[i];
  }
  template <class S> void field(const Vec<S>& s, Vec<S>& ds) const { field(coefficients_, s, ds); }

  Eigen::VectorXd integrals(const double* s) const override;
  double measureDensity(const double* s) const override;
  std::optional<BodyPose> pose(const double* s) const override;
  std::optional<BodyGeometry> geometry() const override {
    return BodyGeometry{.shape = BodyShape::Ball, .semiAxes = Eigen::Vector3d::Constant(R_)};
  }
  std::optional<SupportSurface> support() const override;
  Eigen::VectorXd stateFromNamed(const std::map<std::string, double>& named,
                                 const std::string& context) const override;
  /// (l, L/G) completed through the energy and the integral K (root finding in H/G), or (l, L/G, H/G) through
  /// the energy alone.
  Eigen::VectorXd stateFromMap(const std::vector<double>& point, const MapPointSpec& spec,
                               const std::string& context) const override;

  double energy(const Eigen::Vector3d& M, const Eigen::Vector3d& g) const;
  double integralK(const Eigen::Vector3d& M, const Eigen::Vector3d& g) const;

private:
  Eigen::VectorXd stateFrom(const Eigen::Vector3d& M, const Eigen::Vector3d& g) const;
  Eigen::Vector3d B_, Binv_, c_;
  double mu_, D_, R_, k_;
  Coefficients<double> coefficients_; ///< the same, as the field reads them
};

// compiled once, in BallOnEllipsoid.cpp: constructing the model elsewhere does not compile its kernels again
// (ModelWithField.h)
extern template class ModelWithField<BallOnEllipsoid, 12, 6>;

} // namespace rv
