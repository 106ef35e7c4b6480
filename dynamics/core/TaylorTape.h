// TaylorTape.h -- Taylor coefficients of a model's right-hand side by automatic differentiation of its
// one templated field: the field is evaluated once on a recording scalar (`taylor::Var`), which writes each
// elementary operation to a tape with its value; the tape then yields the k-th Taylor coefficient of every
// intermediate from the lower ones by the standard recurrences of series arithmetic (product, quotient,
// square root, exp, sin/cos pairs, ...), O(k) per operation and order.
// References: A. Jorba, M. Zou, A software package for the numerical integration of ODEs by means of
// high-order Taylor methods, Experimental Mathematics 14 (2005) 99-117; F. Biscani, D. Izzo, Revisiting
// high-order Taylor methods for astrodynamics and celestial mechanics, MNRAS 504 (2021) 2614 (heyoka);
// A. Griewank, A. Walther, Evaluating Derivatives (2008), §13.2 (the recurrences).
//
// The recording follows the branches the field takes at the recorded state (a field that branches on a
// value, through valueOf, is expanded on the branch of that state): such a tape is recorded per expansion;
// a tape without branches is recorded once and only its values are recomputed for a new state.
//
// Evaluation is compiled once per recording (heyoka compiles its decomposition once per system; here the
// compiled form is a flat program, not machine code): operations whose result no output uses are
// dropped, the linear ones (+, -, negation, constant offsets and factors) become one kind, the rest are
// scheduled into runs of one kind each (one dispatch a run, not a node), and every node keeps its
// coefficients in both orders so that each series product is a dot product of two contiguous arrays.
#pragma once

#include "dynamics/core/HeldScalar.h"

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <vector>

namespace rv::taylor {

class Tape;
/// The tape being recorded on this thread (set by Recording), or null.
inline thread_local Tape* activeTape = nullptr;

/// A recorded value: a node of the active tape, or a constant (id < 0) that records nothing.
struct Var {
  int id = -1;
  double v = 0;
  Var() = default;
  Var(double constant) : v(constant) {} // NOLINT(google-explicit-constructor): constants mix with variables
  Var(int node, double value) : id(node), v(value) {}
  bool constant() const { return id < 0; }
  Var& operator+=(const Var& o);
  Var& operator-=(const Var& o);
  Var& operator*=(const Var& o);
  Var& operator/=(const Var& o);
};

/// Elementary operations. C: a constant operand (stored in the node); Sin and Cos come in pairs (the
/// recurrence of each needs the other), `b` naming the partner.
enum class Op : std::uint8_t {
  Input,
  Add,
  Sub,
  Neg,
  Mul,
  Square,
  Div,
  AddC,
  CSub,
  MulC,
  DivC,
  CDiv,
  Sqrt,
  Exp,
  Log,
  PowC,
  Sin,
  Cos
};

struct Node {
  Op op;
  int a = -1, b = -1;
  double c = 0;
};

/// The operations of one evaluation of a field, and their Taylor coefficients up to an order.
class Tape {
public:
  /// Forgets the last recording (keeping its memory) and makes `inputs` input nodes 0..inputs-1.
  void begin(int inputs);
  /// Notes that the field branched on a recorded value (valueOf): the tape then holds only for the
  /// recorded state and must be recorded again for another.
  void markBranch() { branches_ = true; }
  /// Whether the recording branched on a value (see markBranch).
  bool branches() const { return branches_; }
  /// Input node i, with the value x.
  Var input(int i, double x) {
    values_[static_cast<std::size_t>(i)] = x;
    return {i, x};
  }
  /// Records an operation with its value; returns the new node.
  Var push(Op op, int a, int b, double c, double value) {
    nodes_.push_back({op, a, b, c});
    values_.push_back(value);
    return {static_cast<int>(nodes_.size()) - 1, value};
  }
  /// Output i of the field (a node or a constant).
  void setOutput(int i, const Var& v);

  /// Makes room for coefficients 0..order of every node; coefficient 0 is the recorded value. Compiles
  /// the recording on its first call after it.
  void prepare(int order);
  /// New values of the inputs (after prepare): every node's value (coefficient 0) is recomputed along
  /// the recorded operations. Only for a tape that does not branch.
  void setInputs(const double* x);
  /// Coefficients 0..order of a node (contiguous).
  double* coefficients(int node) { return coef_.data() + static_cast<std::size_t>(node) * width_; }
  const double* coefficients(int node) const {
    return coef_.data() + static_cast<std::size_t>(node) * width_;
  }
  /// Coefficient k of every used node, from coefficients 0..k of the inputs and 0..k-1 of the rest.
  void evaluate(int k);
  /// Coefficient k of output i.
  double output(int i, int k) const {
    const int n = outputs_[static_cast<std::size_t>(i)].id;
    if (n < 0) return k == 0 ? outputs_[static_cast<std::size_t>(i)].v : 0.0;
    return coefficients(n)[k];
  }
  int inputCount() const { return inputs_; }
  int nodeCount() const { return static_cast<int>(nodes_.size()); }
  /// Operations evaluated per order once compiled (the recorded ones some output uses).
  int usedCount() const { return static_cast<int>(code_.size()); }
  /// Runs of one kind the compiled operations fall into (one dispatch each per order).
  int runCount() const { return static_cast<int>(runs_.size()); }
  const std::vector<Node>& nodes() const { return nodes_; }

private:
  /// The compiled kinds: Lin is c = alpha a + beta b (+ gamma at order 0) for every linear operation.
  enum class Kind : std::uint8_t { Lin, Mul, Square, Div, CDiv, DivC, Sqrt, Exp, Log, PowC, Sin, Cos };
  struct Instr {
    int out, a, b;
    double alpha, beta, gamma;
  };
  struct Run {
    Kind kind;
    int begin, end; // into code_
  };
  /// Drops unused operations, folds the linear kinds and schedules runs of one kind (see the header).
  void compile();
  /// Coefficients of a node in reverse: reversed(n)[order - k] is coefficient k.
  double* reversed(int node) { return coefficients(node) + stride_; }
  /// evaluate() with the order fixed at compile time (K > 0) or given at run time (K = 0).
  template <int K> void evaluateOrder(int runtimeOrder);

  std::vector<Node> nodes_;
  std::vector<double> values_, coef_;
  std::vector<Var> outputs_;
  std::vector<Instr> code_;
  std::vector<Run> runs_;
  std::size_t stride_ = 1, width_ = 2;
  int inputs_ = 0, order_ = 0;
  bool branches_ = false, compiled_ = false;
};

/// Makes a tape the active one on this thread for its lifetime (restores the previous one after).
class Recording {
public:
  Recording(Tape& tape, int inputs) : previous_(activeTape) {
    tape.begin(inputs);
    activeTape = &tape;
  }
  ~Recording() { activeTape = previous_; }
  Recording(const Recording&) = delete;
  Recording& operator=(const Recording&) = delete;

private:
  Tape* previous_;
};

namespace detail {
inline Var record(Op op, int a, int b, double c, double value) {
  return activeTape->push(op, a, b, c, value);
}
inline Var addConstant(const Var& x, double c) {
  return c == 0 ? x : record(Op::AddC, x.id, -1, c, x.v + c);
}
inline Var scale(const Var& x, double c) {
  if (c == 0) return Var(0.0); // a zero factor (a diagonal tensor's off-diagonal): no node at all
  if (c == 1) return x;
  if (c == -1) return record(Op::Neg, x.id, -1, 0, -x.v);
  return record(Op::MulC, x.id, -1, c, c * x.v);
}
} // namespace detail

inline Var operator-(const Var& x) {
  return x.constant() ? Var(-x.v) : detail::record(Op::Neg, x.id, -1, 0, -x.v);
}
inline Var operator+(const Var& x, const Var& y) {
  if (x.constant()) return y.constant() ? Var(x.v + y.v) : detail::addConstant(y, x.v);
  if (y.constant()) return detail::addConstant(x, y.v);
  return detail::record(Op::Add, x.id, y.id, 0, x.v + y.v);
}
inline Var operator-(const Var& x, const Var& y) {
  if (y.constant()) return x.constant() ? Var(x.v - y.v) : detail::addConstant(x, -y.v);
  if (x.constant()) return detail::record(Op::CSub, y.id, -1, x.v, x.v - y.v);
  return detail::record(Op::Sub, x.id, y.id, 0, x.v - y.v);
}
inline Var operator*(const Var& x, const Var& y) {
  if (x.constant()) return y.constant() ? Var(x.v * y.v) : detail::scale(y, x.v);
  if (y.constant()) return detail::scale(x, y.v);
  if (x.id == y.id) return detail::record(Op::Square, x.id, -1, 0, x.v * y.v);
  return detail::record(Op::Mul, x.id, y.id, 0, x.v * y.v);
}
inline Var operator/(const Var& x, const Var& y) {
  if (y.constant()) {
    if (x.constant()) return Var(x.v / y.v);
    return y.v == 1 ? x : detail::record(Op::DivC, x.id, -1, y.v, x.v / y.v);
  }
  if (x.constant()) return detail::record(Op::CDiv, y.id, -1, x.v, x.v / y.v);
  return detail::record(Op::Div, x.id, y.id, 0, x.v / y.v);
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

inline Var sqrt(const Var& x) {
  return x.constant() ? Var(std::sqrt(x.v)) : detail::record(Op::Sqrt, x.id, -1, 0, std::sqrt(x.v));
}
inline Var exp(const Var& x) {
  return x.constant() ? Var(std::exp(x.v)) : detail::record(Op::Exp, x.id, -1, 0, std::exp(x.v));
}
inline Var log(const Var& x) {
  return x.constant() ? Var(std::log(x.v)) : detail::record(Op::Log, x.id, -1, 0, std::log(x.v));
}
inline Var pow(const Var& x, double p) {
  if (x.constant()) return Var(std::pow(x.v, p));
  if (p == 1) return x;
  if (p == 2) return x * x;
  return detail::record(Op::PowC, x.id, -1, p, std::pow(x.v, p));
}
inline Var sin(const Var& x) {
  if (x.constant()) return Var(std::sin(x.v));
  const int s = activeTape->nodeCount();
  const Var result = detail::record(Op::Sin, x.id, s + 1, 0, std::sin(x.v));
  detail::record(Op::Cos, x.id, s, 0, std::cos(x.v));
  return result;
}
inline Var cos(const Var& x) {
  if (x.constant()) return Var(std::cos(x.v));
  const int c = activeTape->nodeCount();
  const Var result = detail::record(Op::Cos, x.id, c + 1, 0, std::cos(x.v));
  detail::record(Op::Sin, x.id, c, 0, std::sin(x.v));
  return result;
}

} // namespace rv::taylor

namespace rv {
/// The plain value of a recorded scalar (for branch decisions: the tape is marked as branching).
inline double valueOf(const taylor::Var& v) {
  if (!v.constant() && taylor::activeTape != nullptr) taylor::activeTape->markBranch();
  return v.v;
}
} // namespace rv

namespace Eigen {
template <> struct NumTraits<rv::taylor::Var> : rv::HeldScalarTraits<rv::taylor::Var, 3> {};
template <typename BinaryOp> struct ScalarBinaryOpTraits<rv::taylor::Var, double, BinaryOp> {
  using ReturnType = rv::taylor::Var;
};
template <typename BinaryOp> struct ScalarBinaryOpTraits<double, rv::taylor::Var, BinaryOp> {
  using ReturnType = rv::taylor::Var;
};
} // namespace Eigen
