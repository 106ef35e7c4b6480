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
}

void Tape::setOutput(int i, const Var& v) {
  if (static_cast<std::size_t>(i) >= outputs_.size()) outputs_.resize(static_cast<std::size_t>(i) + 1);
  outputs_[static_cast<std::size_t>(i)] = v;
}

void Tape::prepare(int order) {
  stride_ = static_cast<std::size_t>(order) + 1;
  coef_.resize(nodes_.size() * stride_);
  for (std::size_t n = 0; n < nodes_.size(); ++n)
    coef_[n * stride_] = values_[n];
}

namespace {
// sum_{j=lo}^{hi} a[j] b[k-j], in four independent partial sums: one running sum would wait on the adder's
// latency at every term, and these sums are most of the expansion's time
inline double convolve(const double* a, const double* b, int k, int lo, int hi) {
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  int j = lo;
  for (; j + 3 <= hi; j += 4) {
    s0 += a[j] * b[k - j];
    s1 += a[j + 1] * b[k - j - 1];
    s2 += a[j + 2] * b[k - j - 2];
    s3 += a[j + 3] * b[k - j - 3];
  }
  for (; j <= hi; ++j)
    s0 += a[j] * b[k - j];
  return (s0 + s1) + (s2 + s3);
}
// sum_{j=1}^{k} j a[j] b[k-j]: the derivative-weighted product of exp, sin and cos
inline double weighted(const double* a, const double* b, int k) {
  double s0 = 0, s1 = 0;
  int j = 1;
  for (; j + 1 <= k; j += 2) {
    s0 += j * a[j] * b[k - j];
    s1 += (j + 1) * a[j + 1] * b[k - j - 1];
  }
  if (j <= k) s0 += j * a[j] * b[k - j];
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
  const int count = static_cast<int>(nodes_.size());
  const double dk = k;
  for (int n = inputs_; n < count; ++n) {
    const Node& node = nodes_[static_cast<std::size_t>(n)];
    double* c = coefficients(n);
    const double* a = node.a >= 0 ? coefficients(node.a) : nullptr;
    switch (node.op) {
    case Op::Input:
      break;
    case Op::Add:
      c[k] = a[k] + coefficients(node.b)[k];
      break;
    case Op::Sub:
      c[k] = a[k] - coefficients(node.b)[k];
      break;
    case Op::Neg:
    case Op::CSub:
      c[k] = -a[k];
      break;
    case Op::AddC:
      c[k] = a[k];
      break;
    case Op::MulC:
      c[k] = node.c * a[k];
      break;
    case Op::DivC:
      c[k] = a[k] / node.c;
      break;
    case Op::Mul:
      c[k] = convolve(a, coefficients(node.b), k, 0, k);
      break;
    case Op::Square: {
      // the symmetric half of the product, doubled, plus the middle term
      double s = 2 * convolve(a, a, k, 0, (k - 1) / 2);
      if (k % 2 == 0) s += a[k / 2] * a[k / 2];
      c[k] = s;
      break;
    }
    case Op::Div: { // c b = a
      const double* b = coefficients(node.b);
      c[k] = (a[k] - convolve(b, c, k, 1, k)) / b[0];
      break;
    }
    case Op::CDiv: // c = const / a: c a = const
      c[k] = -convolve(a, c, k, 1, k) / a[0];
      break;
    case Op::Sqrt: { // c^2 = a; a square root at zero has no series: its derivatives are taken as zero
      if (c[0] == 0) {
        c[k] = 0;
        break;
      }
      double s = 2 * convolve(c, c, k, 1, (k - 1) / 2);
      if (k % 2 == 0 && k > 0) s += c[k / 2] * c[k / 2];
      c[k] = (a[k] - s) / (2 * c[0]);
      break;
    }
    case Op::Exp: // c' = a' c
      c[k] = weighted(a, c, k) / dk;
      break;
    case Op::Log: { // a c' = a'
      double s = 0;
      for (int j = 1; j < k; ++j)
        s += j * c[j] * a[k - j];
      c[k] = (a[k] - s / dk) / a[0];
      break;
    }
    case Op::PowC: { // a c' = p a' c
      double s = 0;
      for (int j = 0; j < k; ++j)
        s += (node.c * (k - j) - j) * a[k - j] * c[j];
      c[k] = s / (dk * a[0]);
      break;
    }
    case Op::Sin: // sin' = a' cos
      c[k] = weighted(a, coefficients(node.b), k) / dk;
      break;
    case Op::Cos: // cos' = -a' sin
      c[k] = -weighted(a, coefficients(node.b), k) / dk;
      break;
    }
  }
}

} // namespace rv::taylor
