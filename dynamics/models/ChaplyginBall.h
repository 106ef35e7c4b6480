// ChaplyginBall.h -- a dynamically asymmetric balanced ball with a gyrostat rolling without slipping on a
// plane: manual §3.5, equations (25), integrals (26), invariant measure (27), absolute motion (28)-(30).
// Reference: A. V. Borisov, I. S. Mamaev, Nonholonomic dynamical systems (2002), §8;
//            A. Yu. Moskvin, Chaplygin's ball with a gyrostat: singular solutions, Nelin. Dinam. 5 (2009).
//
// State (16): M (momentum about the contact point), gamma (upward vertical), alpha, beta (fixed horizontal
// axes), all in the body frame; x, y (contact point on the plane); s_plane, s_body (trace lengths).
// The first six components evolve on their own; the rest are kinematics.
#pragma once
#include "dynamics/core/ModelWithField.h"
#include "dynamics/models/ThreeVector.h"

#include <Eigen/Dense>
#include <array>

namespace rv {

class ChaplyginBall final : public ModelWithField<ChaplyginBall, 16, 6> {
public:
  explicit ChaplyginBall(const ParameterValues& params);
  static const ModelInfo& staticInfo();
  static constexpr bool kLaneField = true; ///< no branch on a value: runs on lanes (Lanes.h)

  /// What the field reads, as T: double, or one value per lane (LaneField.h): J^-1 (J = I + D E), the
  /// gyrostat K, D = m R^2 and R.
  template <class T> struct Coefficients {
    std::array<T, 3> Jinv, K;
    T D, R;
  };
  const Coefficients<double>& coefficients() const { return c_; }

  /// (25), (28)-(30) on ThreeVector, always inlined: the one statement of the equations, for one ball and for
  /// lanes of balls (the lane kernels compile it whole: ThreeVector.h says why).
  template <class S, class T>
  [[gnu::always_inline]] static inline void field(const Coefficients<T>& c, const Vec<S>& x, Vec<S>& dx);
  template <class S> void field(const Vec<S>& x, Vec<S>& dx) const { field(c_, x, dx); }
  /// omega from M and gamma: M = I omega + D gamma x (omega x gamma), solved in closed form.
  template <class S, class T>
  [[gnu::always_inline]] static inline ThreeVector<S>
  angularVelocityOf(const Coefficients<T>& c, const ThreeVector<S>& M, const ThreeVector<S>& g);

  Eigen::VectorXd integrals(const double* x) const override;
  double measureDensity(const double* x) const override;
  std::optional<BodyPose> pose(const double* x) const override;
  std::optional<BodyGeometry> geometry() const override {
    return BodyGeometry{.shape = BodyShape::Ball, .semiAxes = Eigen::Vector3d::Constant(R_)};
  }
  Eigen::VectorXd stateFromNamed(const std::map<std::string, double>& named,
                                 const std::string& context) const override;
  Eigen::VectorXd stateFromMap(const std::vector<double>& point, const MapPointSpec& spec,
                               const std::string& context) const override;
  /// The root (G) of the completion nearest to the state's G.
  int sheetOf(const Eigen::VectorXd& x, const MapPointSpec& spec) const override;
  /// "nh": the bifurcation set (31)-(34) in the plane (n, h) at the scene's c; "ch": the same set in the
  /// plane (c, h) at n = diagram_n (ChaplyginDiagram.h). Their `place` refers to this model.
  std::vector<Diagram> diagrams() const override;

  /// omega from M and gamma: M = I omega + D gamma x (omega x gamma), solved in closed form.
  template <class S>
  Eigen::Matrix<S, 3, 1> angularVelocity(const Eigen::Matrix<S, 3, 1>& M,
                                         const Eigen::Matrix<S, 3, 1>& g) const;
  double radius() const { return R_; }

private:
  /// The values of G at which (l, L/G) on g = g0 has the scene's energy and area constant, ascending.
  std::vector<double> completionRoots(double l, double LG, double g0) const;
  void stateOnSection(double l, double LG, double g0, double G, Eigen::Vector3d& M, Eigen::Vector3d& g) const;
  Eigen::Vector3d I_, Jinv_, K_; // principal moments, J = I + D E (diagonal), gyrostat
  double D_, R_;
  Coefficients<double> c_; ///< the same, as the field reads them
};

template <class S, class T>
ThreeVector<S> ChaplyginBall::angularVelocityOf(const Coefficients<T>& c, const ThreeVector<S>& M,
                                                const ThreeVector<S>& g) {
  // J omega = M + D (gamma, omega) gamma  =>  (gamma, omega) = (gamma, J^-1 M) / (1 - D (gamma, J^-1 gamma))
  const ThreeVector<S> JiM = times(c.Jinv, M), Jig = times(c.Jinv, g);
  const S s = dot(g, JiM) / (1.0 - c.D * dot(g, Jig));
  return JiM + (c.D * s) * Jig;
}

template <class S>
Eigen::Matrix<S, 3, 1> ChaplyginBall::angularVelocity(const Eigen::Matrix<S, 3, 1>& M,
                                                      const Eigen::Matrix<S, 3, 1>& g) const {
  return angularVelocityOf<S>(c_, ThreeVector<S>::from(M), ThreeVector<S>::from(g)).eigen();
}

template <class S, class T> void ChaplyginBall::field(const Coefficients<T>& c, const Vec<S>& x, Vec<S>& dx) {
  using std::sqrt;
  using Three = ThreeVector<S>;
  const Three M{{x[0], x[1], x[2]}}, g{{x[3], x[4], x[5]}}, a{{x[6], x[7], x[8]}}, b{{x[9], x[10], x[11]}};
  const Three w = angularVelocityOf<S>(c, M, g);
  const Three dM = cross(M + Three::of(c.K), w), dg = cross(g, w); // (25)
  const Three da = cross(a, w), db = cross(b, w);                  // (28)
  for (int i = 0; i < 3; ++i) {
    dx[i] = dM[i];
    dx[3 + i] = dg[i];
    dx[6 + i] = da[i];
    dx[9 + i] = db[i];
  }
  const S vx = c.R * dot(w, b), vy = -(c.R * dot(w, a)); // (30), r = -R gamma
  dx[12] = vx;
  dx[13] = vy;
  dx[14] = sqrt(vx * vx + vy * vy); // speed of the contact point on the plane
  dx[15] = c.R * sqrt(dot(dg, dg)); // ... and on the ball: |d(-R gamma)/dt|
}

// compiled once, in ChaplyginBall.cpp: constructing the model elsewhere does not compile its kernels again
// (ModelWithField.h)
extern template class ModelWithField<ChaplyginBall, 16, 6>;

} // namespace rv
