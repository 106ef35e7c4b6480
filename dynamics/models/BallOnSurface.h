// BallOnSurface.h -- what a homogeneous ball rolling without slipping on a fixed surface shares, whatever the
// surface (manual §3.3 equations (11)-(14), written in the fixed frame):
//   M = mu w + D g x (w x g),  D = m R^2,  x' = R w x g  (x the centre, g the unit normal at the contact),
//   M' = D g' x (w x g) + R g x F,  F = -grad U(x)  (the torque of the force on the centre about the
//   contact),
// and the ball's orientation as a unit quaternion, q' = (0, w) q / 2.
// Written on ThreeVector (ThreeVector.h says why) over coefficients T: a double, or one value per SIMD lane
// (dynamics/core/LaneField.h), so that the balls' fields run on lanes.
// Reference: A. V. Borisov, I. S. Mamaev, Nonholonomic dynamical systems (2002); errata in design.md.
#pragma once
#include "dynamics/core/JetProgram.h"
#include "dynamics/core/Lanes.h"
#include "dynamics/core/Model.h"
#include "dynamics/models/ThreeVector.h"

#include <Eigen/Dense>
#include <array>
#include <type_traits>

namespace rv::ball_on_surface {

template <class S> using V3 = Eigen::Matrix<S, 3, 1>;

/// `term()` where `coefficient` is not 0, else 0 with no derivatives: a term c f(x) that vanishes with c
/// although f is not finite everywhere (c / x^3 at x = 0, which would be 0 / 0). A branch on a coefficient,
/// taken lane by lane where the coefficients are one per lane, so each lane is the scalar run's; the term is
/// not computed at all where no lane has it (the common case, c = 0, costs no division).
template <class S, class T, class Term>
[[gnu::always_inline]] inline S vanishingWith(const T& coefficient, const Term& term) {
  if constexpr (std::is_arithmetic_v<T>) {
    return coefficient != 0.0 ? S(term()) : S(0.0);
  } else if constexpr (std::is_same_v<T, jet_recording::Constant>) { // recorded (JetProgram.h)
    return keptWhereNonzero(coefficient, term());
  } else { // S a Jet of lanes T
    bool any = false;
    for (int l = 0; l < T::kWidth; ++l)
      any = any || coefficient[l] != 0.0;
    return any ? keptWhereNonzero(coefficient, term()) : S(0.0);
  }
}

/// What the ball's own equations read, as T: D / mu and 1 / (mu + D) (the angular velocity), D = m R^2, R and
/// R / (mu + D). Reciprocals, so that the fields multiply: a division of a jet costs two (the value's and the
/// derivatives' scale), and AVX2 divides four lanes at half the rate of two on the CPUs measured.
template <class T> struct BallCoefficients { T DbyMu, byMuPlusD, D, R, RbyMuPlusD; };
/// The ball's coefficients from mu, D and R.
inline BallCoefficients<double> ballCoefficients(double mu, double D, double R) {
  return {D / mu, 1 / (mu + D), D, R, R / (mu + D)};
}

/// w from M: (g, M) = mu (g, w), so w = (M + (D / mu)(g, M) g) / (mu + D).
template <class S, class T>
[[gnu::always_inline]] inline ThreeVector<S> omega(const BallCoefficients<T>& c, const ThreeVector<S>& M,
                                                   const ThreeVector<S>& g) {
  return c.byMuPlusD * (M + (c.DbyMu * dot(g, M)) * g);
}
/// The same on Eigen vectors (the integrals and observables).
inline Eigen::Vector3d omega(const BallCoefficients<double>& c, const Eigen::Vector3d& M,
                             const Eigen::Vector3d& g) {
  return omega<double>(c, ThreeVector<double>::from(M), ThreeVector<double>::from(g)).eigen();
}

/// The rates of a ball whose centre moves with the unit normal g (and g' = dg) at angular velocity w under
/// the force F on the centre, from the state's quaternion q (4 components from `quaternion`): M' = D g' x (w
/// x g) + R g x F into dM[0..2], q' into dq[0..3], and the speeds of the contact point on the surface and on
/// the ball into speeds[0..1] (equal when rolling without slipping).
template <class S, class T, class In, class Out>
[[gnu::always_inline]] inline void rates(const BallCoefficients<T>& c, const ThreeVector<S>& g,
                                         const ThreeVector<S>& dg, const ThreeVector<S>& w,
                                         const ThreeVector<S>& force, const In& quaternion, Out dM, Out dq,
                                         Out speeds) {
  using std::sqrt;
  const ThreeVector<S> wg = cross(w, g);
  const ThreeVector<S> momentum = c.D * cross(dg, wg) + c.R * cross(g, force);
  for (int i = 0; i < 3; ++i)
    dM[i] = momentum[i];
  // d/dt of the quaternion (q0, q1, q2, q3) turning the ball's frame into the fixed one, w in the fixed frame
  const S &q0 = quaternion[0], &q1 = quaternion[1], &q2 = quaternion[2], &q3 = quaternion[3];
  dq[0] = -0.5 * (w[0] * q1 + w[1] * q2 + w[2] * q3);
  dq[1] = 0.5 * (w[0] * q0 + w[1] * q3 - w[2] * q2);
  dq[2] = 0.5 * (w[1] * q0 + w[2] * q1 - w[0] * q3);
  dq[3] = 0.5 * (w[2] * q0 + w[0] * q2 - w[1] * q1);
  // the contact point x - R g moves with x' - R g' on the surface; on the ball, -R g seen from the turning
  // ball changes at -R (g' - w x g): equal speeds, as rolling without slipping requires
  const ThreeVector<S> onSurface = c.R * wg - c.R * dg, onBall = dg - wg;
  speeds[0] = sqrt(dot(onSurface, onSurface));
  speeds[1] = c.R * sqrt(dot(onBall, onBall));
}

/// A window of `count` components of a state vector from `first` (what rates() reads and writes).
template <class V> struct Part {
  V& v;
  int first;
  [[gnu::always_inline]] decltype(auto) operator[](int i) const { return v[first + i]; }
};
template <class V> Part(V&, int) -> Part<V>;

/// The rotation of a (normalised) quaternion.
Eigen::Matrix3d rotation(const double* q);

/// Kinetic energy (M, w) / 2.
inline double kinetic(const BallCoefficients<double>& c, const Eigen::Vector3d& M, const Eigen::Vector3d& g) {
  return 0.5 * M.dot(omega(c, M, g));
}

} // namespace rv::ball_on_surface
