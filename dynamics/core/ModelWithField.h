// ModelWithField.h -- CRTP base: a model writes its right-hand side once, as a template on the scalar
// type, and gets rhs() in double and an exact Jacobian through Eigen's forward-mode AutoDiff.
#pragma once
#include "dynamics/core/Model.h"
#include "dynamics/core/TaylorTape.h"

#include <stdexcept>
#include <unsupported/Eigen/AutoDiff>

namespace rv {

/// The plain value of a scalar that may carry derivatives (for branch decisions such as wrapping an angle).
inline double valueOf(double v) {
  return v;
}
template <class D> double valueOf(const Eigen::AutoDiffScalar<D>& v) {
  return v.value();
}

/// Derived must provide `template <class S> void field(const Vec<S>& x, Vec<S>& dx) const`. M is the core
/// dimension (the leading components that evolve on their own); it must equal info().coreDimension.
template <class Derived, int N, int M = N> class ModelWithField : public Model {
public:
  static constexpr int kDim = N;
  static constexpr int kCore = M;
  template <class S> using Vec = Eigen::Matrix<S, N, 1>;
  ModelWithField(const ModelInfo& info, const ParameterValues& params) : Model(info, params) {
    if (info.coreDimension != M || static_cast<int>(info.stateNames.size()) != N)
      throw std::logic_error(info.id + ": the state sizes of ModelWithField and ModelInfo disagree");
  }

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
    for (int i = 0; i < N; ++i)
      xa[i] = AD(x[i], N, i);
    self().field(xa, fa);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        jac[i * N + j] = fa[i].derivatives()[j];
  }

  /// Derivatives with respect to the core components only: cheaper when the kinematics add many components.
  void coreJacobian(const double* x, double* jac) const final {
    using D = Eigen::Matrix<double, M, 1>; // M derivatives, fixed size: no heap, unrolled
    using AD = Eigen::AutoDiffScalar<D>;
    Vec<AD> xa, fa;
    for (int i = 0; i < N; ++i)
      xa[i] = i < M ? AD(x[i], M, i) : AD(x[i], D::Zero());
    self().field(xa, fa);
    for (int i = 0; i < M; ++i)
      for (int j = 0; j < M; ++j)
        jac[i * M + j] = fa[i].derivatives()[j];
  }

  /// One pass of forward AutoDiff seeded with the tangent vectors (fixed sizes for the 1-3 vectors of map
  /// derivatives; more go through the Jacobian): the values are f, the derivatives J V.
  void tangentRhs(const double* x, const double* V, int k, double* dx, double* dV) const final {
    switch (k) {
    case 1:
      return directional<1>(x, V, dx, dV);
    case 2:
      return directional<2>(x, V, dx, dV);
    case 3:
      return directional<3>(x, V, dx, dV);
    default:
      return Model::tangentRhs(x, V, k, dx, dV);
    }
  }

  /// The field evaluated on recording scalars: its Taylor expansion for the taylor integrator.
  void recordField(taylor::Tape& tape, const double* x) const final {
    taylor::Recording recording(tape, N);
    Vec<taylor::Var> xa, fa;
    for (int i = 0; i < N; ++i)
      xa[i] = tape.input(i, x[i]);
    self().field(xa, fa);
    for (int i = 0; i < N; ++i)
      tape.setOutput(i, fa[i]);
  }

private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
  template <int K> void directional(const double* x, const double* V, double* dx, double* dV) const {
    using D = Eigen::Matrix<double, K, 1>;
    using AD = Eigen::AutoDiffScalar<D>;
    Vec<AD> xa, fa;
    for (int i = 0; i < N; ++i) {
      D seed = D::Zero();
      if (i < M)
        for (int c = 0; c < K; ++c)
          seed[c] = V[c * M + i];
      xa[i] = AD(x[i], seed);
    }
    self().field(xa, fa);
    for (int i = 0; i < N; ++i)
      dx[i] = fa[i].value();
    for (int i = 0; i < M; ++i)
      for (int c = 0; c < K; ++c)
        dV[c * M + i] = fa[i].derivatives().size() ? fa[i].derivatives()[c] : 0.0;
  }
};

} // namespace rv
