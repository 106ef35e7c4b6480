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
  static constexpr bool kLaneField = true; ///< no branch on a value: runs on lanes (Lanes.h)

  /// What the field reads, as T: double, or one value per lane (LaneField.h): the ball's coefficients, the
  /// bowl's as the height's terms multiply them (1 / (2 p), 1 / p, Lambda_i / 3, ...: reciprocals, as
  /// BallCoefficients says why) and the weight m g.
  template <class T> struct Coefficients {
    ball_on_surface::BallCoefficients<T> ball;
    T byTwoP, byTwoQ, byP, byQ;
    std::array<T, 4> L, Lthird; ///< Lambda_i, Lambda_i / 3
    T twoThirdsL1, twoThirdsL2, twoL0, twoL3;
    T weight;
  };
  const Coefficients<double>& coefficients() const { return c_; }

  /// Height of the centre's surface and its first and second derivatives.
  template <class S> struct Height { S phi, pu, pv, puu, puv, pvv; };
  template <class S, class T>
  [[gnu::always_inline]] static inline Height<S> heightOf(const Coefficients<T>& c, const S& u, const S& v) {
    const S uu = u * u, uv = u * v, vv = v * v;
    return {uu * c.byTwoP + vv * c.byTwoQ +
                (c.Lthird[0] * (uu * u) + c.Lthird[1] * (uu * v) + c.Lthird[2] * (u * vv) +
                 c.Lthird[3] * (vv * v)),
            u * c.byP + (c.L[0] * uu + c.twoThirdsL1 * uv + c.Lthird[2] * vv),
            v * c.byQ + (c.Lthird[1] * uu + c.twoThirdsL2 * uv + c.L[3] * vv),
            c.byP + (c.twoL0 * u + c.twoThirdsL1 * v),
            c.twoThirdsL1 * u + c.twoThirdsL2 * v,
            c.byQ + (c.twoThirdsL2 * u + c.twoL3 * v)};
  }
  Height<double> height(double u, double v) const { return heightOf<double>(c_, u, v); }
  /// The upward unit normal at (u, v): (-phi_u, -phi_v, 1) / sqrt(1 + phi_u^2 + phi_v^2).
  template <class S> [[gnu::always_inline]] static inline ThreeVector<S> normalOf(const Height<S>& h) {
    using std::sqrt;
    return (1.0 / sqrt(1.0 + h.pu * h.pu + h.pv * h.pv)) * ThreeVector<S>{{-h.pu, -h.pv, S(1.0)}};
  }

  /// The flow of (21)-(22) with the erratum, on ThreeVector, always inlined: the one statement of the
  /// equations, for one ball and for lanes of balls.
  template <class S, class T>
  [[gnu::always_inline]] static inline void field(const Coefficients<T>& c, const Vec<S>& s, Vec<S>& ds) {
    using std::sqrt;
    using Three = ThreeVector<S>;
    const Three M{{s[0], s[1], s[2]}};
    const Height<S> h = heightOf<S>(c, s[3], s[4]);
    // the upward unit normal n = (-phi_u, -phi_v, 1) / wn (normalOf) and its rate along (u', v')
    const S byWn = 1.0 / sqrt(1.0 + h.pu * h.pu + h.pv * h.pv);
    const Three n = byWn * Three{{-h.pu, -h.pv, S(1.0)}};
    const Three w = ball_on_surface::omega<S>(c.ball, M, n);
    const Three dx = c.ball.R * cross(w, n); // the centre's velocity
    const S dpu = h.puu * dx[0] + h.puv * dx[1], dpv = h.puv * dx[0] + h.pvv * dx[1];
    const S dwnByWn = (h.pu * dpu + h.pv * dpv) * (byWn * byWn); // wn' / wn
    const Three dn = byWn * Three{{-dpu, -dpv, S(0.0)}} - dwnByWn * n;
    const Three gravity{{S(0.0), S(0.0), S(-c.weight)}};
    ball_on_surface::rates<S>(c.ball, n, dn, w, gravity, ball_on_surface::Part{s, 5},
                              ball_on_surface::Part{ds, 0}, ball_on_surface::Part{ds, 5},
                              ball_on_surface::Part{ds, 9});
    ds[3] = dx[0];
    ds[4] = dx[1];
  }
  template <class S> void field(const Vec<S>& s, Vec<S>& ds) const { field(c_, s, ds); }

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
  Eigen::Vector3d normalAt(double u, double v) const { return normalOf<double>(height(u, v)).eigen(); }
  Eigen::Vector3d centre(double u, double v) const { return {u, v, height(u, v).phi}; }
  double energy(const double* s) const;

private:
  Eigen::VectorXd stateFrom(const Eigen::Vector3d& omega, double u, double v) const;
  double p_, q_, R_, mu_, D_, m_, g_;
  double L_[4];
  Coefficients<double> c_; ///< the same, as the field reads them
};

// compiled once, in BallOnParaboloid.cpp: constructing the model elsewhere does not compile its kernels again
// (ModelWithField.h)
extern template class ModelWithField<BallOnParaboloid, 11, 5>;

} // namespace rv
