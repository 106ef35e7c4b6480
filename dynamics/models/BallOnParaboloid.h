// BallOnParaboloid.h -- a homogeneous ball rolling without slipping in a bowl under gravity: its centre moves
// on the cubically perturbed paraboloid (21), z = u^2/(2 p) + v^2/(2 q) + (L1 u^3 + L2 u^2 v + L3 u v^2 + L4
// v^3)/3 (rollviz's p, q are the b1, b2 of (21)-(22)). Manual §3.4 with the design.md erratum to (22): the
// flow runs gamma' = -R g3/(mu + D) gamma x (gamma x B'(gamma x M)). With all L = 0 the measure (23) and the
// integral F = (24) + (mu + D) m g (g1^2 + g2^2)/g3^2 exist. The centre's horizontal coordinates (u, v) are
// the state instead of gamma: gamma = n(u, v) is then explicit for any perturbation (no Newton solve), and
// the map coordinates (x1, w1, w2) at x2 = const are state functions.
//
// State (11): M (fixed frame), u, v; the ball's orientation quaternion q0..q3; trace lengths.
#pragma once
#include "dynamics/core/ModelWithField.h"
#include "dynamics/models/BallOnSurface.h"

namespace rv {

class BallOnParaboloid final : public ModelWithField<BallOnParaboloid, 11, 5> {
public:
  template <class S> using V3 = ball_on_surface::V3<S>;
  explicit BallOnParaboloid(const ParameterValues& params);
  static const ModelInfo& staticInfo();

  /// Height of the centre's surface and its first and second derivatives.
  template <class S> struct Height { S phi, pu, pv, puu, puv, pvv; };
  template <class S> Height<S> height(const S& u, const S& v) const {
    const double* L = L_;
    return {u * u / (2 * p_) + v * v / (2 * q_) +
                (L[0] * u * u * u + L[1] * u * u * v + L[2] * u * v * v + L[3] * v * v * v) / 3.0,
            u / p_ + (3.0 * L[0] * u * u + 2.0 * L[1] * u * v + L[2] * v * v) / 3.0,
            v / q_ + (L[1] * u * u + 2.0 * L[2] * u * v + 3.0 * L[3] * v * v) / 3.0,
            1.0 / p_ + (6.0 * L[0] * u + 2.0 * L[1] * v) / 3.0,
            (2.0 * L[1] * u + 2.0 * L[2] * v) / 3.0,
            1.0 / q_ + (2.0 * L[2] * u + 6.0 * L[3] * v) / 3.0};
  }
  /// The upward unit normal at (u, v): (-phi_u, -phi_v, 1) / sqrt(1 + phi_u^2 + phi_v^2).
  template <class S> V3<S> normal(const Height<S>& h) const {
    using std::sqrt;
    return V3<S>(-h.pu, -h.pv, S(1.0)) / sqrt(1.0 + h.pu * h.pu + h.pv * h.pv);
  }

  template <class S> void field(const Vec<S>& s, Vec<S>& ds) const {
    using std::sqrt;
    const V3<S> M = s.template segment<3>(0);
    const Height<S> h = height<S>(s[3], s[4]);
    const V3<S> n = normal<S>(h);
    const V3<S> w = ball_on_surface::omega<S>(M, n, mu_, D_);
    const V3<S> dx = R_ * w.cross(n); // the centre's velocity
    // n' from the second derivatives along (u', v')
    const S wn = sqrt(1.0 + h.pu * h.pu + h.pv * h.pv);
    const S dpu = h.puu * dx[0] + h.puv * dx[1], dpv = h.puv * dx[0] + h.pvv * dx[1];
    const S dwn = (h.pu * dpu + h.pv * dpv) / wn;
    const V3<S> dn = V3<S>(-dpu, -dpv, S(0.0)) / wn - n * (dwn / wn);
    const V3<S> gravity(S(0.0), S(0.0), S(-m_ * g_));
    ds.template segment<3>(0) = ball_on_surface::momentumRate<S>(n, dn, w, gravity, D_, R_);
    ds[3] = dx[0];
    ds[4] = dx[1];
    ds.template segment<4>(5) = ball_on_surface::quaternionRate<S>(s.template segment<4>(5), w);
    const V3<S> dq = dx - R_ * dn, onBall = dn - w.cross(n);
    ds[9] = sqrt(dq.squaredNorm());
    ds[10] = R_ * sqrt(onBall.squaredNorm());
  }

  Eigen::VectorXd integrals(const double* s) const override;
  double measureDensity(const double* s) const override;
  bool hasInvariantMeasure() const override { return unperturbed(); }
  std::optional<BodyPose> pose(const double* s) const override;
  std::optional<BodyGeometry> geometry() const override {
    return BodyGeometry{.shape = BodyShape::Ball, .semiAxes = Eigen::Vector3d::Constant(R_)};
  }
  std::optional<SupportSurface> support() const override;
  /// State from M1..M3 (or omega1..omega3), x1, x2 (the centre's horizontal position).
  Eigen::VectorXd stateFromNamed(const std::map<std::string, double>& named,
                                 const std::string& context) const override;
  /// (x1, w1, w2) at x2 = section value, w3 from the energy (root 1: the smaller, 2: the larger).
  Eigen::VectorXd stateFromMap(const std::vector<double>& point, const MapPointSpec& spec,
                               const std::string& context) const override;

  bool unperturbed() const { return L_[0] == 0 && L_[1] == 0 && L_[2] == 0 && L_[3] == 0; }
  Eigen::Vector3d normalAt(double u, double v) const { return normal<double>(height<double>(u, v)); }
  Eigen::Vector3d centre(double u, double v) const { return {u, v, height<double>(u, v).phi}; }
  double energy(const double* s) const;

private:
  Eigen::VectorXd stateFrom(const Eigen::Vector3d& omega, double u, double v) const;
  double p_, q_, R_, mu_, D_, m_, g_;
  double L_[4];
};

} // namespace rv
