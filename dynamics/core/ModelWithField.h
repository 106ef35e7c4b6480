// ModelWithField.h -- CRTP base: a model writes its right-hand side once, as a template on the scalar
// type, and gets rhs() in double and an exact Jacobian through Eigen's forward-mode AutoDiff.
#pragma once
#include "dynamics/core/JetProgram.h"
#include "dynamics/core/LaneField.h"
#include "dynamics/core/Model.h"
#include "dynamics/core/Rk4Scheme.h"
#include "dynamics/core/TaylorTape.h"
#include "dynamics/core/ValueOf.h"

#include <algorithm>
#include <array>
#include <bit>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <unsupported/Eigen/AutoDiff>
#include <utility>
#include <vector>

namespace rv {

/// Derived must provide `template <class S> void field(const Vec<S>& x, Vec<S>& dx) const`. M is the core
/// dimension (the leading components that evolve on their own); it must equal info().coreDimension. A Derived
/// whose field has no branch on a value may declare `static constexpr bool kLaneField = true`: then its field
/// also runs on 4 or 8 states at once (LaneField.h).
///
/// A lane field of more than kInlinedFieldDimension components (the rolling bodies) is compiled only for the
/// counts of tangent directions the tools use most (one orbit: 1 and min(M, 6); lanes: 0 and 1, for AVX2 and
/// AVX-512) and recorded once as a JetProgram that runs every other count (one interpreter, compiled once,
/// giving the same bits): compiling the field for every lane width, count and instruction set had cost the
/// five rolling bodies 628 s of a cold build. A smaller field (Lorenz, Henon-Heiles) is compiled for all of
/// them, inlined: cheap to build, and the fastest.
///
/// Every virtual member is instantiated wherever the class is constructed: the compiled kernels make that
/// costly. A model constructed in
/// more than one file declares `extern template class ModelWithField<Derived, N, M>;` after its class and
/// defines it in its own .cpp (`template class ...;`), so that they are compiled once: the registry's one
/// list of models (BuiltinModels.cpp) had compiled every model's kernels again, 6 min at -O2 and 9 min under
/// ASan.
template <class Derived, int N, int M = N> class ModelWithField : public Model, public LaneField {
public:
  static constexpr int kDim = N;
  static constexpr int kCore = M;
  template <class S> using Vec = Eigen::Matrix<S, N, 1>;
  ModelWithField(const ModelInfo& info, const ParameterValues& params) : Model(info, params) {
    if (info.coreDimension != M || static_cast<int>(info.stateNames.size()) != N)
      throw std::logic_error(info.id + ": the state sizes of ModelWithField and ModelInfo disagree");
  }

  void rhs(const double* x, double* dx) const final;
  void jacobian(const double* x, double* jac) const final;

  /// Derivatives with respect to the core components only: cheaper when the kinematics add many components.
  void coreJacobian(const double* x, double* jac) const final;

  /// One pass of forward differentiation seeded with the tangent vectors: the values are f, the derivatives
  /// J V (compiled counts, or the recorded program; a small field beyond kMaxFixedVectors goes through the
  /// Jacobian, a recorded one and a large one in passes).
  void tangentRhs(const double* x, const double* V, int k, double* dx, double* dV) const final;

  /// RK4 on (x, V) in one loop, for 1 <= k <= min(M, kMaxFixedVectors): a small field inlined into steps of
  /// fixed size; a recorded one by JetEvaluator::rk4 (the stages' arithmetic in AVX2 registers around one
  /// compiled differentiation pass per stage).
  bool tangentRk4(double* x, double* V, int k, double h, long steps) const final;

  /// The lane kernel of 4 or 8 models of this class: their fields at once, in one AVX2 (4 lanes) or AVX-512
  /// (8 lanes) register per component where the CPU has it (without fused multiply-add: each lane rounds as
  /// the scalar path does), else in SSE2 pairs.
  std::unique_ptr<LaneKernel> laneKernel(const LaneModels& models) const final;

  /// Tangent vectors up to this many (and the core dimension) get code with their count fixed at compile
  /// time.
  static constexpr int kMaxFixedVectors = kJetDirections;

  /// The field evaluated on recording scalars: its Taylor expansion for the taylor integrator.
  void recordField(taylor::Tape& tape, const double* x) const final;

  /// Lane fields larger than this are run from their JetProgram (see the class comment).
  static constexpr int kInlinedFieldDimension = 4;

  /// The recorded program of such a field and its constants at this model's parameters (for tests).
  template <class D = Derived> const JetProgram& jetProgram() const {
    static_assert(recordedField(), "only a lane field larger than kInlinedFieldDimension is recorded");
    return *recorded<D>().program;
  }

private:
  // whether the derivatives and lanes come from the recorded program (only read in member bodies: Derived is
  // complete there)
  static constexpr bool recordedField() {
    if constexpr (requires { Derived::kLaneField; })
      return N > kInlinedFieldDimension;
    else
      return false;
  }
  // the program and its constants at this model's coefficients
  struct Recorded {
    std::shared_ptr<const JetProgram> program;
    std::vector<double> constants;
    JetEvaluator orbit; // the program on one orbit, with the counts of directions compiled for it
  };
  // (the members of the recorded path are templates: the explicit instantiation of a class that compiles its
  // field instead does not instantiate them)
  template <class D = Derived> const Recorded& recorded() const {
    std::call_once(recordedOnce_, [this] {
      auto r = std::make_unique<Recorded>();
      if constexpr (kCoefficients) {
        r->program = classProgram<D>(); // the coefficients are its inputs: one recording per class
        const auto values = coefficientValues<D>(self());
        r->constants = r->program->bindConstants({values.data()});
      } else {
        r->program = recordProgram<D>(this); // the parameters are numbers in it
        r->constants = r->program->bindConstants({nullptr});
      }
      r->orbit = {r->program.get(), r->constants.data(), 1, {}, static_cast<const D*>(this)};
      r->orbit.compiled[1] = &compiledOrbit<1, D>;
      r->orbit.compiled[kCompiledVectors] = &compiledOrbit<kCompiledVectors, D>;
      recorded_ = std::move(r);
    });
    return *recorded_;
  }
  template <class D = Derived> static std::shared_ptr<const JetProgram> classProgram() {
    static const std::shared_ptr<const JetProgram> program = recordProgram<D>(nullptr);
    return program;
  }
  // the field on recording scalars: of coefficients as inputs (model null), or of this model's parameters
  template <class D = Derived>
  static std::shared_ptr<const JetProgram> recordProgram(const ModelWithField* model) {
    using jet_recording::Var;
    auto program = std::make_shared<JetProgram>();
    if constexpr (kCoefficients) {
      (void)model;
      using All = typename D::template Coefficients<jet_recording::Constant>;
      constexpr int count = coefficientCount<D>();
      static_assert(sizeof(All) == count * sizeof(jet_recording::Constant),
                    "Coefficients<T> must hold members of type T only");
      JetRecording recording(*program, N, count);
      std::array<jet_recording::Constant, count> inputs;
      for (int i = 0; i < count; ++i)
        inputs[static_cast<std::size_t>(i)] = program->coefficient(i);
      const auto coefficients = std::bit_cast<All>(inputs);
      Vec<Var> xa, fa;
      for (int i = 0; i < N; ++i)
        xa[i] = program->input(i);
      D::field(coefficients, xa, fa);
      for (int i = 0; i < N; ++i)
        program->setOutput(i, fa[i]);
    } else {
      JetRecording recording(*program, N, 0);
      Vec<Var> xa, fa;
      for (int i = 0; i < N; ++i)
        xa[i] = program->input(i);
      model->self().field(xa, fa);
      for (int i = 0; i < N; ++i)
        program->setOutput(i, fa[i]);
    }
    program->finish();
    return program;
  }
  template <class D = Derived> static constexpr int coefficientCount() {
    return static_cast<int>(sizeof(typename D::template Coefficients<double>) / sizeof(double));
  }
  // a model's Coefficients as the doubles they hold
  template <class D = Derived> static auto coefficientValues(const D& model) {
    using One = typename D::template Coefficients<double>;
    static_assert(sizeof(One) == coefficientCount<D>() * sizeof(double),
                  "Coefficients<T> must hold members of type T only");
    return std::bit_cast<std::array<double, coefficientCount<D>()>>(static_cast<One>(model.coefficients()));
  }
  template <class D = Derived>
  std::unique_ptr<LaneKernel> recordedLaneKernel(const LaneModels& models) const {
    return models.size() == 4 ? recordedLaneKernelOf<4, D>(models) : recordedLaneKernelOf<8, D>(models);
  }
  template <int W, class D> std::unique_ptr<LaneKernel> recordedLaneKernelOf(const LaneModels& models) const {
    LaneSelves<W> lanes{};
    for (int l = 0; l < W; ++l) { // another class, or different parameters not read as Coefficients: no
      lanes[l] = dynamic_cast<const D*>(models[l]); // kernel
      if (!lanes[l]) return nullptr;
      if (!kCoefficients && lanes[l]->parameters().values() != parameters().values()) return nullptr;
    }
    // the field and one direction compiled for the CPU's vector extension; the rest from the program
    std::array<CompiledJets, kJetDirections + 1> compiled{};
    if (W == 8 ? cpuHasAvx512() : cpuHasAvx2()) {
      compiled[0] = &compiledLanes<W, 0, D>;
      compiled[1] = &compiledLanes<W, 1, D>;
    }
    if constexpr (kCoefficients) {
      std::vector<decltype(coefficientValues<D>(*lanes[0]))> values;
      std::vector<const double*> perLane;
      values.reserve(W);
      for (const D* lane : lanes)
        perLane.push_back(values.emplace_back(coefficientValues<D>(*lane)).data());
      const auto gathered = laneCoefficients<W>(lanes);
      return jetProgramLaneKernel(classProgram<D>(), classProgram<D>()->bindConstants(perLane), W, M,
                                  compiled, std::make_shared<const decltype(gathered)>(gathered));
    } else {
      const auto& r = recorded<D>();
      return jetProgramLaneKernel(
          r.program, r.program->bindConstants(std::vector<const double*>(W, nullptr)), W, M, compiled,
          std::shared_ptr<const void>(static_cast<const void*>(lanes[0]), [](const void*) {}));
    }
  }
  // The counts of directions compiled from the field itself (the rest run the program, which gives the same
  // bits): on one orbit 1 (MEGNO, the largest exponent) and kCompiledVectors (a full spectrum, Jacobians in
  // passes); on lanes 0 (trajectories) and 1 (a sweep's largest exponents and MEGNO). Each costs a compile of
  // the field; all of them the rolling bodies' 628 s (issue 64).
  static constexpr int kCompiledVectors = std::min(M, kJetDirections);
  // f and the derivatives along K directions of one orbit, the field compiled on Eigen's AutoDiff with K
  // derivatives (Jet's rules are AutoDiff's, so the bits are the program's; AutoDiff's lazy expressions
  // compute a sum of products' derivatives in one pass, half the time of Jet<double, K>'s temporaries at K =
  // 6): runJetProgram's layout at width 1
  template <int K, class D>
  [[gnu::flatten]] static void compiledOrbit(const void* model, const double* x, const double* V, int seeded,
                                             double* dx, double* dV, int differentiated) {
    // one direction of a recorded field (no branch on a value): Jet, a value and a derivative, in a third of
    // AutoDiff's compile time (for Lorenz, Jet<double, 3> ran at half AutoDiff's speed)
    if constexpr (K == 1 && recordedField()) {
      using J = Jet<double, K>;
      Vec<J> xa, fa;
      for (int i = 0; i < N; ++i)
        xa[i] = J::with(x[i], [&](int c) { return i < seeded ? V[c * seeded + i] : 0.0; });
      static_cast<const D*>(model)->field(xa, fa);
      for (int i = 0; i < N; ++i)
        dx[i] = fa[i].v;
      for (int c = 0; c < K; ++c)
        for (int i = 0; i < differentiated; ++i)
          dV[c * differentiated + i] = fa[i].d[static_cast<std::size_t>(c)];
    } else {
      using Derivatives = Eigen::Matrix<double, K, 1>;
      using AD = Eigen::AutoDiffScalar<Derivatives>;
      Vec<AD> xa, fa;
      // written in place: a seed written element by element and then copied whole (two 8-byte stores read as
      // one 16-byte load) missed store forwarding, half of Lorenz's spectrum time
      for (int i = 0; i < N; ++i) {
        xa[i].value() = x[i];
        for (int c = 0; c < K; ++c)
          xa[i].derivatives()[c] = i < seeded ? V[c * seeded + i] : 0.0;
      }
      static_cast<const D*>(model)->field(xa, fa);
      for (int i = 0; i < N; ++i)
        dx[i] = fa[i].value();
      for (int c = 0; c < K; ++c)
        for (int i = 0; i < differentiated; ++i)
          dV[c * differentiated + i] = fa[i].derivatives().size() ? fa[i].derivatives()[c] : 0.0;
    }
  }
  // the same on W lanes, compiled for AVX2 (4 lanes) or AVX-512 (8); `context` the lanes' gathered
  // Coefficients, or the model
  template <int W, int K, class D>
  [[gnu::always_inline]] static void lanesBody(const void* context, const double* x, const double* V,
                                               int seeded, double* dx, double* dV, int differentiated) {
    using L = LaneVector<W>;
    using J = Jet<L, K>;
    Vec<J> xa, fa;
    for (int i = 0; i < N; ++i)
      xa[i] = J::with(L::load(x + i * W),
                      [&](int c) { return i < seeded ? L::load(V + (c * seeded + i) * W) : L(0.0); });
    if constexpr (kCoefficients)
      D::field(*static_cast<const decltype(laneCoefficients<W>(LaneSelves<W>{}))*>(context), xa, fa);
    else
      static_cast<const D*>(context)->field(xa, fa);
    for (int i = 0; i < N; ++i)
      fa[i].v.store(dx + i * W);
    for (int c = 0; c < K; ++c)
      for (int i = 0; i < differentiated; ++i)
        fa[i].d[static_cast<std::size_t>(c)].store(dV + (c * differentiated + i) * W);
  }
  template <int W, int K, class D>
  static void compiledLanes(const void* context, const double* x, const double* V, int seeded, double* dx,
                            double* dV, int differentiated) {
    if constexpr (W == 8)
      lanesAvx512<K, D>(context, x, V, seeded, dx, dV, differentiated);
    else
      lanesAvx2<K, D>(context, x, V, seeded, dx, dV, differentiated);
  }
  template <int K, class D>
  [[gnu::target("avx2"), gnu::flatten, gnu::noinline]] static void
  lanesAvx2(const void* context, const double* x, const double* V, int seeded, double* dx, double* dV,
            int differentiated) {
    lanesBody<4, K, D>(context, x, V, seeded, dx, dV, differentiated);
  }
  template <int K, class D>
  [[gnu::target("avx512f"), gnu::flatten, gnu::noinline]] static void
  lanesAvx512(const void* context, const double* x, const double* V, int seeded, double* dx, double* dV,
              int differentiated) {
    lanesBody<8, K, D>(context, x, V, seeded, dx, dV, differentiated);
  }
  mutable std::once_flag recordedOnce_;
  mutable std::unique_ptr<const Recorded> recorded_;

  const Derived& self() const { return static_cast<const Derived&>(*this); }
  static constexpr bool kCoefficients = requires { typename Derived::template Coefficients<double>; };
  template <int W> using LaneSelves = std::array<const Derived*, W>;
  template <int W> std::unique_ptr<LaneKernel> laneKernelOf(const LaneModels& models) const {
    LaneSelves<W> lanes{};
    for (int l = 0; l < W; ++l) { // another class, or different parameters not read as Coefficients: no
      lanes[l] = dynamic_cast<const Derived*>(models[l]);
      if (!lanes[l]) return nullptr;
      if (!kCoefficients && lanes[l]->parameters().values() != parameters().values()) return nullptr;
    }
    const auto coefficients = laneCoefficients<W>(lanes);
    return std::make_unique<Kernel<W, std::remove_const_t<decltype(coefficients)>>>(*this, coefficients);
  }
  // what the field reads per lane: Derived::Coefficients<LaneVector<W>> gathered from the lanes' models
  // (Coefficients<T> holds T members only, so it is an array of them); nothing for a field without
  // Coefficients
  struct NoCoefficients {};
  template <int W> static auto laneCoefficients(const LaneSelves<W>& lanes) {
    if constexpr (kCoefficients) {
      using L = LaneVector<W>;
      using One = typename Derived::template Coefficients<double>;
      using All = typename Derived::template Coefficients<L>;
      constexpr std::size_t count = sizeof(One) / sizeof(double);
      static_assert(sizeof(One) == count * sizeof(double) && sizeof(All) == count * sizeof(L),
                    "Coefficients<T> must hold members of type T only");
      std::array<L, count> gathered;
      for (int l = 0; l < W; ++l) {
        const auto values = std::bit_cast<std::array<double, count>>(lanes[l]->coefficients());
        for (std::size_t i = 0; i < count; ++i)
          gathered[i].v[l] = values[i];
      }
      return std::bit_cast<All>(gathered);
    } else {
      (void)lanes;
      return NoCoefficients{};
    }
  }
  // f and J V of W states with K tangent vectors, component-major in TangentSystem's layout: the lane form of
  // compiledOrbit<K> (a field declared always_inline is compiled into the kernel's vector code: LaneField.h)
  template <int W, int K, class C>
  EIGEN_ALWAYS_INLINE void laneDirectional(const C& coefficients, const double* in, double* out) const {
    using L = LaneVector<W>;
    using J = Jet<L, K>;
    Vec<J> xa, fa;
    for (int i = 0; i < N; ++i)
      xa[i] = J::with(L::load(in + i * W),
                      [&](int c) { return i < M ? L::load(in + (N + c * M + i) * W) : L(0.0); });
    if constexpr (kCoefficients)
      Derived::field(coefficients, xa, fa);
    else
      self().field(xa, fa);
    for (int i = 0; i < N; ++i)
      fa[i].v.store(out + i * W);
    for (int c = 0; c < K; ++c)
      for (int i = 0; i < M; ++i)
        fa[i].d[c].store(out + (N + c * M + i) * W);
  }
  // JetEvaluator::rk4 on W orbits with the lanes' f and J V `rhs`: the same steps element by element
  // (rk4StepOnArrays)
  template <int W, int K, class Rhs>
  EIGEN_ALWAYS_INLINE static void laneRk4(const Rhs& rhs, double* y, double h, long steps) {
    constexpr long size = static_cast<long>(N + M * K) * W;
    std::vector<double> stages(static_cast<std::size_t>(7 * size)); // y0, f0, k2, k3, k4, tmp, y1
    double *y0 = stages.data(), *f0 = y0 + size, *k2 = f0 + size, *k3 = k2 + size, *k4 = k3 + size,
           *tmp = k4 + size, *y1 = tmp + size;
    std::copy(y, y + size, y0);
    for (long s = 0; s < steps; ++s) {
      rhs(y0, f0);
      rk4StepOnArrays<W>(rhs, h, size, y0, f0, k2, k3, k4, tmp, y1);
      std::swap(y0, y1);
    }
    std::copy(y0, y0 + size, y);
  }
  // W models' fields bound: their coefficients gathered once, the kernels compiled for the CPU's vector
  // extension (AVX2 for 4 lanes, AVX-512 for 8) and for baseline x86-64 (the models' fields and Jet's rules
  // inlined whole: Lanes.h, LaneField.h)
  template <int W, class C> class Kernel final : public LaneKernel {
  public:
    Kernel(const ModelWithField& model, const C& coefficients) : model_(model), coefficients_(coefficients) {}
    int width() const override { return W; }
    bool tangentRhs(const double* x, int k, double* out) const override {
      if (k == 0) return evaluate<0>(x, out), true; // the field alone
      return withFixedVectors(k, [&]<int K>() { evaluate<K>(x, out); });
    }
    bool tangentRk4(double* y, int k, double h, long steps) const override {
      return withFixedVectors(k, [&]<int K>() {
        if (steps == 0) return;
        if constexpr (W == 8) {
          if (cpuHasAvx512()) return rk4Avx512<K>(y, h, steps);
        } else {
          if (cpuHasAvx2()) return rk4Avx2<K>(y, h, steps);
        }
        rk4Baseline<K>(y, h, steps);
      });
    }

  private:
    // four lanes in AVX2 (whose target has no FMA), eight in AVX-512 (whose has: the project compiles with
    // -ffp-contract=off, so no product and sum are fused), else SSE2 pairs. The field is compiled once per
    // target and count of vectors, into these (noinline): the RK4 loops below call it for each stage rather
    // than inline it four times over -- a rolling body's field over jets of 8 lanes is large, and four copies
    // in each of its RK4 loops made its file take >15 min and 4 GB to compile under ThreadSanitizer. A small
    // system's field (Lorenz, Henon-Heiles) is inlined into the loops all the same: the call per stage cost
    // Lorenz's four lanes 27 % (360 -> 264 points/s, bench_sweep SweepLanesLyapunov/4).
    static constexpr bool kSmallField = N <= 4;
    template <int K> void evaluate(const double* x, double* out) const {
      if constexpr (W == 8) {
        if (cpuHasAvx512()) return rhsAvx512<K>(x, out);
      } else {
        if (cpuHasAvx2()) return rhsAvx2<K>(x, out);
      }
      rhsBaseline<K>(x, out);
    }
    template <int K> EIGEN_ALWAYS_INLINE void laneDirectional(const double* x, double* out) const {
      model_.template laneDirectional<W, K>(coefficients_, x, out);
    }
    template <int K>
    [[gnu::target("avx2"), gnu::flatten, gnu::noinline]] void rhsAvx2(const double* x, double* out) const {
      model_.template laneDirectional<W, K>(coefficients_, x, out);
    }
    template <int K>
    [[gnu::target("avx512f"), gnu::flatten, gnu::noinline]] void rhsAvx512(const double* x,
                                                                           double* out) const {
      model_.template laneDirectional<W, K>(coefficients_, x, out);
    }
    template <int K> [[gnu::flatten, gnu::noinline]] void rhsBaseline(const double* x, double* out) const {
      model_.template laneDirectional<W, K>(coefficients_, x, out);
    }
    template <int K>
    [[gnu::target("avx2"), gnu::flatten]] void rk4Avx2(double* y, double h, long steps) const {
      if constexpr (kSmallField)
        laneRk4<W, K>([this](const double* in, double* out) { laneDirectional<K>(in, out); }, y, h, steps);
      else
        laneRk4<W, K>([this](const double* in, double* out) { rhsAvx2<K>(in, out); }, y, h, steps);
    }
    template <int K>
    [[gnu::target("avx512f"), gnu::flatten]] void rk4Avx512(double* y, double h, long steps) const {
      if constexpr (kSmallField)
        laneRk4<W, K>([this](const double* in, double* out) { laneDirectional<K>(in, out); }, y, h, steps);
      else
        laneRk4<W, K>([this](const double* in, double* out) { rhsAvx512<K>(in, out); }, y, h, steps);
    }
    template <int K> [[gnu::flatten]] void rk4Baseline(double* y, double h, long steps) const {
      if constexpr (kSmallField)
        laneRk4<W, K>([this](const double* in, double* out) { laneDirectional<K>(in, out); }, y, h, steps);
      else
        laneRk4<W, K>([this](const double* in, double* out) { rhsBaseline<K>(in, out); }, y, h, steps);
    }
    const ModelWithField& model_;
    C coefficients_;
  };
  // calls body.template operator()<k>() when 1 <= k <= min(M, kMaxFixedVectors); false otherwise
  template <class Body> static bool withFixedVectors(int k, Body&& body) {
    return withCount<1, std::min(M, kMaxFixedVectors)>(k, std::forward<Body>(body));
  }
  // A large field compiled on AutoDiff (no recorded program: it branches on a value, as a model file's
  // generated C++ or a test's model) is compiled for the recorded path's counts only, 1 and kCompiledVectors:
  // other counts run the larger pass with zero directions added (JetEvaluator), Jacobians in passes -- two
  // instantiations of the field's pass instead of eight (all counts 1..6, the Jacobian and the core one)
  static constexpr bool plainLargeField() { return !recordedField() && N > kInlinedFieldDimension; }
  JetEvaluator compiledEvaluator() const {
    JetEvaluator e{nullptr, nullptr, 1, {}, static_cast<const Derived*>(this), N};
    e.compiled[1] = &compiledOrbit<1, Derived>;
    e.compiled[kCompiledVectors] = &compiledOrbit<kCompiledVectors, Derived>;
    return e;
  }
  // jac[i * size + j] = d f_i / d x_j for i, j < size (N: the Jacobian; M: the core one), by the orbit's
  // evaluator along the unit vectors, in passes of directions
  template <int size> static void jacobianInPasses(const JetEvaluator& orbit, const double* x, double* jac) {
    std::array<double, size * size> seeds{}, derivatives;
    std::array<double, N> values;
    for (int j = 0; j < size; ++j)
      seeds[static_cast<std::size_t>(j) * size + static_cast<std::size_t>(j)] = 1;
    orbit.run(size, x, seeds.data(), size, values.data(), derivatives.data(), size);
    for (int i = 0; i < size; ++i)
      for (int j = 0; j < size; ++j)
        jac[i * size + j] = derivatives[static_cast<std::size_t>(j) * size + static_cast<std::size_t>(i)];
  }
  // `steps` RK4 steps of one orbit and its K vectors, all of fixed size with a small field (at most
  // kInlinedFieldDimension components) inlined (what a hand-written variational system compiles to): its call
  // per stage through JetEvaluator::rk4 and its seeds' round trip through memory were three quarters of
  // Lorenz's spectrum time (bench README, LorenzSpectrum). rk4Step's operations are rk4StepOnArrays's element
  // by element: the same steps as JetEvaluator::rk4's and the lanes'.
  template <int K> [[gnu::flatten]] void orbitRk4(double* x, double* V, double h, long steps) const {
    using Y = Eigen::Matrix<double, N + M * K, 1>;
    using Tangents = Eigen::Matrix<double, M * K, 1>;
    Y y, f0, k2, k3, k4, tmp, y1;
    y.template head<N>() = Eigen::Map<const Vec<double>>(x);
    y.template tail<M * K>() = Eigen::Map<const Tangents>(V);
    const auto field = [this](const Y& in, Y& out) {
      if constexpr (requires { Derived::kLaneField; }) {
        using J = Jet<double, K>; // AutoDiff's rules (Lanes.h) on scalars the compiler keeps in registers
        Vec<J> xa, fa;
#pragma GCC unroll 16 // unrolled at -O2 too: the jets then stay in registers (bench README)
        for (int i = 0; i < N; ++i)
          xa[i] = J::with(in[i], [&](int c) { return i < M ? in[N + c * M + i] : 0.0; });
        self().field(xa, fa);
#pragma GCC unroll 16
        for (int i = 0; i < N; ++i)
          out[i] = fa[i].v;
#pragma GCC unroll 16
        for (int c = 0; c < K; ++c)
#pragma GCC unroll 16
          for (int i = 0; i < M; ++i)
            out[N + c * M + i] = fa[i].d[static_cast<std::size_t>(c)];
      } else { // a field that branches on a value (valueOf): on AutoDiff
        compiledOrbit<K, Derived>(this, in.data(), in.data() + N, M, out.data(), out.data() + N, M);
      }
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
  // `steps` RK4 steps of one orbit and its k vectors with `orbit`'s passes (JetEvaluator::rk4, whose stages
  // are rk4StepOnArrays's: each lane of a lane kernel steps as this)
  static void stepOrbit(const JetEvaluator& orbit, double* x, double* V, int k, double h, long steps) {
    if (steps == 0) return;
    std::vector<double> y(static_cast<std::size_t>(N + M * k));
    std::copy(x, x + N, y.begin());
    std::copy(V, V + M * k, y.begin() + N);
    orbit.rk4(k, M, y.data(), h, steps);
    std::copy(y.begin(), y.begin() + N, x);
    std::copy(y.begin() + N, y.end(), V);
  }
};

// The virtual members out of the class body: not inline, so that `extern template` keeps a file that
// constructs a model from compiling them (see above). Each takes the recorded program or the compiled field
// in branches of `if constexpr`, so that a recorded field never compiles the other.

template <class Derived, int N, int M>
void ModelWithField<Derived, N, M>::rhs(const double* x, double* dx) const {
  const Vec<double> in = Eigen::Map<const Vec<double>>(x);
  Vec<double> out;
  self().field(in, out);
  Eigen::Map<Vec<double>> result(dx);
  result = out;
}

template <class Derived, int N, int M>
void ModelWithField<Derived, N, M>::jacobian(const double* x, double* jac) const {
  if constexpr (recordedField()) {
    jacobianInPasses<N>(recorded().orbit, x, jac);
  } else if constexpr (plainLargeField()) {
    jacobianInPasses<N>(compiledEvaluator(), x, jac);
  } else {
    using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
    Vec<AD> xa, fa;
    for (int i = 0; i < N; ++i)
      xa[i] = AD(x[i], N, i);
    self().field(xa, fa);
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j)
        jac[i * N + j] = fa[i].derivatives()[j];
  }
}

template <class Derived, int N, int M>
void ModelWithField<Derived, N, M>::coreJacobian(const double* x, double* jac) const {
  if constexpr (recordedField()) {
    jacobianInPasses<M>(recorded().orbit, x, jac);
  } else if constexpr (plainLargeField()) {
    jacobianInPasses<M>(compiledEvaluator(), x, jac);
  } else {
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
}

template <class Derived, int N, int M>
void ModelWithField<Derived, N, M>::tangentRhs(const double* x, const double* V, int k, double* dx,
                                               double* dV) const {
  if constexpr (recordedField()) {
    recorded().orbit.run(k, x, V, M, dx, dV, M); // any k, in passes
  } else if constexpr (plainLargeField()) {
    compiledEvaluator().run(k, x, V, M, dx, dV, M); // any k, in passes
  } else {
    if (!withFixedVectors(k, [&]<int K>() { compiledOrbit<K, Derived>(this, x, V, M, dx, dV, M); }))
      Model::tangentRhs(x, V, k, dx, dV);
  }
}

template <class Derived, int N, int M>
bool ModelWithField<Derived, N, M>::tangentRk4(double* x, double* V, int k, double h, long steps) const {
  if constexpr (recordedField()) {
    if (isMap() || k < 1 || k > std::min(M, kMaxFixedVectors)) return false;
    stepOrbit(recorded().orbit, x, V, k, h, steps);
    return true;
  } else {
    if (isMap() || k < 1 || k > std::min(M, kMaxFixedVectors)) return false;
    if constexpr (plainLargeField()) // its passes called per stage, not inlined four times over
      stepOrbit(compiledEvaluator(), x, V, k, h, steps);
    else
      withFixedVectors(k, [&]<int K>() { orbitRk4<K>(x, V, h, steps); });
    return true;
  }
}

template <class Derived, int N, int M>
std::unique_ptr<LaneKernel> ModelWithField<Derived, N, M>::laneKernel(const LaneModels& models) const {
  if constexpr (requires { Derived::kLaneField; }) {
    if (isMap() || (models.size() != 4 && models.size() != 8)) return nullptr;
    if constexpr (recordedField())
      return recordedLaneKernel(models);
    else
      return models.size() == 4 ? laneKernelOf<4>(models) : laneKernelOf<8>(models);
  } else {
    (void)models;
    return nullptr;
  }
}

template <class Derived, int N, int M>
void ModelWithField<Derived, N, M>::recordField(taylor::Tape& tape, const double* x) const {
  taylor::Recording recording(tape, N);
  Vec<taylor::Var> xa, fa;
  for (int i = 0; i < N; ++i)
    xa[i] = tape.input(i, x[i]);
  self().field(xa, fa);
  for (int i = 0; i < N; ++i)
    tape.setOutput(i, fa[i]);
}

} // namespace rv
