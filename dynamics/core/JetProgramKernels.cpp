// JetProgramKernels.cpp -- the interpreter of JetProgram: every instruction is the Jet operation it
// recorded (Lanes.h), on one orbit (Jet<double, K>) or on lanes (Jet<LaneVector<W>, K>), compiled here once
// for each K <= kJetDirections and, on lanes, for the CPU's vector extension (AVX2 for 4 lanes, AVX-512 for
// 8; without fused multiply-add, as everywhere: each lane rounds as one orbit does) and baseline x86-64.
#include "dynamics/core/JetProgram.h"
#include "dynamics/core/LaneField.h"
#include "dynamics/core/Lanes.h"
#include "dynamics/core/Rk4Scheme.h"

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
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

template <class T> void interpret(const JetProgram& program, int k, const Io& io) {
  withCount<0, kJetDirections>(k, [&]<int K>() { run<T, K>(program, io); });
}

// one pass of at most kJetDirections directions: compiled, or the program
void pass(const JetEvaluator& e, int k, const Io& io) {
  if (const CompiledJets compiled = e.compiled[static_cast<std::size_t>(k)])
    return compiled(e.context, io.x, io.V, io.seeded, io.dx, io.dV, io.differentiated);
  if (!e.program) { // the next count compiled, with zero directions added and their derivatives dropped
    for (int more = k + 1; more <= kJetDirections; ++more)
      if (const CompiledJets compiled = e.compiled[static_cast<std::size_t>(more)]) {
        const auto block = [&](int count, int per) {
          return static_cast<std::size_t>(count) * static_cast<std::size_t>(per * e.width);
        };
        thread_local std::vector<double> seeds, derivatives;
        seeds.assign(block(more, io.seeded), 0.0);
        std::copy(io.V, io.V + block(k, io.seeded), seeds.begin());
        derivatives.resize(block(more, io.differentiated));
        compiled(e.context, io.x, seeds.data(), io.seeded, io.dx, derivatives.data(), io.differentiated);
        std::copy(derivatives.begin(),
                  derivatives.begin() + static_cast<std::ptrdiff_t>(block(k, io.differentiated)), io.dV);
        return;
      }
    throw std::logic_error("JetEvaluator: no program and no compiled form for " + std::to_string(k));
  }
  if (e.width == 1)
    interpret<double>(*e.program, k, io);
  else if (e.width == 4)
    interpret<LaneVector<4>>(*e.program, k, io);
  else if (e.width == 8)
    interpret<LaneVector<8>>(*e.program, k, io);
  else
    throw std::logic_error("JetEvaluator: a width of " + std::to_string(e.width));
}

// the RK4 loop of rk4JetProgram, with the stages' arithmetic compiled for W's vector extension
template <int W, class Field>
[[gnu::always_inline]] inline void rk4Loop(const Field& field, long size, double* y0, double* f0, double* k2,
                                           double* k3, double* k4, double* tmp, double* y1, double h,
                                           long steps, double*& result) {
  for (long s = 0; s < steps; ++s) {
    field(y0, f0);
    rk4StepOnArrays<W>(field, h, size, y0, f0, k2, k3, k4, tmp, y1);
    std::swap(y0, y1);
  }
  result = y0;
}
template <class Field>
[[gnu::target("avx2")]] void rk4LoopAvx2(const Field& field, long size, double* y0, double* f0, double* k2,
                                         double* k3, double* k4, double* tmp, double* y1, double h,
                                         long steps, double*& result) {
  rk4Loop<4>(field, size, y0, f0, k2, k3, k4, tmp, y1, h, steps, result);
}
template <class Field>
[[gnu::target("avx512f")]] void rk4LoopAvx512(const Field& field, long size, double* y0, double* f0,
                                              double* k2, double* k3, double* k4, double* tmp, double* y1,
                                              double h, long steps, double*& result) {
  rk4Loop<8>(field, size, y0, f0, k2, k3, k4, tmp, y1, h, steps, result);
}

// a program's fields of W models bound together (LaneField.h)
class JetProgramLaneKernel final : public LaneKernel {
public:
  JetProgramLaneKernel(std::shared_ptr<const JetProgram> program, std::vector<double> constants, int width,
                       int core, const std::array<CompiledJets, kJetDirections + 1>& compiled,
                       std::shared_ptr<const void> context)
      : program_(std::move(program)), constants_(std::move(constants)), context_(std::move(context)),
        core_(core) {
    evaluator_ = {program_.get(), constants_.data(), width, compiled, context_.get()};
  }
  int width() const override { return evaluator_.width; }
  bool compiledFor(int k) const override {
    return k >= 0 && k <= kJetDirections && evaluator_.compiled[static_cast<std::size_t>(k)] != nullptr;
  }
  bool tangentRhs(const double* x, int k, double* out) const override {
    if (k < 0 || k > maxVectors()) return false;
    const int n = program_->inputCount() * evaluator_.width;
    evaluator_.run(k, x, x + n, core_, out, out + n, core_);
    return true;
  }
  bool tangentRk4(double* y, int k, double h, long steps) const override {
    if (k < 1 || k > maxVectors()) return false;
    if (steps > 0) evaluator_.rk4(k, core_, y, h, steps);
    return true;
  }

private:
  int maxVectors() const { return std::min(core_, kJetDirections); }
  std::shared_ptr<const JetProgram> program_;
  std::vector<double> constants_;
  std::shared_ptr<const void> context_;
  int core_;
  JetEvaluator evaluator_;
};

} // namespace

void JetEvaluator::run(int k, const double* x, const double* V, int seeded, double* dx, double* dV,
                       int differentiated) const {
  if (k < 0) throw std::logic_error("JetEvaluator: a negative count of directions");
  // more directions than one pass carries: passes of kJetDirections (each computes the same values)
  for (int first = 0;; first += kJetDirections) {
    const int count = std::min(k - first, kJetDirections);
    pass(*this, count,
         {constants, x, V + static_cast<std::ptrdiff_t>(first) * seeded * width, seeded, dx,
          dV + static_cast<std::ptrdiff_t>(first) * differentiated * width, differentiated});
    if (first + count >= k) break;
  }
}

void JetEvaluator::rk4(int k, int core, double* y, double h, long steps) const {
  if (k < 1 || k > kJetDirections) throw std::logic_error("JetEvaluator::rk4: k out of 1..kJetDirections");
  const int inputs = program ? program->inputCount() : dimension;
  const int n = inputs * width;
  const long size = static_cast<long>(inputs + core * k) * width;
  thread_local std::vector<double> stages;
  stages.resize(static_cast<std::size_t>(7 * size)); // y0, f0, k2, k3, k4, tmp, y1
  double *y0 = stages.data(), *f0 = y0 + size, *k2 = f0 + size, *k3 = k2 + size, *k4 = k3 + size,
         *tmp = k4 + size, *y1 = tmp + size, *result = y0;
  std::copy(y, y + size, y0);
  const auto field = [&](const double* in, double* out) {
    pass(*this, k, {constants, in, in + n, core, out, out + n, core});
  };
  // elementwise, so any chunk of elements gives each element's bits: one orbit four at a time too
  if (width == 8 && cpuHasAvx512())
    rk4LoopAvx512(field, size, y0, f0, k2, k3, k4, tmp, y1, h, steps, result);
  else if (width == 8)
    rk4Loop<8>(field, size, y0, f0, k2, k3, k4, tmp, y1, h, steps, result);
  else if (cpuHasAvx2())
    rk4LoopAvx2(field, size, y0, f0, k2, k3, k4, tmp, y1, h, steps, result);
  else
    rk4Loop<4>(field, size, y0, f0, k2, k3, k4, tmp, y1, h, steps, result);
  std::copy(result, result + size, y);
}

void runJetProgram(const JetProgram& program, const double* constants, int width, int k, const double* x,
                   const double* V, int seeded, double* dx, double* dV, int differentiated) {
  JetEvaluator{&program, constants, width}.run(k, x, V, seeded, dx, dV, differentiated);
}

void rk4JetProgram(const JetProgram& program, const double* constants, int width, int k, int core, double* y,
                   double h, long steps) {
  JetEvaluator{&program, constants, width}.rk4(k, core, y, h, steps);
}

std::unique_ptr<LaneKernel> jetProgramLaneKernel(std::shared_ptr<const JetProgram> program,
                                                 std::vector<double> constants, int width, int core,
                                                 const std::array<CompiledJets, kJetDirections + 1>& compiled,
                                                 std::shared_ptr<const void> context) {
  return std::make_unique<JetProgramLaneKernel>(std::move(program), std::move(constants), width, core,
                                                compiled, std::move(context));
}

} // namespace rv
