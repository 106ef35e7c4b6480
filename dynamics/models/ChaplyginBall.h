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

#include <Eigen/Dense>

namespace rv {

class ChaplyginBall final : public ModelWithField<ChaplyginBall, 16, 6> {
public:
  explicit ChaplyginBall(const ParameterValues& params);
  static const ModelInfo& staticInfo();

  template <class S> void field(const Vec<S>& x, Vec<S>& dx) const;

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
};

template <class S>
Eigen::Matrix<S, 3, 1> ChaplyginBall::angularVelocity(const Eigen::Matrix<S, 3, 1>& M,
                                                      const Eigen::Matrix<S, 3, 1>& g) const {
  // J omega = M + D (gamma, omega) gamma  =>  (gamma, omega) = (gamma, J^-1 M) / (1 - D (gamma, J^-1 gamma))
  const Eigen::Matrix<S, 3, 1> JiM = Jinv_.cast<S>().cwiseProduct(M), Jig = Jinv_.cast<S>().cwiseProduct(g);
  const S s = g.dot(JiM) / (S(1) - D_ * g.dot(Jig));
  return JiM + (D_ * s) * Jig;
}

template <class S> void ChaplyginBall::field(const Vec<S>& x, Vec<S>& dx) const {
  using V3 = Eigen::Matrix<S, 3, 1>;
  using std::sqrt;
  const V3 M = x.template segment<3>(0), g = x.template segment<3>(3);
  const V3 a = x.template segment<3>(6), b = x.template segment<3>(9);
  const V3 w = angularVelocity<S>(M, g);
  dx.template segment<3>(0) = (M + K_.cast<S>()).cross(w); // (25)
  dx.template segment<3>(3) = g.cross(w);
  dx.template segment<3>(6) = a.cross(w); // (28)
  dx.template segment<3>(9) = b.cross(w);
  const S vx = R_ * w.dot(b), vy = -R_ * w.dot(a); // (30), r = -R gamma
  dx[12] = vx;
  dx[13] = vy;
  dx[14] = sqrt(vx * vx + vy * vy);                            // speed of the contact point on the plane
  dx[15] = R_ * sqrt(dx.template segment<3>(3).squaredNorm()); // ... and on the ball: |d(-R gamma)/dt|
}

} // namespace rv
