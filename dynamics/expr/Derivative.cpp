#include "dynamics/expr/Derivative.h"

#include <algorithm>
#include <string>

namespace rv::expr {

std::vector<int> directionalDerivative(Graph& g, const std::vector<int>& outputs,
                                       const std::vector<std::pair<int, int>>& seeds) {
  constexpr int kZero = -1; // no dependence on a seed: skipped instead of building zero nodes
  int last = -1, first = g.size();
  for (int o : outputs)
    last = std::max(last, o);
  for (const auto& [node, rate] : seeds)
    first = std::min(first, node);
  std::vector<int> t(static_cast<std::size_t>(std::max(last, 0) + 1), kZero);
  for (const auto& [node, rate] : seeds)
    if (node <= last) {
      int& slot = t[static_cast<std::size_t>(node)];
      slot = slot == kZero ? rate : g.make(Op::Add, slot, rate); // a node given twice: both rates
    }
  const auto tan = [&](int n) { return n < 0 ? kZero : t[static_cast<std::size_t>(n)]; };
  const auto mul = [&](int a, int b) { return g.make(Op::Mul, a, b); };
  const auto add = [&](int a, int b) { return a == kZero ? b : b == kZero ? a : g.make(Op::Add, a, b); };
  const auto neg = [&](int a) { return a == kZero ? kZero : g.make(Op::Neg, a); };
  const auto scaled = [&](int factor, int ta) { return ta == kZero ? kZero : mul(factor, ta); };
  const auto one = [&] { return g.constant(1); };
  for (int n = std::max(first, 0); n <= last; ++n) {
    int& out = t[static_cast<std::size_t>(n)];
    if (out != kZero) continue; // a seed
    if (g.size() > kMaxDerivativeGraph)
      throw InputError("the derivatives make more than " + std::to_string(kMaxDerivativeGraph) +
                       " operations (derivatives of derivatives grow geometrically)");
    const GraphNode k = g.at(n); // a copy: make() may grow the graph
    const int ta = tan(k.a), tb = tan(k.b);
    if (ta == kZero && tb == kZero) continue;
    const int a = k.a, b = k.b;
    switch (k.op) {
    case Op::Const:
    case Op::Input:
    case Op::Sign:
      break;
    case Op::Add:
      out = add(ta, tb);
      break;
    case Op::Sub:
      out = add(ta, neg(tb));
      break;
    case Op::Mul:
      out = add(scaled(b, ta), scaled(a, tb));
      break;
    case Op::Div: // (ta - (a/b) tb) / b
      out = g.make(Op::Div, add(ta, neg(scaled(n, tb))), b);
      break;
    case Op::Neg:
      out = neg(ta);
      break;
    case Op::PowC:
      out = scaled(mul(g.constant(k.c), g.make(Op::PowC, a, -1, k.c - 1)), ta);
      break;
    case Op::Pow: // a^b (b' log a + b a'/a)
      out = add(scaled(mul(b, g.make(Op::Pow, a, g.make(Op::Sub, b, one()))), ta),
                scaled(mul(n, g.make(Op::Log, a)), tb));
      break;
    case Op::Sqrt:
      out = g.make(Op::Div, ta, mul(g.constant(2), n));
      break;
    case Op::Exp:
      out = scaled(n, ta);
      break;
    case Op::Log:
      out = g.make(Op::Div, ta, a);
      break;
    case Op::Sin:
      out = scaled(g.make(Op::Cos, a), ta);
      break;
    case Op::Cos:
      out = neg(scaled(g.make(Op::Sin, a), ta));
      break;
    case Op::Tan:
      out = scaled(add(one(), mul(n, n)), ta);
      break;
    case Op::Asin:
    case Op::Acos: {
      const int d = g.make(Op::Div, ta, g.make(Op::Sqrt, g.make(Op::Sub, one(), mul(a, a))));
      out = k.op == Op::Asin ? d : neg(d);
      break;
    }
    case Op::Atan:
      out = g.make(Op::Div, ta, add(one(), mul(a, a)));
      break;
    case Op::Atan2: // atan2(a, b): (b a' - a b') / (a^2 + b^2)
      out = g.make(Op::Div, add(scaled(b, ta), neg(scaled(a, tb))), add(mul(a, a), mul(b, b)));
      break;
    case Op::Sinh:
      out = scaled(g.make(Op::Cosh, a), ta);
      break;
    case Op::Cosh:
      out = scaled(g.make(Op::Sinh, a), ta);
      break;
    case Op::Tanh:
      out = scaled(g.make(Op::Sub, one(), mul(n, n)), ta);
      break;
    case Op::Abs:
      out = scaled(g.make(Op::Sign, a), ta);
      break;
    case Op::Min:
    case Op::Max: { // the branch taken: a' + (b' - a') [b is taken], b taken when sign(b - a) = -1 (min), +1
                    // (max)
      const int s = g.make(Op::Sign, g.make(Op::Sub, b, a));
      const int taken = g.make(Op::Mul, g.constant(0.5),
                               k.op == Op::Min ? g.make(Op::Sub, one(), s) : g.make(Op::Add, one(), s));
      const int ta0 = ta == kZero ? g.constant(0) : ta, tb0 = tb == kZero ? g.constant(0) : tb;
      out = add(ta, scaled(taken, g.make(Op::Sub, tb0, ta0)));
      break;
    }
    }
  }
  std::vector<int> d;
  d.reserve(outputs.size());
  for (int o : outputs) {
    const int r = t[static_cast<std::size_t>(o)];
    d.push_back(r == kZero ? g.constant(0) : r);
  }
  return d;
}

} // namespace rv::expr
