// JetProgramKernels.cpp -- the interpreter of JetProgram: every instruction is the Jet operation it
// recorded (Lanes.h), on one orbit (Jet<double, K>) or on lanes (Jet<LaneVector<W>, K>), compiled here once
// for each K <= kJetDirections and, on lanes, for the CPU's vector extension (AVX2 for 4 lanes, AVX-512 for
// 8; without fused multiply-add, as everywhere: each lane rounds as one orbit does) and baseline x86-64.
#include "dynamics/core/JetProgram.h"
#include "dynamics/core/LaneField.h"
#include "dynamics/core/Lanes.h"
#include "dynamics/integrators/Rk4Scheme.h"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rv {
namespace {

template <class T> constexpr int widthOf() {
  if constexpr (std::is_same_v<T, double>)
    return 1;
  else
    return T::kWidth;
}
template <class T> [[gnu::always_inline]] inline T load(const double* p) {
  if constexpr (std::is_same_v<T, double>)
    return *p;
  else
    return T::load(p);
}
template <class T> [[gnu::always_inline]] inline void store(double* p, const T& v) {
  if constexpr (std::is_same_v<T, double>)
    *p = v;
  else
    v.store(p);
}

// where one run reads and writes (runJetProgram's layout)
struct Io {
  const double* constants;
  const double* x;
  const double* V;
  int seeded;
  double* dx;
  double* dV;
  int differentiated;
};

// the working slots of one thread for jets of type J (a program's run reuses them)
template <class J> J* slotsFor(const JetProgram& program) {
  thread_local std::vector<J> slots;
  if (slots.size() < static_cast<std::size_t>(program.slotCount()))
    slots.resize(static_cast<std::size_t>(program.slotCount()));
  return slots.data();
}

template <class T, int K>
[[gnu::always_inline]] inline void runBody(const JetProgram& program, const Io& io) {
  using J = Jet<T, K>;
  using Op = JetProgram::Op;
  constexpr int W = widthOf<T>();
  J* s = slotsFor<J>(program);
  const auto constant = [&](int c) { return load<T>(io.constants + static_cast<std::ptrdiff_t>(c) * W); };
  const auto& inputs = program.inputSlots();
  for (int i = 0; i < static_cast<int>(inputs.size()); ++i) {
    if (inputs[static_cast<std::size_t>(i)] < 0) continue;
    s[inputs[static_cast<std::size_t>(i)]] = J::with(load<T>(io.x + i * W), [&](int c) {
      return i < io.seeded ? load<T>(io.V + (c * io.seeded + i) * W) : T(0.0);
    });
  }
  for (const JetProgram::Instr& in : program.code()) {
    J& r = s[in.out];
    switch (in.op) {
    case Op::ConstJet:
      r = J::with(constant(in.a), [](int) { return T(0.0); });
      break;
    case Op::Add:
      r = s[in.a] + s[in.b];
      break;
    case Op::Sub:
      r = s[in.a] - s[in.b];
      break;
    case Op::Mul:
      r = s[in.a] * s[in.b];
      break;
    case Op::Div:
      r = s[in.a] / s[in.b];
      break;
    case Op::Neg:
      r = -s[in.a];
      break;
    case Op::AddC:
      r = s[in.a] + constant(in.b);
      break;
    case Op::SubC:
      r = s[in.a] - constant(in.b);
      break;
    case Op::CSub:
      r = constant(in.b) - s[in.a];
      break;
    case Op::MulC:
      r = s[in.a] * constant(in.b);
      break;
    case Op::DivC:
      r = s[in.a] / constant(in.b);
      break;
    case Op::CDiv:
      r = constant(in.b) / s[in.a];
      break;
    case Op::Sqrt:
      r = sqrt(s[in.a]);
      break;
    case Op::Sin:
      r = sin(s[in.a]);
      break;
    case Op::Cos:
      r = cos(s[in.a]);
      break;
    case Op::KeepC:
      r = keptWhereNonzero(constant(in.b), s[in.a]);
      break;
    }
  }
  const auto& outputs = program.outputSlots();
  for (int i = 0; i < static_cast<int>(outputs.size()); ++i) {
    const J& o = s[outputs[static_cast<std::size_t>(i)]];
    store(io.dx + i * W, o.v);
    if (i < io.differentiated)
      for (int c = 0; c < K; ++c)
        store(io.dV + (c * io.differentiated + i) * W, o.d[static_cast<std::size_t>(c)]);
  }
}

// the interpreter compiled for each target (noinline: the RK4 loop calls it per stage rather than holding
// four copies)
template <class T, int K>
[[gnu::noinline, gnu::flatten]] void runBaseline(const JetProgram& program, const Io& io) {
  runBody<T, K>(program, io);
}
template <class T, int K>
[[gnu::noinline, gnu::flatten, gnu::target("avx2")]] void runAvx2(const JetProgram& program, const Io& io) {
  runBody<T, K>(program, io);
}
template <class T, int K>
[[gnu::noinline, gnu::flatten, gnu::target("avx512f")]] void runAvx512(const JetProgram& program,
                                                                       const Io& io) {
  runBody<T, K>(program, io);
}

template <class T, int K> void run(const JetProgram& program, const Io& io) {
  if constexpr (widthOf<T>() == 8) {
    if (cpuHasAvx512()) return runAvx512<T, K>(program, io);
  } else if constexpr (widthOf<T>() == 4) {
    if (cpuHasAvx2()) return runAvx2<T, K>(program, io);
  }
  runBaseline<T, K>(program, io);
}

// body.template operator()<K>() for K = k in 0..kJetDirections
template <class Body> void withDirections(int k, Body&& body) {
  [&]<int... I>(std::integer_sequence<int, I...>) {
    ((I == k ? (body.template operator()<I>(), true) : false) || ...);
  }
  (std::make_integer_sequence<int, kJetDirections + 1>{});
}

template <class T> void runAt(const JetProgram& program, int k, const Io& io) {
  withDirections(k, [&]<int K>() { run<T, K>(program, io); });
}

template <class T>
void rk4(const JetProgram& program, const double* constants, int k, int core, double* y, double h,
         long steps) {
  constexpr int W = widthOf<T>();
  const int n = program.inputCount();
  const long size = static_cast<long>(n + core * k) * W;
  thread_local std::vector<double> stages;
  stages.resize(static_cast<std::size_t>(7 * size)); // y0, f0, k2, k3, k4, tmp, y1
  double *y0 = stages.data(), *f0 = y0 + size, *k2 = f0 + size, *k3 = k2 + size, *k4 = k3 + size,
         *tmp = k4 + size, *y1 = tmp + size;
  std::copy(y, y + size, y0);
  withDirections(k, [&]<int K>() {
    const auto field = [&](const double* in, double* out) {
      run<T, K>(program, {constants, in, in + n * W, core, out, out + n * W, core});
    };
    for (long s = 0; s < steps; ++s) {
      field(y0, f0);
      // elementwise, so any chunk of lanes gives each element's bits: 4 at a time for one orbit too
      rk4StepOnArrays<W == 1 ? 4 : W>(field, h, size, y0, f0, k2, k3, k4, tmp, y1);
      std::swap(y0, y1);
    }
  });
  std::copy(y0, y0 + size, y);
}

// a program's fields of W models bound together (LaneField.h)
class JetProgramLaneKernel final : public LaneKernel {
public:
  JetProgramLaneKernel(std::shared_ptr<const JetProgram> program, std::vector<double> constants, int width,
                       int core)
      : program_(std::move(program)), constants_(std::move(constants)), width_(width), core_(core) {}
  int width() const override { return width_; }
  bool tangentRhs(const double* x, int k, double* out) const override {
    if (k < 0 || k > maxVectors()) return false;
    const int n = program_->inputCount();
    runJetProgram(*program_, constants_.data(), width_, k, x, x + n * width_, core_, out, out + n * width_,
                  core_);
    return true;
  }
  bool tangentRk4(double* y, int k, double h, long steps) const override {
    if (k < 1 || k > maxVectors()) return false;
    if (steps > 0) rk4JetProgram(*program_, constants_.data(), width_, k, core_, y, h, steps);
    return true;
  }

private:
  int maxVectors() const { return std::min(core_, kJetDirections); }
  std::shared_ptr<const JetProgram> program_;
  std::vector<double> constants_;
  int width_, core_;
};

} // namespace

void runJetProgram(const JetProgram& program, const double* constants, int width, int k, const double* x,
                   const double* V, int seeded, double* dx, double* dV, int differentiated) {
  if (k < 0) throw std::logic_error("runJetProgram: a negative count of directions");
  // more directions than one pass carries: passes of kJetDirections (each computes the same values)
  for (int first = 0;; first += kJetDirections) {
    const int pass = std::min(k - first, kJetDirections);
    const Io io{constants,     x,  V + static_cast<std::ptrdiff_t>(first) * seeded * width,
                seeded,        dx, dV + static_cast<std::ptrdiff_t>(first) * differentiated * width,
                differentiated};
    if (width == 1)
      runAt<double>(program, pass, io);
    else if (width == 4)
      runAt<LaneVector<4>>(program, pass, io);
    else if (width == 8)
      runAt<LaneVector<8>>(program, pass, io);
    else
      throw std::logic_error("runJetProgram: a width of " + std::to_string(width));
    if (first + pass >= k) break;
  }
}

void rk4JetProgram(const JetProgram& program, const double* constants, int width, int k, int core, double* y,
                   double h, long steps) {
  if (k < 1 || k > kJetDirections) throw std::logic_error("rk4JetProgram: k out of 1..kJetDirections");
  if (width == 1)
    rk4<double>(program, constants, k, core, y, h, steps);
  else if (width == 4)
    rk4<LaneVector<4>>(program, constants, k, core, y, h, steps);
  else if (width == 8)
    rk4<LaneVector<8>>(program, constants, k, core, y, h, steps);
  else
    throw std::logic_error("rk4JetProgram: a width of " + std::to_string(width));
}

std::unique_ptr<LaneKernel> jetProgramLaneKernel(std::shared_ptr<const JetProgram> program,
                                                 std::vector<double> constants, int width, int core) {
  return std::make_unique<JetProgramLaneKernel>(std::move(program), std::move(constants), width, core);
}

} // namespace rv
