#include "dynamics/core/TaylorTape.h"

#include <algorithm>
#include <array>
#include <utility>

namespace rv::taylor {

void Tape::begin(int inputs) {
  inputs_ = inputs;
  nodes_.assign(static_cast<std::size_t>(inputs), Node{Op::Input});
  values_.assign(static_cast<std::size_t>(inputs), 0.0);
  outputs_.assign(static_cast<std::size_t>(inputs), Var());
  branches_ = compiled_ = false;
}

void Tape::setOutput(int i, const Var& v) {
  if (static_cast<std::size_t>(i) >= outputs_.size()) outputs_.resize(static_cast<std::size_t>(i) + 1);
  outputs_[static_cast<std::size_t>(i)] = v;
}

void Tape::compile() {
  const int count = nodeCount();
  // the operations some output needs: a reverse sweep (operands precede their node; a sine's cosine
  // partner may follow it, and is marked after the sweep passed it, but its operands are the sine's own)
  std::vector<char> used(static_cast<std::size_t>(count), 0);
  for (const Var& o : outputs_)
    if (o.id >= 0) used[static_cast<std::size_t>(o.id)] = 1;
  for (int n = count - 1; n >= inputs_; --n) {
    if (!used[static_cast<std::size_t>(n)]) continue;
    const Node& node = nodes_[static_cast<std::size_t>(n)];
    if (node.a >= 0) used[static_cast<std::size_t>(node.a)] = 1;
    if (node.b >= 0) used[static_cast<std::size_t>(node.b)] = 1;
  }

  // each recorded operation as a compiled one: the linear kinds become c = alpha a + beta b (+ gamma at
  // order 0); a node's constant is the offset of AddC and CSub and the operand of CDiv, DivC and PowC (it is
  // 0 on the operations without one), MulC's is its factor
  static constexpr std::array kindOf{Kind::Lin,  Kind::Lin, Kind::Lin, Kind::Lin,  Kind::Mul,  Kind::Square,
                                     Kind::Div,  Kind::Lin, Kind::Lin, Kind::Lin,  Kind::DivC, Kind::CDiv,
                                     Kind::Sqrt, Kind::Exp, Kind::Log, Kind::PowC, Kind::Sin,  Kind::Cos};
  static_assert(kindOf.size() == static_cast<std::size_t>(Op::Cos) + 1);
  std::vector<Kind> kind(static_cast<std::size_t>(count), Kind::Lin);
  std::vector<Instr> instr(static_cast<std::size_t>(count));
  for (int n = inputs_; n < count; ++n) {
    const Node& node = nodes_[static_cast<std::size_t>(n)];
    Instr& in = instr[static_cast<std::size_t>(n)];
    kind[static_cast<std::size_t>(n)] = kindOf[static_cast<std::size_t>(node.op)];
    in = {n, node.a, node.b >= 0 ? node.b : node.a, 1, 0, node.op == Op::MulC ? 0 : node.c};
    if (node.op == Op::Add) in.beta = 1;
    if (node.op == Op::Sub) in.beta = -1;
    if (node.op == Op::Neg || node.op == Op::CSub) in.alpha = -1;
    if (node.op == Op::MulC) in.alpha = node.c;
  }

  // list scheduling into runs of one kind: a node is ready once the operands whose coefficient of the
  // same order it reads are done (a sine reads only lower orders of its partner)
  const auto sameOrderOperands = [&](int n) {
    const Node& node = nodes_[static_cast<std::size_t>(n)];
    const bool partner = node.op == Op::Sin || node.op == Op::Cos;
    return std::array<int, 2>{node.a, partner || node.b == node.a ? -1 : node.b};
  };
  std::vector<int> pending(static_cast<std::size_t>(count), 0);
  std::vector<std::vector<int>> dependents(static_cast<std::size_t>(count));
  constexpr std::size_t kKinds = static_cast<std::size_t>(Kind::Cos) + 1;
  std::array<std::vector<int>, kKinds> ready;
  int toSchedule = 0;
  for (int n = inputs_; n < count; ++n) {
    if (!used[static_cast<std::size_t>(n)]) continue;
    ++toSchedule;
    for (const int d : sameOrderOperands(n))
      if (d >= inputs_) {
        ++pending[static_cast<std::size_t>(n)];
        dependents[static_cast<std::size_t>(d)].push_back(n);
      }
    if (pending[static_cast<std::size_t>(n)] == 0)
      ready[static_cast<std::size_t>(kind[static_cast<std::size_t>(n)])].push_back(n);
  }
  code_.clear();
  runs_.clear();
  std::size_t current = 0;
  for (int done = 0; done < toSchedule; ++done) {
    if (ready[current].empty())
      current = static_cast<std::size_t>(
          std::max_element(ready.begin(), ready.end(),
                           [](const auto& x, const auto& y) { return x.size() < y.size(); }) -
          ready.begin());
    const int n = ready[current].back();
    ready[current].pop_back();
    if (runs_.empty() || runs_.back().kind != static_cast<Kind>(current))
      runs_.push_back({static_cast<Kind>(current), static_cast<int>(code_.size()), 0});
    code_.push_back(instr[static_cast<std::size_t>(n)]);
    runs_.back().end = static_cast<int>(code_.size());
    for (const int d : dependents[static_cast<std::size_t>(n)])
      if (--pending[static_cast<std::size_t>(d)] == 0)
        ready[static_cast<std::size_t>(kind[static_cast<std::size_t>(d)])].push_back(d);
  }
  compiled_ = true;
}

void Tape::prepare(int order) {
  if (!compiled_) compile();
  order_ = order;
  stride_ = static_cast<std::size_t>(order) + 1;
  width_ = 2 * stride_;
  coef_.resize(nodes_.size() * width_);
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    coef_[n * width_] = coef_[n * width_ + stride_ + static_cast<std::size_t>(order)] = values_[n];
}

void Tape::setInputs(const double* x) {
  const std::size_t top = static_cast<std::size_t>(order_);
  for (int i = 0; i < inputs_; ++i)
    coefficients(i)[0] = reversed(i)[top] = x[i];
  for (const Run& run : runs_)
    for (int i = run.begin; i < run.end; ++i) {
      const Instr& in = code_[static_cast<std::size_t>(i)];
      const double a = coefficients(in.a)[0], b = coefficients(in.b)[0];
      double v = 0;
      switch (run.kind) {
      case Kind::Lin:
        v = in.alpha * a + in.beta * b + in.gamma;
        break;
      case Kind::Mul:
        v = a * b;
        break;
      case Kind::Square:
        v = a * a;
        break;
      case Kind::Div:
        v = a / b;
        break;
      case Kind::CDiv:
        v = in.gamma / a;
        break;
      case Kind::DivC:
        v = a / in.gamma;
        break;
      case Kind::Sqrt:
        v = std::sqrt(a);
        break;
      case Kind::Exp:
        v = std::exp(a);
        break;
      case Kind::Log:
        v = std::log(a);
        break;
      case Kind::PowC:
        v = std::pow(a, in.gamma);
        break;
      case Kind::Sin:
        v = std::sin(a);
        break;
      case Kind::Cos:
        v = std::cos(a);
        break;
      }
      coefficients(in.out)[0] = reversed(in.out)[top] = v;
    }
}

namespace {
// sum_{j<n} x[j] y[j] over contiguous arrays, in four independent partial sums: one running sum would wait
// on the adder's latency at every term, and these sums are most of the expansion's time (pairs of lanes
// are what the vectoriser packs)
inline double dot(const double* x, const double* y, int n) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int j = 0;
  for (; j + 4 <= n; j += 4) {
    s0 += x[j] * y[j];
    s1 += x[j + 1] * y[j + 1];
    s2 += x[j + 2] * y[j + 2];
    s3 += x[j + 3] * y[j + 3];
  }
  for (; j < n; ++j)
    s0 += x[j] * y[j];
  return (s0 + s1) + (s2 + s3);
}
// sum_{j=1}^{k} j x[j] y[k-j], with y given in reverse (yr[order - i] = y[i], yr passed at order - k)
inline double weighted(const double* x, const double* yr, int k) {
  double s0 = 0, s1 = 0;
  int j = 1;
  for (; j + 1 <= k; j += 2) {
    s0 += j * x[j] * yr[j];
    s1 += (j + 1) * x[j + 1] * yr[j + 1];
  }
  if (j <= k) s0 += j * x[j] * yr[j];
  return s0 + s1;
}
} // namespace

void Tape::evaluate(int k) {
  // the order as a compile-time constant where it is small: every sum's length is then known and unrolled
  constexpr int kUnrolled = 24;
  static constexpr auto byOrder = []<int... K>(std::integer_sequence<int, K...>) {
    return std::array<void (Tape::*)(int), sizeof...(K)>{&Tape::evaluateOrder<K + 1>...};
  }
  (std::make_integer_sequence<int, kUnrolled>{});
  if (k >= 1 && k <= kUnrolled) return (this->*byOrder[static_cast<std::size_t>(k - 1)])(k);
  evaluateOrder<0>(k);
}

template <int K> void Tape::evaluateOrder(int runtimeOrder) {
  const int k = K > 0 ? K : runtimeOrder;
  const double dk = k;
  // reversed(n) + back holds coefficients k, k-1, ..., 0 of node n in that order
  const std::size_t back = static_cast<std::size_t>(order_ - k);
  for (int i = 0; i < inputs_; ++i)
    reversed(i)[back] = coefficients(i)[k];
  for (const Run& run : runs_) {
    const Instr* first = code_.data() + run.begin;
    const Instr* last = code_.data() + run.end;
    const auto each = [&](auto&& coefficient) {
      for (const Instr* in = first; in != last; ++in) {
        const double v = coefficient(*in, coefficients(in->a), coefficients(in->out));
        coefficients(in->out)[k] = reversed(in->out)[back] = v;
      }
    };
    switch (run.kind) {
    case Kind::Lin:
      each([&](const Instr& in, const double* a, const double*) {
        return in.alpha * a[k] + in.beta * coefficients(in.b)[k];
      });
      break;
    case Kind::Mul:
      each([&](const Instr& in, const double* a, const double*) {
        return dot(a, reversed(in.b) + back, k + 1);
      });
      break;
    case Kind::Square:
      // the symmetric half of the product, doubled, plus the middle term
      each([&](const Instr& in, const double* a, const double*) {
        const double s = 2 * dot(a, reversed(in.a) + back, (k + 1) / 2);
        return k % 2 == 0 ? s + a[k / 2] * a[k / 2] : s;
      });
      break;
    case Kind::Div: // c b = a
      each([&](const Instr& in, const double* a, const double*) {
        const double* b = coefficients(in.b);
        return (a[k] - dot(b + 1, reversed(in.out) + back + 1, k)) / b[0];
      });
      break;
    case Kind::CDiv: // c = const / a: c a = const
      each([&](const Instr& in, const double* a, const double*) {
        return -dot(a + 1, reversed(in.out) + back + 1, k) / a[0];
      });
      break;
    case Kind::DivC:
      each([&](const Instr& in, const double* a, const double*) { return a[k] / in.gamma; });
      break;
    case Kind::Sqrt: // c^2 = a; a square root at zero has no series: its derivatives are taken as zero
      each([&](const Instr& in, const double* a, const double* c) {
        if (c[0] == 0) return 0.0;
        double s = 2 * dot(c + 1, reversed(in.out) + back + 1, (k - 1) / 2);
        if (k % 2 == 0) s += c[k / 2] * c[k / 2];
        return (a[k] - s) / (2 * c[0]);
      });
      break;
    case Kind::Exp: // c' = a' c
      each([&](const Instr& in, const double* a, const double*) {
        return weighted(a, reversed(in.out) + back, k) / dk;
      });
      break;
    case Kind::Log: // a c' = a'
      each([&](const Instr&, const double* a, const double* c) {
        double s = 0;
        for (int j = 1; j < k; ++j)
          s += j * c[j] * a[k - j];
        return (a[k] - s / dk) / a[0];
      });
      break;
    case Kind::PowC: // a c' = p a' c
      each([&](const Instr& in, const double* a, const double* c) {
        double s = 0;
        for (int j = 0; j < k; ++j)
          s += (in.gamma * (k - j) - j) * a[k - j] * c[j];
        return s / (dk * a[0]);
      });
      break;
    case Kind::Sin: // sin' = a' cos
      each([&](const Instr& in, const double* a, const double*) {
        return weighted(a, reversed(in.b) + back, k) / dk;
      });
      break;
    case Kind::Cos: // cos' = -a' sin
      each([&](const Instr& in, const double* a, const double*) {
        return -weighted(a, reversed(in.b) + back, k) / dk;
      });
      break;
    }
  }
}

} // namespace rv::taylor
