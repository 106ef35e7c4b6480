// Graph.h -- expressions lowered to scalars: a graph of elementary operations with shared subexpressions
// (hash-consing) and constants folded, and the flat programs cut from it that evaluate chosen outputs on any
// scalar type -- double, the recording scalar of the Taylor integrator -- and the exact forward-mode
// derivatives along given directions (the Jacobian, tangent vectors) in one pass.
// Every vector and matrix operation of the language is already scalar here (Lowering.h), so one
// graph serves the interpreter, the derivatives and the generated C++ (ModelCode.h) alike.
// Reference for the forward mode: A. Griewank, A. Walther, Evaluating Derivatives (2008), ch. 3.
#pragma once
#include "dynamics/core/Errors.h"
#include "dynamics/core/TaylorTape.h"
#include "dynamics/expr/Functions.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace rv::expr {

/// Elementary scalar operations. PowC raises to the constant c; Input reads input slot a.
enum class Op : std::uint8_t {
  Const,
  Input,
  Add,
  Sub,
  Mul,
  Div,
  Neg,
  PowC,
  Pow,
  Sqrt,
  Exp,
  Log,
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Atan2,
  Sinh,
  Cosh,
  Tanh,
  Abs,
  Sign,
  Min,
  Max
};

/// Name of an operation as the language writes it ("+", "sin", ...).
const char* opName(Op op);

/// One operation: operands a, b (graph nodes), constant c; `origin` indexes Graph::origins (which
/// expression of the model it came from, for messages).
struct GraphNode {
  Op op;
  int a = -1, b = -1;
  double c = 0;
  int origin = -1;
};

/// A growing graph of scalar operations.
class Graph {
public:
  /// The node computing op(a, b; c), shared with an equal one made before; constants folded.
  int make(Op op, int a = -1, int b = -1, double c = 0);
  int constant(double v) { return make(Op::Const, -1, -1, v); }
  int input(int slot) { return make(Op::Input, slot); }
  bool isConstant(int n, double v) const { return at(n).op == Op::Const && at(n).c == v; }
  bool isConstant(int n) const { return at(n).op == Op::Const; }
  const GraphNode& at(int n) const { return nodes_[static_cast<std::size_t>(n)]; }
  int size() const { return static_cast<int>(nodes_.size()); }
  /// Nodes made from now on are marked as coming from `where` (an expression's place in the model file).
  void setOrigin(const std::string& where);
  const std::vector<std::string>& origins() const { return origins_; }

private:
  int push(GraphNode n);
  std::vector<GraphNode> nodes_;
  std::unordered_map<std::string, int> shared_;
  std::vector<std::string> origins_;
  int origin_ = -1;
};

/// Straight-line code for some outputs of a graph: the operations they depend on, in order, register i
/// holding instruction i's value.
class Program {
public:
  Program() = default;
  /// The operations `outputs` (graph nodes) depend on.
  Program(const Graph& graph, const std::vector<int>& outputs);

  struct Instr {
    Op op;
    int a, b;
    double c;
    int origin;
  };
  const std::vector<Instr>& code() const { return code_; }
  const std::vector<int>& outputs() const { return outputs_; }
  std::size_t registers() const { return code_.size(); }
  /// Highest input slot read, plus one.
  int inputsUsed() const { return inputsUsed_; }

  /// Registers from the inputs, from instruction `first` on (the ones before already in `reg`); S is double,
  /// an AutoDiff scalar or taylor::Var.
  template <class S> void run(const S* in, S* reg, std::size_t first = 0) const;
  /// Outputs into out[0..outputs().size()).
  void evaluate(const double* in, double* out) const;
  /// Values and derivatives along k directions: seed[slot * k + c] is d(input slot)/d(direction c) (slots
  /// beyond `seeded` have none); out as evaluate(), dOut[i * k + c] the derivative of output i.
  void derivatives(const double* in, const double* seed, int seeded, int k, double* out, double* dOut) const;
  /// The first operation (in order) whose value is not finite while its operands are, at these inputs:
  /// "<origin>: <op> gave <value>", or "" when every value is finite.
  std::string firstNonFinite(const double* in, const std::vector<std::string>& origins) const;

private:
  friend class Graph;       // folds a constant operation through a three-instruction program
  std::vector<Instr> code_; // constants, then inputs, then operations
  std::vector<double> constants_;
  std::size_t firstOperation_ = 0;
  std::vector<int> outputs_;
  int inputsUsed_ = 0;
};

template <class S> void Program::run(const S* in, S* reg, std::size_t first) const {
  using std::exp, std::log, std::sqrt, std::sin, std::cos, std::pow;
  for (std::size_t i = first; i < code_.size(); ++i) {
    const Instr& k = code_[i];
    const auto A = [&]() -> const S& { return reg[k.a]; };
    const auto B = [&]() -> const S& { return reg[k.b]; };
    S& r = reg[i];
    switch (k.op) {
    case Op::Const:
      r = S(k.c);
      break;
    case Op::Input:
      r = in[k.a];
      break;
    case Op::Add:
      r = A() + B();
      break;
    case Op::Sub:
      r = A() - B();
      break;
    case Op::Mul:
      r = A() * B();
      break;
    case Op::Div:
      r = A() / B();
      break;
    case Op::Neg:
      r = -A();
      break;
    case Op::PowC:
      r = pow(A(), k.c);
      break;
    case Op::Pow:
      r = fn::power(A(), B());
      break;
    case Op::Sqrt:
      r = sqrt(A());
      break;
    case Op::Exp:
      r = exp(A());
      break;
    case Op::Log:
      r = log(A());
      break;
    case Op::Sin:
      r = sin(A());
      break;
    case Op::Cos:
      r = cos(A());
      break;
    case Op::Tan:
      r = fn::tan(A());
      break;
    case Op::Asin:
      r = fn::asin(A());
      break;
    case Op::Acos:
      r = fn::acos(A());
      break;
    case Op::Atan:
      r = fn::atan(A());
      break;
    case Op::Atan2:
      r = fn::atan2(A(), B());
      break;
    case Op::Sinh:
      r = fn::sinh(A());
      break;
    case Op::Cosh:
      r = fn::cosh(A());
      break;
    case Op::Tanh:
      r = fn::tanh(A());
      break;
    case Op::Abs:
      r = fn::abs(A());
      break;
    case Op::Sign:
      r = fn::sign(A());
      break;
    case Op::Min:
      r = fn::min(A(), B());
      break;
    case Op::Max:
      r = fn::max(A(), B());
      break;
    }
  }
}

} // namespace rv::expr
