#include "dynamics/integrators/Everhart.h"

#include "dynamics/core/Errors.h"

#include <cmath>
#include <mutex>

namespace rv {

namespace {

using ld = long double;

// P_n(x) and P_{n-1}(x) by the three-term recurrence
std::pair<ld, ld> legendre(int n, ld x) {
  ld p0 = 1, p1 = x;
  if (n == 0) return {1, 0};
  for (int k = 2; k <= n; ++k) {
    const ld p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
    p0 = p1, p1 = p2;
  }
  return {p1, p0};
}

// all roots of f in (lo, hi] by a fine scan and bisection (the polynomials here have well separated roots)
template <class F> std::vector<ld> roots(F f, ld lo, ld hi, int grid) {
  std::vector<ld> r;
  ld a = lo, fa = f(a);
  for (int i = 1; i <= grid; ++i) {
    const ld b = lo + (hi - lo) * i / grid, fb = f(b);
    if (fb == 0) {
      r.push_back(b);
    } else if ((fa < 0) != (fb < 0) && fa != 0) {
      ld x0 = a, x1 = b, f0 = fa;
      for (int it = 0; it < 200; ++it) {
        const ld m = (x0 + x1) / 2, fm = f(m);
        if (m <= x0 || m >= x1) break;
        if ((fm < 0) == (f0 < 0))
          x0 = m, f0 = fm;
        else
          x1 = m;
      }
      r.push_back((x0 + x1) / 2);
    }
    a = b, fa = fb;
  }
  return r;
}

ld lagrange(const std::vector<ld>& c, int j, ld t) {
  ld v = 1;
  for (std::size_t m = 0; m < c.size(); ++m)
    if (static_cast<int>(m) != j) v *= (t - c[m]) / (c[j] - c[m]);
  return v;
}

} // namespace

const ParameterTable& Everhart::parameterTable() {
  static const ParameterTable table{
      {.id = "step",
       .label = "Step",
       .defaultValue = 0.05,
       .min = 1e-12,
       .max = 1e3,
       .description = "constant integration step"},
      {.id = "order",
       .label = "Order",
       .defaultValue = 15,
       .min = 3,
       .max = 1000,
       .description = "3, 7, 11, 15, 19, 23 or 27; other values are rounded down to one of these",
       .integer = true},
      {.id = "iterations",
       .label = "Number of iterations",
       .defaultValue = 12,
       .min = 1,
       .max = 100,
       .description = "most predictor-corrector iterations per step (fewer when the corrector has converged)",
       .integer = true},
  };
  return table;
}

IntegratorEntry Everhart::entry() {
  return {"everhart",
          "Everhart, implicit, Gauss-Radau spacings, orders 3..27",
          "Everhart 1985; Rein and Spiegel, IAS15, MNRAS 446 (2015)",
          &parameterTable(),
          true,
          [](const ParameterValues& p) -> std::unique_ptr<Integrator> {
            return std::make_unique<Everhart>(p["step"], static_cast<int>(p["order"]),
                                              static_cast<int>(p["iterations"]));
          }};
}

int Everhart::effectiveOrder(int requested) {
  if (requested < 3) return 0;
  return std::min(27, 3 + 4 * ((requested - 3) / 4));
}

namespace {
// the spacings, weights and matrices of one order, computed once per process (they cost ~10 ms)
struct EverhartTables {
  std::vector<long double> cl, gaussNodes, gaussWeights;
  std::vector<std::vector<long double>> integrated; // L_j(tau) = int_0^tau l_j = sum_p integrated[j][p] tau^p
  Eigen::MatrixXd A, extrapolate;
  Eigen::VectorXd b;
};

EverhartTables computeTables(int n) {
  EverhartTables t;
  // left Gauss-Radau points: the zeros of P_{n-1} + P_n on [-1, 1], -1 included
  const auto radau = roots(
      [&](ld x) {
        auto [pn, pn1] = legendre(n, x);
        return pn + pn1;
      },
      -1.0L + 1e-12L, 1.0L, 40000);
  t.cl = {0.0L};
  for (ld x : radau)
    t.cl.push_back((x + 1) / 2);
  // Gauss-Legendre on [0, 1] with n points integrates the Lagrange polynomials (degree n - 1) exactly
  for (ld x : roots([&](ld x) { return legendre(n, x).first; }, -1.0L, 1.0L, 40000)) {
    auto [pn, pn1] = legendre(n, x);
    const ld dp = n * (x * pn - pn1) / (x * x - 1);
    t.gaussNodes.push_back((x + 1) / 2);
    t.gaussWeights.push_back(1 / ((1 - x * x) * dp * dp)); // the [-1, 1] weight, halved for [0, 1]
  }
  if (static_cast<int>(t.cl.size()) != n || static_cast<int>(t.gaussNodes.size()) != n)
    throw ComputationError("Everhart: could not compute the Gauss-Radau spacings");
  t.A.resize(n, n), t.extrapolate.resize(n, n), t.b.resize(n);
  for (int j = 0; j < n; ++j) {
    ld bj = 0;
    for (int k = 0; k < n; ++k)
      bj += t.gaussWeights[k] * lagrange(t.cl, j, t.gaussNodes[k]);
    t.b[j] = static_cast<double>(bj);
    for (int i = 0; i < n; ++i) {
      ld aij = 0;
      for (int k = 0; k < n; ++k)
        aij += t.gaussWeights[k] * lagrange(t.cl, j, t.cl[i] * t.gaussNodes[k]);
      t.A(i, j) = static_cast<double>(t.cl[i] * aij);
      t.extrapolate(j, i) = static_cast<double>(lagrange(t.cl, j, 1 + t.cl[i]));
    }
    // monomial coefficients of l_j (a product of n - 1 linear factors), integrated term by term
    std::vector<long double> poly{1.0L};
    for (int m = 0; m < n; ++m) {
      if (m == j) continue;
      const long double d = t.cl[j] - t.cl[m];
      std::vector<long double> next(poly.size() + 1, 0.0L);
      for (std::size_t q = 0; q < poly.size(); ++q) {
        next[q + 1] += poly[q] / d;
        next[q] -= poly[q] * t.cl[m] / d;
      }
      poly = std::move(next);
    }
    std::vector<long double> L(n + 1, 0.0L);
    for (int q = 0; q < n; ++q)
      L[q + 1] = poly[q] / (q + 1);
    t.integrated.push_back(std::move(L));
  }
  return t;
}

const EverhartTables& tablesFor(int n) {
  static std::once_flag once[15];
  static EverhartTables tables[15];
  std::call_once(once[n], [n] { tables[n] = computeTables(n); });
  return tables[n];
}
} // namespace

Everhart::Everhart(double step, int order, int iterations) : h_(step), maxIterations_(iterations) {
  const int effective = effectiveOrder(order);
  if (effective == 0) throw InputError("order " + std::to_string(order) + " is below 3 (use 3, 7, ..., 27)");
  n_ = (effective + 1) / 2;
  const EverhartTables& t = tablesFor(n_);
  integrated_ = &t.integrated;
  A_ = t.A, extrapolate_ = t.extrapolate, b_ = t.b;
  c_.assign(t.cl.begin(), t.cl.end());
}

void Everhart::start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction) {
  Integrator::start(model, t0, x0, direction);
  const auto d = x0.size();
  F_.setZero(d, n_), Fnew_.setZero(d, n_), predicted_.setZero(d, n_), correction_.setZero(d, n_);
  f1_.resize(d), y_.resize(d), sum_.resize(d);
  compensation_.setZero(d);
  havePrevious_ = false;
  evaluate(x_, f1_);
}

void Everhart::step() {
  const double h = direction_ * h_;
  // predictor: the last step's polynomial continued over this one, plus the correction the last prediction
  // needed (IAS15 carries its predictor's error over the same way); a constant on the first step
  if (havePrevious_) {
    Fnew_.noalias() = F_ * extrapolate_;
    Fnew_ += correction_;
  } else {
    Fnew_ = f1_.replicate(1, n_);
    correction_.setZero(F_.rows(), n_);
  }
  F_.swap(Fnew_);
  F_.col(0) = f1_;
  predicted_ = F_;
  // corrector: F_j = f(x0 + h sum_l A(j, l) F_l), sweeping the nodes in order and using each new value at
  // once (as Everhart's substeps do, which roughly halves the sweeps of a Jacobi iteration); stop when the
  // change times the observed contraction is below rounding, or when only rounding is left (IAS15's rule)
  double previousChange = 0;
  lastIterations_ = 0;
  for (int it = 0; it < maxIterations_; ++it) {
    ++lastIterations_;
    double change = 0, scale = 0;
    for (int j = 1; j < n_; ++j) {
      y_.noalias() = F_ * A_.row(j).transpose();
      y_ = x_ + h * y_;
      model_->rhs(y_.data(), f1_.data()); // f1_ is free until the step ends
      ++evaluations_;
      change = std::max(change, (f1_ - F_.col(j)).lpNorm<Eigen::Infinity>());
      scale = std::max(scale, f1_.lpNorm<Eigen::Infinity>());
      F_.col(j) = f1_;
    }
    const double relative = scale > 0 ? change / scale : change;
    const double contraction = it > 0 && previousChange > 0 ? std::min(1.0, relative / previousChange) : 1.0;
    if (relative * contraction < 1e-16 || (it > 2 && relative >= previousChange)) break;
    previousChange = relative;
  }
  if (havePrevious_) correction_ = F_ - predicted_;
  // x1 = x0 + h sum_j b_j F_j, with compensated (Kahan) summation across steps
  xPrev_ = x_;
  sum_.noalias() = F_ * b_;
  y_ = h * sum_ - compensation_;
  sum_ = x_ + y_;
  compensation_ = (sum_ - x_) - y_;
  x_ = sum_;
  tPrev_ = t_;
  t_ = tPrev_ + h;
  checkFinite();
  evaluate(x_, f1_);
  havePrevious_ = true;
}

void Everhart::interpolate(double t, Eigen::VectorXd& out) const {
  const double h = t_ - tPrev_;
  if (h == 0) {
    out = x_;
    return;
  }
  // x(tau) = x0 + h sum_j L_j(tau) F_j, L_j by Horner in long double (the coefficients alternate in sign)
  const ld tau = static_cast<ld>((t - tPrev_) / h);
  out = xPrev_;
  for (int j = 0; j < n_; ++j) {
    const auto& L = (*integrated_)[j];
    ld w = 0;
    for (int q = n_; q >= 1; --q)
      w = (w + L[q]) * tau;
    out += (h * static_cast<double>(w)) * F_.col(j);
  }
}

void Everhart::save(Snapshot& s) const {
  Integrator::save(s);
  s.put(havePrevious_ ? 1 : 0);
  s.put(F_), s.put(predicted_), s.put(correction_), s.put(compensation_), s.put(f1_);
}

void Everhart::restore(Snapshot& s) {
  Integrator::restore(s);
  havePrevious_ = s.get() != 0;
  s.get(F_), s.get(predicted_), s.get(correction_), s.get(compensation_), s.get(f1_);
  if (F_.rows() != x_.size() || F_.cols() != n_)
    throw InputError("checkpoint: saved for another Everhart order");
}

} // namespace rv
