// JetProgram.h -- a model's field recorded once as straight-line code of Jet operations (Lanes.h), then run
// by one compiled interpreter (JetProgramKernels.cpp) on one orbit or on 4 or 8 lanes, with the derivatives
// along up to 6 directions at a time: the tangent vectors, the Jacobian and the lane kernels of the large
// templated fields (the rolling bodies) without compiling each field once per lane width, count of vectors
// and instruction set. Those instantiations took 628 s of a 20-minute cold build (issue 64); the program
// costs one instantiation of the field on the recording scalars below.
//
// Each recorded instruction is one operation of Jet's, in the order the field performs it, with Jet's own
// rule (the interpreter calls Jet's operators), so a run gives what the field compiled on Jet gives, bit for
// bit: on lanes, each lane is the model's own run. Coefficients (one value per lane: a sweep's parameters)
// are inputs of their own; what the field computes from them alone is computed once when a kernel is bound
// (the same operations, on each lane's values), not at every evaluation. The field must not branch on a
// value: the recording scalars have none (a model declares kLaneField for such a field, ModelWithField.h).
// The design follows heyoka's decomposition of a system into elementary operations compiled once (F. Biscani,
// D. Izzo, MNRAS 504 (2021) 2614), here into a flat program as the Taylor tape does (TaylorTape.h).
#pragma once
#include "dynamics/core/HeldScalar.h"

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace rv {

class JetProgram;

namespace jet_recording {

/// The program being recorded on this thread (set by JetRecording), or null.
inline thread_local JetProgram* active = nullptr;

/// A recorded value without derivatives -- a coefficient, a number, or what the field computes from them --
/// as LaneVector is on lanes: an index into the program's constants.
struct Constant {
  int id = -1;
  Constant() = default;
  Constant(double number); // NOLINT(google-explicit-constructor): a number in every lane, as LaneVector's
  explicit Constant(int constant, std::nullptr_t) : id(constant) {}
  Constant& operator+=(const Constant& o);
  Constant& operator-=(const Constant& o);
  Constant& operator*=(const Constant& o);
  Constant& operator/=(const Constant& o);
};

/// A recorded value with derivatives, as Jet is: an index into the program's nodes. Constructed from a
/// number or a Constant it is a jet with zero derivatives (Jet's constructors), which the operations then
/// treat as a jet -- as the compiled field does.
struct Var {
  int id = -1;
  Var() = default;
  Var(double number); // NOLINT(google-explicit-constructor): a constant jet, as Jet's
  explicit Var(const Constant& value);
  explicit Var(int node, std::nullptr_t) : id(node) {}
  Var& operator+=(const Var& o);
  Var& operator-=(const Var& o);
  Var& operator*=(const Var& o);
  Var& operator/=(const Var& o);
};

/// A constant operand of a Var: a number or a Constant (Jet's JetConstant).
template <class C>
concept ConstantOperand = std::is_arithmetic_v<C> || std::is_same_v<C, Constant>;

} // namespace jet_recording

/// The recorded operations of one field and where the interpreter keeps their values.
class JetProgram {
public:
  /// Jet operations: on nodes (a, b), or on a node a and a constant b (the C forms: a + c, a - c, c - a,
  /// a * c, a / c, c / a). ConstJet makes the jet of constant a with zero derivatives; KeepC is a where
  /// constant b is not 0, else 0 (Lanes.h's keptWhereNonzero).
  enum class Op : std::uint8_t {
    ConstJet,
    Add,
    Sub,
    Mul,
    Div,
    Neg,
    AddC,
    SubC,
    CSub,
    MulC,
    DivC,
    CDiv,
    Sqrt,
    Sin,
    Cos,
    KeepC
  };
  /// Operations on constants, computed lane by lane when a kernel is bound.
  enum class ConstantOp : std::uint8_t { Number, Coefficient, Add, Sub, Mul, Div, Neg, Sqrt, Sin, Cos };

  /// One compiled instruction: out and a are slots (a is a constant for ConstJet), b a slot or, in the C
  /// forms, a constant.
  struct Instr {
    Op op;
    int out, a, b;
  };

  /// Starts a recording of a field of `inputs` state components reading `coefficients` coefficients.
  void begin(int inputs, int coefficients);
  /// Input i (a state component).
  jet_recording::Var input(int i) const { return jet_recording::Var(i, nullptr); }
  /// Coefficient i.
  jet_recording::Constant coefficient(int i);
  /// A number (one constant per distinct value).
  jet_recording::Constant number(double value);
  jet_recording::Constant constant(ConstantOp op, int a, int b = -1);
  jet_recording::Var jet(Op op, int a, int b = -1);
  /// Output i of the field.
  void setOutput(int i, const jet_recording::Var& v);
  /// Ends the recording: drops what no output uses and gives the nodes slots, a slot used again once its
  /// value is dead (the working set of a rolling body's field stays in the first-level cache). Throws
  /// std::logic_error when an output was not written.
  void finish();

  int inputCount() const { return inputs_; }
  int outputCount() const { return static_cast<int>(outputs_.size()); }
  int coefficientCount() const { return coefficients_; }
  int constantCount() const { return static_cast<int>(constants_.size()); }
  int slotCount() const { return slots_; }
  /// Slot of input i (-1: unused).
  const std::vector<int>& inputSlots() const { return inputSlots_; }
  const std::vector<int>& outputSlots() const { return outputSlots_; }
  const std::vector<Instr>& code() const { return code_; }

  /// The constants of `width` lanes whose coefficients are coefficientsOfLane[l] (coefficientCount() each),
  /// component-major: values[c * width + l].
  std::vector<double> bindConstants(const std::vector<const double*>& coefficientsOfLane) const;

private:
  struct ConstantNode {
    ConstantOp op;
    int a, b;
    double number;
  };
  struct Node {
    Op op;
    int a, b; // nodes, or constants where the operation takes one
  };
  int inputs_ = 0, coefficients_ = 0, slots_ = 0;
  std::vector<ConstantNode> constants_;
  std::unordered_map<std::uint64_t, int> numbers_; // by the bits of the value
  std::vector<Node> nodes_;                        // the inputs, then the recorded operations
  std::vector<int> outputs_, inputSlots_, outputSlots_;
  std::vector<Instr> code_;
};

/// Makes a program the one recorded on this thread for its lifetime.
class JetRecording {
public:
  JetRecording(JetProgram& program, int inputs, int coefficients) : previous_(jet_recording::active) {
    program.begin(inputs, coefficients);
    jet_recording::active = &program;
  }
  ~JetRecording() { jet_recording::active = previous_; }
  JetRecording(const JetRecording&) = delete;
  JetRecording& operator=(const JetRecording&) = delete;

private:
  JetProgram* previous_;
};

/// The most directions one pass of the interpreter carries (more are taken in passes of this many).
inline constexpr int kJetDirections = 6;

/// body.template operator()<K>() for the K in [First, Last] equal to k; false where k is outside (the counts
/// of directions a compiled kernel has, chosen at run time).
template <int First, int Last, class Body> bool withCount(int k, Body&& body) {
  return [&]<int... I>(std::integer_sequence<int, I...>) {
    return ((First + I == k ? (body.template operator()<First + I>(), true) : false) || ...);
  }
  (std::make_integer_sequence<int, Last - First + 1>{});
}

/// A field compiled for one count of directions (ModelWithField compiles the counts the tools use most, the
/// program runs the rest): runJetProgram's arguments, `context` what the compiled field reads (its model, or
/// its lanes' coefficients). It must give the program's bits (JetProgramTest holds them to it).
using CompiledJets = void (*)(const void* context, const double* x, const double* V, int seeded, double* dx,
                              double* dV, int differentiated);

/// A program with its constants bound for `width` lanes (1, 4 or 8), and the counts of directions compiled
/// from the field itself, which run in its place.
struct JetEvaluator {
  const JetProgram* program = nullptr; ///< null: compiled counts only
  const double* constants = nullptr;
  int width = 1;
  /// By count of directions; null: the program, or without one the next count compiled (zero directions
  /// added, their derivatives dropped: the same bits).
  std::array<CompiledJets, kJetDirections + 1> compiled{};
  const void* context = nullptr;
  int dimension = 0; ///< the field's components, where there is no program

  /// At `width` states, component-major (x[i * width + l]): dx = f(x) and, for k directions whose seeds are
  /// V[(c * seeded + i) * width + l] for the first `seeded` inputs (the others have none),
  /// dV[(c * differentiated + i) * width + l] = the derivative of output i < `differentiated` along direction
  /// c. Any k: more than kJetDirections take several passes (each giving the same values).
  void run(int k, const double* x, const double* V, int seeded, double* dx, double* dV,
           int differentiated) const;
  /// `steps` classical RK4 steps of h on `width` orbits with k tangent vectors each (1 <= k <=
  /// kJetDirections) in the first `core` components: y holds, component-major, each orbit's state and then
  /// its vectors column after column (TangentSystem's layout). The steps are rk4StepOnArrays's (Rk4Scheme.h).
  void rk4(int k, int core, double* y, double h, long steps) const;
};

/// JetEvaluator::run of the program alone.
void runJetProgram(const JetProgram& program, const double* constants, int width, int k, const double* x,
                   const double* V, int seeded, double* dx, double* dV, int differentiated);

/// JetEvaluator::rk4 of the program alone.
void rk4JetProgram(const JetProgram& program, const double* constants, int width, int k, int core, double* y,
                   double h, long steps);

class LaneKernel;
/// The lane kernel (LaneField.h) of `width` models that share `program`, with the constants bound for their
/// lanes (JetProgram::bindConstants) and the counts of directions compiled for them (reading `context`):
/// tangent vectors in the first `core` components, up to min(core, kJetDirections) of them.
std::unique_ptr<LaneKernel>
jetProgramLaneKernel(std::shared_ptr<const JetProgram> program, std::vector<double> constants, int width,
                     int core, const std::array<CompiledJets, kJetDirections + 1>& compiled = {},
                     std::shared_ptr<const void> context = nullptr);

namespace jet_recording {

inline JetProgram& program() {
  return *active;
}

inline Constant::Constant(double number) : id(program().number(number).id) {}
inline Var::Var(double number)
    : id(program().jet(JetProgram::Op::ConstJet, program().number(number).id).id) {}
inline Var::Var(const Constant& value) : id(program().jet(JetProgram::Op::ConstJet, value.id).id) {}

// Constants: what LaneVector does, recorded
inline Constant operator+(const Constant& a, const Constant& b) {
  return program().constant(JetProgram::ConstantOp::Add, a.id, b.id);
}
inline Constant operator-(const Constant& a, const Constant& b) {
  return program().constant(JetProgram::ConstantOp::Sub, a.id, b.id);
}
inline Constant operator*(const Constant& a, const Constant& b) {
  return program().constant(JetProgram::ConstantOp::Mul, a.id, b.id);
}
inline Constant operator/(const Constant& a, const Constant& b) {
  return program().constant(JetProgram::ConstantOp::Div, a.id, b.id);
}
inline Constant operator+(double a, const Constant& b) {
  return Constant(a) + b;
}
inline Constant operator+(const Constant& a, double b) {
  return a + Constant(b);
}
inline Constant operator-(double a, const Constant& b) {
  return Constant(a) - b;
}
inline Constant operator-(const Constant& a, double b) {
  return a - Constant(b);
}
inline Constant operator*(double a, const Constant& b) {
  return Constant(a) * b;
}
inline Constant operator*(const Constant& a, double b) {
  return a * Constant(b);
}
inline Constant operator/(double a, const Constant& b) {
  return Constant(a) / b;
}
inline Constant operator/(const Constant& a, double b) {
  return a / Constant(b);
}
inline Constant operator-(const Constant& a) {
  return program().constant(JetProgram::ConstantOp::Neg, a.id);
}
inline Constant operator+(const Constant& a) {
  return a;
}
inline Constant sqrt(const Constant& a) {
  return program().constant(JetProgram::ConstantOp::Sqrt, a.id);
}
inline Constant sin(const Constant& a) {
  return program().constant(JetProgram::ConstantOp::Sin, a.id);
}
inline Constant cos(const Constant& a) {
  return program().constant(JetProgram::ConstantOp::Cos, a.id);
}
inline Constant& Constant::operator+=(const Constant& o) {
  return *this = *this + o;
}
inline Constant& Constant::operator-=(const Constant& o) {
  return *this = *this - o;
}
inline Constant& Constant::operator*=(const Constant& o) {
  return *this = *this * o;
}
inline Constant& Constant::operator/=(const Constant& o) {
  return *this = *this / o;
}

/// A Var's constant operand as a Constant (Jet's constantAs).
template <ConstantOperand C> Constant constantOf(const C& c) {
  if constexpr (std::is_same_v<C, Constant>)
    return c;
  else
    return Constant(static_cast<double>(c));
}

// Jets: Jet's overloads, recorded
inline Var operator+(const Var& a, const Var& b) {
  return program().jet(JetProgram::Op::Add, a.id, b.id);
}
inline Var operator-(const Var& a, const Var& b) {
  return program().jet(JetProgram::Op::Sub, a.id, b.id);
}
inline Var operator*(const Var& a, const Var& b) {
  return program().jet(JetProgram::Op::Mul, a.id, b.id);
}
inline Var operator/(const Var& a, const Var& b) {
  return program().jet(JetProgram::Op::Div, a.id, b.id);
}
inline Var operator-(const Var& a) {
  return program().jet(JetProgram::Op::Neg, a.id);
}
inline Var operator+(const Var& a) {
  return a;
}
// a + c and c + a, a * c and c * a: one operation each (a sum and a product round the same either way)
template <ConstantOperand C> Var operator+(const Var& a, const C& c) {
  return program().jet(JetProgram::Op::AddC, a.id, constantOf(c).id);
}
template <ConstantOperand C> Var operator+(const C& c, const Var& b) {
  return program().jet(JetProgram::Op::AddC, b.id, constantOf(c).id);
}
template <ConstantOperand C> Var operator-(const Var& a, const C& c) {
  return program().jet(JetProgram::Op::SubC, a.id, constantOf(c).id);
}
template <ConstantOperand C> Var operator-(const C& c, const Var& b) {
  return program().jet(JetProgram::Op::CSub, b.id, constantOf(c).id);
}
template <ConstantOperand C> Var operator*(const Var& a, const C& c) {
  return program().jet(JetProgram::Op::MulC, a.id, constantOf(c).id);
}
template <ConstantOperand C> Var operator*(const C& c, const Var& b) {
  return program().jet(JetProgram::Op::MulC, b.id, constantOf(c).id);
}
template <ConstantOperand C> Var operator/(const Var& a, const C& c) {
  return program().jet(JetProgram::Op::DivC, a.id, constantOf(c).id);
}
template <ConstantOperand C> Var operator/(const C& c, const Var& b) {
  return program().jet(JetProgram::Op::CDiv, b.id, constantOf(c).id);
}
inline Var sqrt(const Var& a) {
  return program().jet(JetProgram::Op::Sqrt, a.id);
}
inline Var sin(const Var& a) {
  return program().jet(JetProgram::Op::Sin, a.id);
}
inline Var cos(const Var& a) {
  return program().jet(JetProgram::Op::Cos, a.id);
}
/// v where c is not 0, else a zero jet (Lanes.h's keptWhereNonzero, recorded).
inline Var keptWhereNonzero(const Constant& c, const Var& v) {
  return program().jet(JetProgram::Op::KeepC, v.id, c.id);
}
inline Var& Var::operator+=(const Var& o) {
  return *this = *this + o;
}
inline Var& Var::operator-=(const Var& o) {
  return *this = *this - o;
}
inline Var& Var::operator*=(const Var& o) {
  return *this = *this * o;
}
inline Var& Var::operator/=(const Var& o) {
  return *this = *this / o;
}

} // namespace jet_recording
} // namespace rv

namespace Eigen {
template <>
struct NumTraits<rv::jet_recording::Constant> : rv::HeldScalarTraits<rv::jet_recording::Constant, 1> {};
template <> struct NumTraits<rv::jet_recording::Var> : rv::HeldScalarTraits<rv::jet_recording::Var, 3> {};
// a vector of jets times a coefficient (as Lanes.h declares for Jet and LaneVector)
template <typename BinaryOp>
struct ScalarBinaryOpTraits<rv::jet_recording::Constant, rv::jet_recording::Var, BinaryOp> {
  using ReturnType = rv::jet_recording::Var;
};
template <typename BinaryOp>
struct ScalarBinaryOpTraits<rv::jet_recording::Var, rv::jet_recording::Constant, BinaryOp> {
  using ReturnType = rv::jet_recording::Var;
};
} // namespace Eigen
