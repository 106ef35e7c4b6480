#include "dynamics/core/TaylorTape.h"

#include <algorithm>

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
// sum_{j=lo}^{hi} a[j] b[k-j]
inline double convolve(const double* a, const double* b, int k, int lo, int hi) {
  double s = 0;
  for (int j = lo; j <= hi; ++j)
    s += a[j] * b[k - j];
  return s;
}
// sum_{j=1}^{k} j a[j] b[k-j]: the derivative-weighted product of exp, sin and cos
inline double weighted(const double* a, const double* b, int k) {
  double s = 0;
  for (int j = 1; j <= k; ++j)
    s += j * a[j] * b[k - j];
  return s;
}
} // namespace

void Tape::evaluate(int k) {
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
