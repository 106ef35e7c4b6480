// ModelWithField.h -- CRTP base: a model writes its right-hand side once, as a template on the scalar
// type, and gets rhs() in double and an exact Jacobian through Eigen's forward-mode AutoDiff.
#pragma once
#include "dynamics/core/LaneField.h"
#include "dynamics/core/Model.h"
#include "dynamics/core/TaylorTape.h"
#include "dynamics/integrators/Rk4Scheme.h"

#include <algorithm>
#include <stdexcept>
#include <unsupported/Eigen/AutoDiff>
#include <utility>

namespace rv {

/// The plain value of a scalar that may carry derivatives (for branch decisions such as wrapping an angle).
inline double valueOf(double v) {
  return v;
}
template <class D> double valueOf(const Eigen::AutoDiffScalar<D>& v) {
  return v.value();
}

/// Derived must provide `template <class S> void field(const Vec<S>& x, Vec<S>& dx) const`. M is the core
/// dimension (the leading components that evolve on their own); it must equal info().coreDimension. A Derived
/// whose field has no branch on a value may declare `static constexpr bool kLaneField = true`: then its field
/// also runs on kLanes states at once (LaneField.h).
template <class Derived, int N, int M = N> class ModelWithField : public Model, public LaneField {
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

  /// One pass of forward AutoDiff seeded with the tangent vectors (derivative vectors of fixed size for up to
  /// kMaxFixedVectors; more go through the Jacobian): the values are f, the derivatives J V.
  void tangentRhs(const double* x, const double* V, int k, double* dx, double* dV) const final {
    if (!withFixedVectors(k, [&]<int K>() { directional<K>(x, V, dx, dV); }))
      Model::tangentRhs(x, V, k, dx, dV);
  }

  /// RK4 on (x, V) with the state, the stages and the AutoDiff pass all of fixed size and inlined: what a
  /// hand-written variational system compiles to (Boost.Odeint's chaotic_system example), from the one field.
  bool tangentRk4(double* x, double* V, int k, double h, long steps) const final {
    return !isMap() && withFixedVectors(k, [&]<int K>() { fusedRk4<K>(x, V, h, steps); });
  }

  /// f and J w at kLanes states at once, in one AVX2 register per component where the CPU has AVX2 (compiled
  /// for it without FMA: each lane rounds as the scalar path does), else as SSE2 pairs.
  bool laneTangentRhs(const double* x, double* out) const final {
    if constexpr (requires { Derived::kLaneField; }) {
      if (cpuHasAvx2())
        laneKernelAvx2(x, out);
      else
        laneKernelBaseline(x, out);
      return true;
    } else {
      (void)x, (void)out;
      return false;
    }
  }

  /// Tangent vectors up to this many (and the core dimension) get code with their count fixed at compile
  /// time.
  static constexpr int kMaxFixedVectors = 6;

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
  [[gnu::target("avx2"), gnu::flatten]] void laneKernelAvx2(const double* x, double* out) const {
    laneKernel(x, out);
  }
  [[gnu::flatten]] void laneKernelBaseline(const double* x, double* out) const { laneKernel(x, out); }
  EIGEN_ALWAYS_INLINE void laneKernel(const double* x, double* out) const {
    using J = Jet<Lanes>;
    Vec<J> xa, fa;
    for (int i = 0; i < N; ++i)
      xa[i] = J(Lanes::load(x + i * kLanes), i < M ? Lanes::load(x + (N + i) * kLanes) : Lanes(0.0));
    self().field(xa, fa);
    for (int i = 0; i < N; ++i)
      fa[i].v.store(out + i * kLanes);
    for (int i = 0; i < M; ++i)
      fa[i].d.store(out + (N + i) * kLanes);
  }
  // calls body.template operator()<k>() when 1 <= k <= min(M, kMaxFixedVectors); false otherwise
  template <class Body> static bool withFixedVectors(int k, Body&& body) {
    return [&]<int... I>(std::integer_sequence<int, I...>) {
      return ((I + 1 == k ? (body.template operator()<I + 1>(), true) : false) || ...);
    }
    (std::make_integer_sequence<int, std::min(M, kMaxFixedVectors)>{});
  }
  template <int K> void fusedRk4(double* x, double* V, double h, long steps) const {
    using Y = Eigen::Matrix<double, N + M * K, 1>;
    using Tangents = Eigen::Matrix<double, M * K, 1>;
    Y y, f0, k2, k3, k4, tmp, y1;
    y.template head<N>() = Eigen::Map<const Vec<double>>(x);
    y.template tail<M * K>() = Eigen::Map<const Tangents>(V);
    const auto field = [this](const Y& in, Y& out) {
      directional<K>(in.data(), in.data() + N, out.data(), out.data() + N);
    };
    for (long s = 0; s < steps; ++s) {
      field(y, f0);
      rk4Step(field, h, y, f0, k2, k3, k4, tmp, y1);
      y = y1;
    }
    Eigen::Map<Vec<double>> xOut(x);
    Eigen::Map<Tangents> vOut(V);
    xOut = y.template head<N>();
    vOut = y.template tail<M * K>();
  }
  template <int K>
  EIGEN_ALWAYS_INLINE void directional(const double* x, const double* V, double* dx, double* dV) const {
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
