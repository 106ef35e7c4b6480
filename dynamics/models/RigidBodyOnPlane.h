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
#include "dynamics/models/ThreeVector.h"

#include <Eigen/Dense>
#include <array>
#include <cstddef>

namespace rv {

/// Constants shared by every rigid body on the plane.
struct RigidBodyConstants {
  Eigen::Matrix3d inertia; ///< central inertia tensor in the body (geometric) axes
  double mass = 1, gravity = 1;
  Eigen::Matrix3d field = Eigen::Matrix3d::Zero(); ///< B of U = (gamma, B gamma) / 2
};

/// The same constants as the equations read them, as T: double, or one value per SIMD lane (a sweep's points
/// side by side, dynamics/core/LaneField.h). Matrices column-major.
template <class T> struct RigidBodyCoefficients {
  std::array<T, 9> inertia;
  T mass, gravity;
  std::array<T, 9> field;
};

/// The equations, generic in the surface (Derived provides contact<S>(gamma) and contactRate<S>(gamma,
/// dgamma) on Eigen vectors). A Derived whose surface is a `Surface<T>` of coefficients (EllipsoidOnPlane)
/// gives it by `surface()` and declares `Coefficients<T> {RigidBodyCoefficients<T> body; Surface<T>
/// surface;}` with `coefficients()`: its field then runs on lanes.
template <class Derived> class RigidBodyOnPlane : public ModelWithField<Derived, 16, 6> {
public:
  using Base = ModelWithField<Derived, 16, 6>;
  template <class S> using Vec = typename Base::template Vec<S>;
  template <class S> using V3 = Eigen::Matrix<S, 3, 1>;

  RigidBodyOnPlane(const ModelInfo& info, const ParameterValues& p, const RigidBodyConstants& c)
      : Base(info, p) {
    for (int k = 0; k < 9; ++k) {
      body_.inertia[static_cast<std::size_t>(k)] = c.inertia(k % 3, k / 3);
      body_.field[static_cast<std::size_t>(k)] = c.field(k % 3, k / 3);
    }
    body_.mass = c.mass, body_.gravity = c.gravity;
  }

  /// omega from M: M = I omega + m r x (omega x r).
  template <class S> V3<S> angularVelocity(const V3<S>& M, const V3<S>& r) const {
    return angularVelocityOf<S>(body_, ThreeVector<S>::from(M), ThreeVector<S>::from(r)).eigen();
  }
  template <class S, class T>
  [[gnu::always_inline]] static ThreeVector<S>
  angularVelocityOf(const RigidBodyCoefficients<T>& body, const ThreeVector<S>& M, const ThreeVector<S>& r) {
    ThreeMatrix<S> A = ThreeMatrix<S>::of(body.inertia);
    const S rr = dot(r, r);
    for (int i = 0; i < 3; ++i) {
      A(i, i) = A(i, i) + body.mass * rr;
      for (int j = 0; j < 3; ++j)
        A(i, j) = A(i, j) - body.mass * r[i] * r[j];
    }
    return A.solve(M);
  }

  /// (2) with the kinematics, of the body's coefficients and a surface that has contact<S>(gamma) and
  /// contactRate<S>(gamma, dgamma) on ThreeVector<S>: the one statement of the equations, for one body and
  /// for lanes of bodies (Coefficients<T>, T one value per lane). Written on ThreeVector, always inlined: the
  /// lane kernels compile it whole (ThreeVector.h says why).
  template <class S, class T, class Surface>
  [[gnu::always_inline]] static void equations(const RigidBodyCoefficients<T>& body, const Surface& surface,
                                               const Vec<S>& x, Vec<S>& dx) {
    using std::sqrt;
    using Three = ThreeVector<S>;
    const Three M{{x[0], x[1], x[2]}}, g{{x[3], x[4], x[5]}}, a{{x[6], x[7], x[8]}}, b{{x[9], x[10], x[11]}};
    const Three r = surface.template contact<S>(g);
    const Three w = angularVelocityOf<S>(body, M, r);
    const Three dg = cross(g, w);
    const Three dr = surface.template contactRate<S>(g, dg);
    const Three Bg = ThreeMatrix<S>::of(body.field) * g;
    const Three dM = cross(M, w) + body.mass * cross(dr, cross(w, r)) +
                     (body.mass * body.gravity) * cross(r, g) + cross(g, Bg); // (2)
    const Three da = cross(a, w), db = cross(b, w);
    for (int i = 0; i < 3; ++i) {
      dx[i] = dM[i];
      dx[3 + i] = dg[i];
      dx[6 + i] = da[i];
      dx[9 + i] = db[i];
    }
    const Three v = -cross(w, r); // velocity of the centre of mass, from the rolling constraint (1)
    dx[12] = dot(v, a);
    dx[13] = dot(v, b);
    // the contact point moves on the plane with ((alpha, r'), (beta, r')) and on the body with r'
    const S pa = dot(a, dr), pb = dot(b, dr);
    dx[14] = sqrt(pa * pa + pb * pb);
    dx[15] = sqrt(dot(dr, dr));
  }
  template <class S> void field(const Vec<S>& x, Vec<S>& dx) const {
    if constexpr (requires(const Derived& d) { d.surface(); })
      equations<S>(body_, self().surface(), x, dx);
    else
      equations<S>(body_, EigenSurface{self()}, x, dx);
  }
  /// The lanes' field (LaneField.h), for a Derived with Coefficients.
  template <class S, class C>
  [[gnu::always_inline]] static void field(const C& coefficients, const Vec<S>& x, Vec<S>& dx) {
    equations<S>(coefficients.body, coefficients.surface, x, dx);
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
    return -body_.mass * body_.gravity * r.dot(g) +
           0.5 * g.dot(Eigen::Map<const Eigen::Matrix3d>(body_.field.data()) * g);
  }

  std::optional<BodyPose> pose(const double* x) const override {
    BodyPose p;
    p.rotation.row(0) = Eigen::Vector3d(x[6], x[7], x[8]).transpose();
    p.rotation.row(1) = Eigen::Vector3d(x[9], x[10], x[11]).transpose();
    const Eigen::Vector3d g(x[3], x[4], x[5]);
    p.rotation.row(2) = g.transpose();
    const Eigen::Vector3d r = self().template contact<double>(g);
    p.centre = {x[12], x[13], -r.dot(g)}; // the centre of mass
    p.contact = p.centre + p.rotation * r;
    return p;
  }

  RigidBodyConstants constants() const {
    return {.inertia = Eigen::Map<const Eigen::Matrix3d>(body_.inertia.data()),
            .mass = body_.mass,
            .gravity = body_.gravity,
            .field = Eigen::Map<const Eigen::Matrix3d>(body_.field.data())};
  }
  /// The constants as the equations read them.
  const RigidBodyCoefficients<double>& body() const { return body_; }

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
  RigidBodyCoefficients<double> body_;

private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
  // a Derived whose contact<S> and contactRate<S> take and give Eigen vectors, as a surface of equations()
  struct EigenSurface {
    const Derived& body;
    template <class S> ThreeVector<S> contact(const ThreeVector<S>& g) const {
      return ThreeVector<S>::from(body.template contact<S>(g.eigen()));
    }
    template <class S> ThreeVector<S> contactRate(const ThreeVector<S>& g, const ThreeVector<S>& dg) const {
      return ThreeVector<S>::from(body.template contactRate<S>(g.eigen(), dg.eigen()));
    }
  };
};

} // namespace rv

#include "dynamics/models/RigidBodyOnPlane.inl"
