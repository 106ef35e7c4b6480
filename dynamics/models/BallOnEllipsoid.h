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

  template <class S> V3<S> centre(const V3<S>& g) const {
    using std::sqrt;
    const V3<S> Bg = B_.cast<S>().cwiseProduct(g);
    return Bg / sqrt(g.dot(Bg));
  }
  /// -grad U at the centre.
  template <class S> V3<S> force(const V3<S>& x) const {
    V3<S> f = -k_ * x;
    for (int i = 0; i < 3; ++i)
      f[i] += 2.0 * c_[i] / (x[i] * x[i] * x[i]);
    return f;
  }

  template <class S> void field(const Vec<S>& s, Vec<S>& ds) const {
    using std::sqrt;
    const V3<S> M = s.template segment<3>(0), g = s.template segment<3>(3);
    const V3<S> w = ball_on_surface::omega<S>(M, g, mu_, D_);
    const S root = sqrt(g.dot(B_.cast<S>().cwiseProduct(g)));
    const V3<S> dg =
        (R_ * root / (mu_ + D_)) * g.cross(g.cross(Binv_.cast<S>().cwiseProduct(g.cross(M)))); // (16)
    ds.template segment<3>(0) = ball_on_surface::momentumRate<S>(g, dg, w, force<S>(centre<S>(g)), D_, R_);
    ds.template segment<3>(3) = dg;
    ds.template segment<4>(6) = ball_on_surface::quaternionRate<S>(s.template segment<4>(6), w);
    // the contact point x - R g moves with x' - R g' on the surface; on the ball, -R g seen from the turning
    // ball changes at -R (g' - w x g): equal speeds, as rolling without slipping requires
    const V3<S> dx = R_ * w.cross(g), dq = dx - R_ * dg, onBall = dg - w.cross(g);
    ds[10] = sqrt(dq.squaredNorm());
    ds[11] = R_ * sqrt(onBall.squaredNorm());
  }

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
};

} // namespace rv
