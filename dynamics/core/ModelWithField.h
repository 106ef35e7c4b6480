// ModelWithField.h -- CRTP base: a model writes its right-hand side once, as a template on the scalar
// type, and gets rhs() in double and an exact Jacobian through Eigen's forward-mode AutoDiff.
#pragma once
#include "dynamics/core/Model.h"

#include <unsupported/Eigen/AutoDiff>

namespace rv {

/// The plain value of a scalar that may carry derivatives (for branch decisions such as wrapping an angle).
inline double valueOf(double v) { return v; }
template <class D> double valueOf(const Eigen::AutoDiffScalar<D>& v) { return v.value(); }

/// Derived must provide `template <class S> void field(const Vec<S>& x, Vec<S>& dx) const`.
template <class Derived, int N> class ModelWithField : public Model {
public:
  static constexpr int kDim = N;
  template <class S> using Vec = Eigen::Matrix<S, N, 1>;
  using Model::Model;

  void rhs(const double* x, double* dx) const final {
    const Vec<double> in = Eigen::Map<const Vec<double>>(x);
    Vec<double> out;
    self().field(in, out);
    Eigen::Map<Vec<double>> result(dx);
    result = out;
  }

  void jacobian(const double* x, double* jac) const final {
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
    Vec<AD> xa, fa;
    for (int i = 0; i < N; ++i) xa[i] = AD(x[i], N, i);
    self().field(xa, fa);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) jac[i * N + j] = fa[i].derivatives()[j];
  }

  /// Derivatives with respect to the core components only: cheaper when the kinematics add many components.
  void coreJacobian(const double* x, double* jac) const final {
    using D = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, N, 1>; // no heap: at most N derivatives
    using AD = Eigen::AutoDiffScalar<D>;
    const int m = this->info().coreDimension;
    Vec<AD> xa, fa;
    for (int i = 0; i < N; ++i) xa[i] = i < m ? AD(x[i], m, i) : AD(x[i], D::Zero(m));
    self().field(xa, fa);
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) jac[i * m + j] = fa[i].derivatives().size() ? fa[i].derivatives()[j] : 0.0;
  }

private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

} // namespace rv
