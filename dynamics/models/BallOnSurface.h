// BallOnSurface.h -- what a homogeneous ball rolling without slipping on a fixed surface shares, whatever the
// surface (manual §3.3 equations (11)-(14), written in the fixed frame):
//   M = mu w + D g x (w x g),  D = m R^2,  x' = R w x g  (x the centre, g the unit normal at the contact),
//   M' = D g' x (w x g) + R g x F,  F = -grad U(x)  (the torque of the force on the centre about the
//   contact),
// and the ball's orientation as a unit quaternion, q' = (0, w) q / 2.
// Reference: A. V. Borisov, I. S. Mamaev, Nonholonomic dynamical systems (2002); errata in design.md.
#pragma once
#include "dynamics/core/Model.h"

#include <Eigen/Dense>

namespace rv::ball_on_surface {

template <class S> using V3 = Eigen::Matrix<S, 3, 1>;

/// w from M: (g, M) = mu (g, w), so w = (M + (D / mu)(g, M) g) / (mu + D).
template <class S> V3<S> omega(const V3<S>& M, const V3<S>& g, double mu, double D) {
  return (M + (D / mu) * g.dot(M) * g) / (mu + D);
}

/// M' = D g' x (w x g) + R g x F.
template <class S>
V3<S> momentumRate(const V3<S>& g, const V3<S>& dg, const V3<S>& w, const V3<S>& force, double D, double R) {
  return D * dg.cross(w.cross(g)) + R * g.cross(force);
}

/// d/dt of the quaternion (q0, q1, q2, q3) turning the ball's frame into the fixed one, w in the fixed frame.
template <class S, class Q> Eigen::Matrix<S, 4, 1> quaternionRate(const Q& q, const V3<S>& w) {
  Eigen::Matrix<S, 4, 1> dq;
  dq[0] = -0.5 * (w[0] * q[1] + w[1] * q[2] + w[2] * q[3]);
  dq[1] = 0.5 * (w[0] * q[0] + w[1] * q[3] - w[2] * q[2]);
  dq[2] = 0.5 * (w[1] * q[0] + w[2] * q[1] - w[0] * q[3]);
  dq[3] = 0.5 * (w[2] * q[0] + w[0] * q[2] - w[1] * q[1]);
  return dq;
}

/// The rotation of a (normalised) quaternion.
Eigen::Matrix3d rotation(const double* q);

/// Kinetic energy (M, w) / 2.
inline double kinetic(const Eigen::Vector3d& M, const Eigen::Vector3d& g, double mu, double D) {
  return 0.5 * M.dot(omega<double>(M, g, mu, D));
}

} // namespace rv::ball_on_surface
