#include "dynamics/expr/Graph.h"

#include <algorithm>
#include <cstring>
#include <sstream>

namespace rv::expr {

const char* opName(Op op) {
  switch (op) {
  case Op::Const:
    return "constant";
  case Op::Input:
    return "input";
  case Op::Add:
    return "+";
  case Op::Sub:
    return "-";
  case Op::Mul:
    return "*";
  case Op::Div:
    return "/";
  case Op::Neg:
    return "unary -";
  case Op::PowC:
  case Op::Pow:
    return "^";
  case Op::Sqrt:
    return "sqrt";
  case Op::Exp:
    return "exp";
  case Op::Log:
    return "log";
  case Op::Sin:
    return "sin";
  case Op::Cos:
    return "cos";
  case Op::Tan:
    return "tan";
  case Op::Asin:
    return "asin";
  case Op::Acos:
    return "acos";
  case Op::Atan:
    return "atan";
  case Op::Atan2:
    return "atan2";
  case Op::Sinh:
    return "sinh";
  case Op::Cosh:
    return "cosh";
  case Op::Tanh:
    return "tanh";
  case Op::Abs:
    return "abs";
  case Op::Sign:
    return "sign";
  case Op::Min:
    return "min";
  case Op::Max:
    return "max";
  }
  return "?";
}

namespace fn {
void notExpandable(const char* function) {
  throw InputError(std::string("the taylor integrator cannot expand ") + function +
                   " (its series recurrence is not implemented): choose another integrator");
}
} // namespace fn

namespace {
bool commutative(Op op) {
  return op == Op::Add || op == Op::Mul || op == Op::Min || op == Op::Max;
}
} // namespace

void Graph::setOrigin(const std::string& where) {
  const auto it = std::find(origins_.begin(), origins_.end(), where);
  origin_ = static_cast<int>(it - origins_.begin());
  if (it == origins_.end()) origins_.push_back(where);
}

int Graph::push(GraphNode n) {
  std::string key(sizeof(Op) + 2 * sizeof(int) + sizeof(double), '\0');
  char* p = key.data();
  std::memcpy(p, &n.op, sizeof(Op));
  std::memcpy(p + sizeof(Op), &n.a, sizeof(int));
  std::memcpy(p + sizeof(Op) + sizeof(int), &n.b, sizeof(int));
  std::memcpy(p + sizeof(Op) + 2 * sizeof(int), &n.c, sizeof(double));
  const auto [it, fresh] = shared_.emplace(std::move(key), size());
  if (fresh) {
    n.origin = origin_;
    nodes_.push_back(n);
  }
  return it->second;
}

int Graph::make(Op op, int a, int b, double c) {
  if (op == Op::Const || op == Op::Input) return push({op, a, b, c});
  if (commutative(op) && b >= 0 && a > b) std::swap(a, b);
  const bool unary = b < 0;
  if (isConstant(a) && (unary || isConstant(b))) { // fold: evaluate the one operation on constants
    Program one;
    one.code_ = {{Op::Const, -1, -1, at(a).c, -1},
                 {Op::Const, -1, -1, unary ? 0.0 : at(b).c, -1},
                 {op, 0, unary ? -1 : 1, c, -1}};
    double reg[3];
    one.run<double>(nullptr, reg);
    return constant(reg[2]);
  }
  switch (op) { // identities that keep diagonal tensors and zero gyrostats from costing anything
  case Op::Add:
    if (isConstant(a, 0)) return b;
    if (isConstant(b, 0)) return a;
    break;
  case Op::Sub:
    if (isConstant(b, 0)) return a;
    if (isConstant(a, 0)) return make(Op::Neg, b);
    break;
  case Op::Mul:
    if (isConstant(a, 0)) return a;
    if (isConstant(a, 1)) return b;
    if (isConstant(a, -1)) return make(Op::Neg, b);
    break;
  case Op::Div:
    if (isConstant(b, 1)) return a;
    if (isConstant(a, 0)) return a;
    break;
  case Op::Neg:
    if (at(a).op == Op::Neg) return at(a).a;
    break;
  case Op::PowC:
    if (c == 1) return a;
    if (c == 0) return constant(1);
    if (c == 2) return make(Op::Mul, a, a);
    if (c == 3) return make(Op::Mul, make(Op::Mul, a, a), a);
    if (c == 4) {
      const int s = make(Op::Mul, a, a);
      return make(Op::Mul, s, s);
    }
    if (c == 0.5) return make(Op::Sqrt, a);
    if (c == -1) return make(Op::Div, constant(1), a);
    if (c == -2) return make(Op::Div, constant(1), make(Op::Mul, a, a));
    break;
  case Op::Pow:
    if (isConstant(b)) return make(Op::PowC, a, -1, at(b).c);
    break;
  default:
    break;
  }
  return push({op, a, b, c});
}

Program::Program(const Graph& graph, const std::vector<int>& outputs) {
  std::vector<int> reg(static_cast<std::size_t>(graph.size()), -1);
  std::vector<char> used(static_cast<std::size_t>(graph.size()), 0);
  for (int o : outputs)
    used[static_cast<std::size_t>(o)] = 1;
  for (int n = graph.size() - 1; n >= 0; --n) { // operands come before their users
    if (!used[static_cast<std::size_t>(n)]) continue;
    const GraphNode& g = graph.at(n);
    if (g.op == Op::Input) continue;
    if (g.a >= 0) used[static_cast<std::size_t>(g.a)] = 1;
    if (g.b >= 0) used[static_cast<std::size_t>(g.b)] = 1;
  }
  // constants first, then inputs, then the operations (all in graph order, so operands still come first):
  // evaluate() copies the first two blocks instead of dispatching on them
  for (const int pass : {0, 1, 2})
    for (int n = 0; n < graph.size(); ++n) {
      if (!used[static_cast<std::size_t>(n)]) continue;
      const GraphNode& g = graph.at(n);
      if ((pass == 0) != (g.op == Op::Const) || (pass == 1) != (g.op == Op::Input)) continue;
      reg[static_cast<std::size_t>(n)] = static_cast<int>(code_.size());
      if (g.op == Op::Const) {
        constants_.push_back(g.c);
        code_.push_back({g.op, -1, -1, g.c, g.origin});
      } else if (g.op == Op::Input) {
        code_.push_back({g.op, g.a, -1, 0, g.origin});
        inputsUsed_ = std::max(inputsUsed_, g.a + 1);
      } else {
        code_.push_back({g.op, g.a >= 0 ? reg[static_cast<std::size_t>(g.a)] : -1,
                         g.b >= 0 ? reg[static_cast<std::size_t>(g.b)] : -1, g.c, g.origin});
      }
    }
  firstOperation_ = 0;
  while (firstOperation_ < code_.size() &&
         (code_[firstOperation_].op == Op::Const || code_[firstOperation_].op == Op::Input))
    ++firstOperation_;
  for (int o : outputs)
    outputs_.push_back(reg[static_cast<std::size_t>(o)]);
}

void Program::evaluate(const double* in, double* out) const {
  constexpr std::size_t kOnStack = 256; // most fields: no thread-local lookup, no heap
  double stack[kOnStack];
  thread_local std::vector<double> heap;
  double* reg = stack;
  if (code_.size() > kOnStack) {
    heap.resize(code_.size());
    reg = heap.data();
  }
  std::copy(constants_.begin(), constants_.end(), reg);
  for (std::size_t i = constants_.size(); i < firstOperation_; ++i)
    reg[i] = in[code_[i].a];
  run<double>(in, reg, firstOperation_);
  for (std::size_t i = 0; i < outputs_.size(); ++i)
    out[i] = reg[static_cast<std::size_t>(outputs_[i])];
}

void Program::derivatives(const double* in, const double* seed, int seeded, int k, double* out,
                          double* dOut) const {
  thread_local std::vector<double> val, der;
  val.resize(code_.size());
  std::copy(constants_.begin(), constants_.end(), val.begin());
  for (std::size_t i = constants_.size(); i < firstOperation_; ++i)
    val[i] = in[code_[i].a];
  run<double>(in, val.data(), firstOperation_);
  const std::size_t K = static_cast<std::size_t>(k);
  der.assign(code_.size() * K, 0.0); // constants have none
  for (std::size_t i = constants_.size(); i < code_.size(); ++i) {
    const Instr& c = code_[i];
    double* d = der.data() + i * K;
    const double* da = c.a >= 0 ? der.data() + static_cast<std::size_t>(c.a) * K : nullptr;
    const double* db = c.b >= 0 ? der.data() + static_cast<std::size_t>(c.b) * K : nullptr;
    const double a = c.a >= 0 && c.op != Op::Input ? val[static_cast<std::size_t>(c.a)] : 0.0;
    const double b = c.b >= 0 ? val[static_cast<std::size_t>(c.b)] : 0.0;
    const double v = val[i];
    // d(result) = fa da + fb db
    double fa = 0, fb = 0;
    switch (c.op) {
    case Op::Const:
      continue;
    case Op::Input:
      if (c.a < seeded) std::copy_n(seed + static_cast<std::size_t>(c.a) * K, K, d);
      continue;
    case Op::Add:
      fa = 1, fb = 1;
      break;
    case Op::Sub:
      fa = 1, fb = -1;
      break;
    case Op::Mul:
      fa = b, fb = a;
      break;
    case Op::Div:
      fa = 1 / b, fb = -v / b;
      break;
    case Op::Neg:
      fa = -1;
      break;
    case Op::PowC:
      fa = c.c * std::pow(a, c.c - 1);
      break;
    case Op::Pow:
      fa = b * std::pow(a, b - 1), fb = v * std::log(a);
      break;
    case Op::Sqrt:
      fa = 0.5 / v;
      break;
    case Op::Exp:
      fa = v;
      break;
    case Op::Log:
      fa = 1 / a;
      break;
    case Op::Sin:
      fa = std::cos(a);
      break;
    case Op::Cos:
      fa = -std::sin(a);
      break;
    case Op::Tan:
      fa = 1 + v * v;
      break;
    case Op::Asin:
      fa = 1 / std::sqrt(1 - a * a);
      break;
    case Op::Acos:
      fa = -1 / std::sqrt(1 - a * a);
      break;
    case Op::Atan:
      fa = 1 / (1 + a * a);
      break;
    case Op::Atan2: { // atan2(y = a, x = b)
      const double r2 = a * a + b * b;
      fa = b / r2, fb = -a / r2;
      break;
    }
    case Op::Sinh:
      fa = std::cosh(a);
      break;
    case Op::Cosh:
      fa = std::sinh(a);
      break;
    case Op::Tanh:
      fa = 1 - v * v;
      break;
    case Op::Abs:
      fa = fn::sign(a);
      break;
    case Op::Sign:
      continue;
    case Op::Min:
      (a <= b ? fa : fb) = 1;
      break;
    case Op::Max:
      (a >= b ? fa : fb) = 1;
      break;
    }
    if (fb == 0 || db == nullptr) {
      if (fa != 0 && da != nullptr)
        for (std::size_t j = 0; j < K; ++j)
          d[j] = fa * da[j];
    } else if (fa == 0 || da == nullptr) {
      for (std::size_t j = 0; j < K; ++j)
        d[j] = fb * db[j];
    } else {
      for (std::size_t j = 0; j < K; ++j)
        d[j] = fa * da[j] + fb * db[j];
    }
  }
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    const auto r = static_cast<std::size_t>(outputs_[i]);
    out[i] = val[r];
    std::copy_n(der.data() + r * K, K, dOut + i * K);
  }
}

std::string Program::firstNonFinite(const double* in, const std::vector<std::string>& origins) const {
  std::vector<double> reg(code_.size());
  run<double>(in, reg.data());
  const auto finite = [&](int r) { return r < 0 || std::isfinite(reg[static_cast<std::size_t>(r)]); };
  for (std::size_t i = 0; i < code_.size(); ++i) {
    const Instr& c = code_[i];
    if (std::isfinite(reg[i]) || c.op == Op::Input || !finite(c.a) || !finite(c.b)) continue;
    std::ostringstream os;
    if (c.origin >= 0) os << origins[static_cast<std::size_t>(c.origin)] << ": ";
    if (c.op == Op::Const) { // folded: an expression of constants and parameters alone
      os << "is " << reg[i] << " whatever the state (it depends on the parameters alone)";
      return os.str();
    }
    os << "'" << opName(c.op) << "' of";
    for (int r : {c.a, c.b})
      if (r >= 0) os << " " << reg[static_cast<std::size_t>(r)];
    os << " gave " << reg[i];
    return os.str();
  }
  return {};
}

} // namespace rv::expr
