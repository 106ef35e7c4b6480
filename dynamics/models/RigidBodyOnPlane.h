// RigidBodyOnPlane.h -- a rigid body with a smooth convex surface rolling without slipping on a horizontal
// plane under gravity and an extra field U = (gamma, B gamma)/2: manual §3.1.1 equations (2), integrals (3).
// The surface enters only through its Gauss map r(gamma) (the contact point seen from the centre of mass,
// in the body frame) and the rate dr/dt along gamma-dot; ParaboloidOnPlane and EllipsoidOnPlane supply them.
// Reference: A. V. Borisov, I. S. Mamaev, Nonholonomic dynamical systems (2002); Borisov, Mamaev, Strange
//            attractors in rattleback dynamics, Physics-Uspekhi 46 (2003).
//
// State (16): M (momentum about the contact point), gamma (upward vertical), alpha, beta (fixed horizontal
// axes), all in the body frame; X, Y (centre of mass on the plane); s_plane, s_body (trace lengths).
#pragma once
#include "dynamics/core/ModelWithField.h"
#include "dynamics/models/BodyParameters.h"

#include <Eigen/Dense>

namespace rv {

/// Constants shared by every rigid body on the plane.
struct RigidBodyConstants {
  Eigen::Matrix3d inertia; ///< central inertia tensor in the body (geometric) axes
  double mass = 1, gravity = 1;
  Eigen::Matrix3d field = Eigen::Matrix3d::Zero(); ///< B of U = (gamma, B gamma) / 2
};

/// The equations, generic in the surface (Derived provides contact<S>(gamma) and contactRate<S>(gamma,
/// dgamma)).
template <class Derived> class RigidBodyOnPlane : public ModelWithField<Derived, 16, 6> {
public:
  using Base = ModelWithField<Derived, 16, 6>;
  template <class S> using Vec = typename Base::template Vec<S>;
  template <class S> using V3 = Eigen::Matrix<S, 3, 1>;

  RigidBodyOnPlane(const ModelInfo& info, const ParameterValues& p, const RigidBodyConstants& c)
      : Base(info, p), c_(c) {}

  /// omega from M: M = I omega + m r x (omega x r).
  template <class S> V3<S> angularVelocity(const V3<S>& M, const V3<S>& r) const {
    Eigen::Matrix<S, 3, 3> A = c_.inertia.template cast<S>();
    const S rr = r.squaredNorm();
    for (int i = 0; i < 3; ++i) {
      A(i, i) += c_.mass * rr;
      for (int j = 0; j < 3; ++j)
        A(i, j) -= c_.mass * r[i] * r[j];
    }
    return A.inverse() * M;
  }

  template <class S> void field(const Vec<S>& x, Vec<S>& dx) const {
    using std::sqrt;
    const V3<S> M = x.template segment<3>(0), g = x.template segment<3>(3);
    const V3<S> a = x.template segment<3>(6), b = x.template segment<3>(9);
    const V3<S> r = self().template contact<S>(g);
    const V3<S> w = angularVelocity<S>(M, r);
    const V3<S> dg = g.cross(w);
    const V3<S> dr = self().template contactRate<S>(g, dg);
    const V3<S> Bg = c_.field.template cast<S>() * g;
    dx.template segment<3>(0) = M.cross(w) + c_.mass * dr.cross(w.cross(r)) +
                                (c_.mass * c_.gravity) * r.cross(g) + g.cross(Bg); // (2)
    dx.template segment<3>(3) = dg;
    dx.template segment<3>(6) = a.cross(w);
    dx.template segment<3>(9) = b.cross(w);
    const V3<S> v = -w.cross(r); // velocity of the centre of mass, from the rolling constraint (1)
    dx[12] = v.dot(a);
    dx[13] = v.dot(b);
    // the contact point moves on the plane with ((alpha, r'), (beta, r')) and on the body with r'
    const S pa = a.dot(dr), pb = b.dot(dr);
    dx[14] = sqrt(pa * pa + pb * pb);
    dx[15] = sqrt(dr.squaredNorm());
  }

  Eigen::VectorXd integrals(const double* x) const override {
    const Eigen::Vector3d M(x[0], x[1], x[2]), g(x[3], x[4], x[5]);
    Eigen::VectorXd v(2);
    v << energy(M, g), g.squaredNorm();
    return v;
  }

  /// H of (3).
  double energy(const Eigen::Vector3d& M, const Eigen::Vector3d& g) const {
    const Eigen::Vector3d r = self().template contact<double>(g);
    return 0.5 * M.dot(angularVelocity<double>(M, r)) + potential(g);
  }
  /// -m g (r, gamma) + U(gamma).
  double potential(const Eigen::Vector3d& g) const {
    const Eigen::Vector3d r = self().template contact<double>(g);
    return -c_.mass * c_.gravity * r.dot(g) + 0.5 * g.dot(c_.field * g);
  }

  std::optional<BodyPose> pose(const double* x) const override {
    BodyPose p;
    p.rotation.row(0) = Eigen::Vector3d(x[6], x[7], x[8]).transpose();
    p.rotation.row(1) = Eigen::Vector3d(x[9], x[10], x[11]).transpose();
    const Eigen::Vector3d g(x[3], x[4], x[5]);
    p.rotation.row(2) = g.transpose();
    const Eigen::Vector3d r = self().template contact<double>(g);
    p.center = {x[12], x[13], -r.dot(g)}; // the centre of mass
    p.contact = p.center + p.rotation * r;
    return p;
  }

  const RigidBodyConstants& constants() const { return c_; }

protected:
  /// Adds the observables every rigid body on the plane has; call from the leaf constructor.
  void addRigidBodyObservables();
  /// A full state from M and gamma (alpha, beta completed; X = Y = 0).
  Eigen::VectorXd stateFrom(const Eigen::Vector3d& M, const Eigen::Vector3d& gamma) const;

public:
  Eigen::VectorXd stateFromNamed(const std::map<std::string, double>& named,
                                 const std::string& context) const override;
  /// (l, L/G, H/G) at g = g0: gamma from the angles, G from the energy (E is quadratic in G).
  Eigen::VectorXd stateFromMap(const std::vector<double>& point, const MapPointSpec& spec,
                               const std::string& context) const override;

protected:
  RigidBodyConstants c_;

private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

} // namespace rv

#include "dynamics/models/RigidBodyOnPlane.inl"
