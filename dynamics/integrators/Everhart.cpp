#include "dynamics/integrators/Everhart.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"
#include "dynamics/integrators/EverhartKernels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

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
      {.id = "adaptive",
       .label = "Adaptive step",
       .defaultValue = 0,
       .min = 0,
       .max = 1,
       .description = "choose each step by IAS15's rule (then `step` is only the first step)",
       .choices = {"no", "yes"}},
      {.id = "tolerance",
       .label = "Tolerance",
       .defaultValue = 1e-9,
       .min = 1e-16,
       .max = 1e-2,
       .description = "adaptive step: the polynomial's last coefficient relative to the right-hand side "
                      "(IAS15's epsilon; 1e-9 gives rounding-level steps at order 15)"},
  };
  return table;
}

IntegratorEntry Everhart::entry() {
  return {"everhart", "Everhart, implicit, Gauss-Radau spacings, orders 3..27",
          "Everhart 1985; Rein and Spiegel, IAS15, MNRAS 446 (2015)", &parameterTable(),
          [](const ParameterValues& p) -> std::unique_ptr<Integrator> {
            return std::make_unique<Everhart>(p["step"], static_cast<int>(p["order"]),
                                              static_cast<int>(p["iterations"]),
                                              p["adaptive"] != 0 ? p["tolerance"] : 0.0);
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
  Eigen::VectorXd b, leading; // leading(j) = 1 / prod_{m != j} (c_j - c_m): the last divided difference
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
  t.A.resize(n, n), t.extrapolate.resize(n, n), t.b.resize(n), t.leading.resize(n);
  for (int j = 0; j < n; ++j) {
    ld w = 1;
    for (int m = 0; m < n; ++m)
      if (m != j) w *= t.cl[j] - t.cl[m];
    t.leading[j] = static_cast<double>(1 / w);
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

Everhart::Everhart(double step, int order, int iterations, double tolerance)
    : h_(step), tolerance_(tolerance), maxIterations_(iterations) {
  const int effective = effectiveOrder(order);
  if (effective == 0) throw InputError("order " + std::to_string(order) + " is below 3 (use 3, 7, ..., 27)");
  n_ = (effective + 1) / 2;
  const EverhartTables& t = tablesFor(n_);
  integrated_ = &t.integrated;
  A_ = t.A, b_ = t.b, leading_ = t.leading; // extrapolate_ is set by start()
  c_.assign(t.cl.begin(), t.cl.end());
}

bool Everhart::stepLanesAlone(int width) {
  if (tolerance_ > 0 || width < 1) return false; // an adaptive step is one step for all lanes
  lanes_ = width;
  return true;
}

void Everhart::start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction) {
  Integrator::start(model, t0, x0, direction);
  const auto d = x0.size();
  if (d % lanes_ != 0)
    throw std::logic_error("Everhart: a state of " + std::to_string(d) + " components is not " +
                           std::to_string(lanes_) + " lanes");
  const auto lanes = static_cast<std::size_t>(lanes_);
  laneRules_.assign(lanes, Convergence{});
  laneChange_.assign(lanes, 0.0), laneScale_.assign(lanes, 0.0), laneOpen_.assign(lanes, 0);
  F_.setZero(d, n_), Fnew_.setZero(d, n_), predicted_.setZero(d, n_), correction_.setZero(d, n_);
  f1_.resize(d), y_.resize(d), sum_.resize(d);
  compensation_.setZero(d);
  havePrevious_ = false;
  rejected_ = 0;
  extrapolate_ = tablesFor(n_).extrapolate, lastRatio_ = 1;
  evaluate(x_, f1_);
}

void Everhart::setExtrapolation(double ratio) {
  // l_l(tau) = prod_m (tau - c_m) * leading_l / (tau - c_l) (the first barycentric form: O(n^2) a step, which
  // the adaptive step pays every step); tau = 1 + ratio c_j > c_l, never a node
  for (int j = 0; j < n_; ++j) {
    const double tau = 1 + ratio * c_[j];
    double all = 1;
    for (int m = 0; m < n_; ++m)
      all *= tau - c_[m];
    for (int l = 0; l < n_; ++l)
      extrapolate_(l, j) = all * leading_[l] / (tau - c_[l]);
  }
  lastRatio_ = ratio;
}

void Everhart::step() {
  switch (n_) {
  case 2:
    return stepWith<2>();
  case 4:
    return stepWith<4>();
  case 6:
    return stepWith<6>();
  case 8:
    return stepWith<8>();
  case 10:
    return stepWith<10>();
  case 12:
    return stepWith<12>();
  default:
    return stepWith<14>();
  }
}

// The corrector on a step of signed length h from x_ (F_ holds the prediction, column 0 = f(x_)): F_j =
// f(x0 + h sum_l A(j, l) F_l), sweeping the nodes in order and using each new value at once (as Everhart's
// substeps do, which roughly halves the sweeps of a Jacobi iteration); stops when only rounding is left
// (IAS15's rule) or what is left is far below it, or after `iterations` sweeps. Returns the polynomial's last
// coefficient relative to the largest node value (IAS15's error measure).
template <int N> double Everhart::correct(double h) {
  if (lanes_ > 1) {
    correctLanes<N>(h);
    return 0; // lanes step at a fixed step
  }
  using Nodes = Eigen::Matrix<double, Eigen::Dynamic, N>;
  const Eigen::Map<const Nodes> nodes(F_.data(), F_.rows(), N);
  Convergence rule;
  const Eigen::Index c = controlled(F_.rows()); // the components whose convergence counts (controlBy)
  lastIterations_ = 0;
  for (int it = 0; it < maxIterations_; ++it) {
    ++lastIterations_;
    double change = 0, scale = 0;
    for (int j = 1; j < N; ++j) {
      // y = x0 + h sum_l A(j, l) F_l
      nodeSum<N>(h, j);
      model_->rhs(y_.data(), f1_.data()); // f1_ is free until the step ends
      ++evaluations_;
      change = std::max(change, (f1_ - F_.col(j)).head(c).cwiseAbs().maxCoeff());
      scale = std::max(scale, f1_.head(c).cwiseAbs().maxCoeff());
      F_.col(j) = f1_;
    }
    if (rule.reached(it, scale > 0 ? change / scale : change)) break;
  }
  if (tolerance_ <= 0) return 0;
  const Eigen::Matrix<double, N, 1> w = leading_;
  y_.noalias() = nodes.lazyProduct(w);
  const double scale = nodes.topRows(c).cwiseAbs().maxCoeff();
  const double last = y_.head(c).cwiseAbs().maxCoeff();
  return scale > 0 ? last / scale : last;
}

// Converged when nothing changes any more or the changes stop shrinking (rounding is all that is left), as
// IAS15 iterates (its test on the last coefficient amplifies the nodes' changes ~1e4-fold). Stopping at a
// change extrapolated below rounding instead left a residual pointing the same way every step, which
// compensated summation then kept: the energy drifted linearly (an oscillator's q^2 + p^2 by ~1e-12 over 2e5
// steps; ~25 % fewer evaluations). The contraction from two sweeps could also fake convergence (one step in
// ~1e5 stopped after two sweeps, a jump of 1.5e-13).
bool Everhart::Convergence::reached(int sweep, double relative) {
  if (relative == 0 || (sweep > 2 && relative >= previousChange)) {
    converged = true;
    return true;
  }
  // Where the sweeps contract fast (short steps) the last one or two only chase rounding: stop once this
  // change times the contraction seen over the two sweeps before leaves less than 1e-18 -- 100 times below
  // the old extrapolated rule, no drift over 2e6 steps (h = 0.1 and 0.5) and 20-40 % fewer sweeps at h <= 0.1
  // -- unless the change dipped far below what that contraction predicts (chance, not convergence)
  if (sweep >= 2 && changeBefore > 0) {
    const double contraction = std::min(1.0, previousChange / changeBefore);
    if (relative * contraction < 1e-18 && relative >= 0.1 * contraction * previousChange) {
      converged = true;
      return true;
    }
  }
  changeBefore = previousChange;
  previousChange = relative;
  return false;
}

// y_ = x_ + h sum_l A(j, l) F_l, column by column: every component summed in the same order whatever the
// number of components (a matrix product would sum a last odd row in another order than the vectorised ones,
// so an orbit's rounding would depend on the lanes stacked with it, and on its dimension's parity)
template <int N> void Everhart::nodeSum(double h, int j) {
  std::array<double, N> coefficients;
  for (int l = 0; l < N; ++l)
    coefficients[static_cast<std::size_t>(l)] = h * A_(j, l);
  everhart::combine(F_.data(), F_.rows(), N, coefficients.data(), x_.data(), y_.data());
}

// correct<N> on `lanes_` orbits stacked component-major: the same sweeps over all lanes (one evaluation of
// the stacked system each), but each lane measures its own change and stops by correct<N>'s rules; a lane
// that has converged keeps its node values while the others iterate on. Each orbit's nodes are then those it
// takes alone, bit for bit: the node sums y = x0 + h A F are row by row.
template <int N> void Everhart::correctLanes(double h) {
  const Eigen::Index width = lanes_, components = F_.rows() / width;
  const Eigen::Index controlledComponents = controlled(F_.rows()) / width;
  for (auto& rule : laneRules_)
    rule = Convergence{};
  std::fill(laneOpen_.begin(), laneOpen_.end(), -1);
  int open = lanes_;
  lastIterations_ = 0;
  for (int it = 0; it < maxIterations_ && open > 0; ++it) {
    ++lastIterations_;
    std::fill(laneChange_.begin(), laneChange_.end(), 0.0);
    std::fill(laneScale_.begin(), laneScale_.end(), 0.0);
    for (int j = 1; j < N; ++j) {
      nodeSum<N>(h, j);
      model_->rhs(y_.data(), f1_.data());
      ++evaluations_;
      everhart::scanLanes(f1_.data(), F_.col(j).data(), components, controlledComponents, lanes_,
                          laneOpen_.data(), laneChange_.data(), laneScale_.data());
    }
    for (std::size_t l = 0; l < laneRules_.size(); ++l) { // correct<N>'s stopping rule, lane by lane
      const double change = laneChange_[l], scale = laneScale_[l];
      if (laneOpen_[l] != 0 && laneRules_[l].reached(it, scale > 0 ? change / scale : change)) {
        laneOpen_[l] = 0;
        --open;
      }
    }
  }
}

template <int N> void Everhart::stepWith() {
  F_.swap(Fnew_); // Fnew_: the last step's nodes, kept while a rejected step is redone
  for (int attempt = 0;; ++attempt) {
    const double h = direction_ * h_;
    // predictor: the last step's polynomial continued over this one (a step `ratio` times as long), plus,
    // when the step is unchanged, what the continuation missed on the last step; a constant on the first
    // step. As in IAS15 (its e and b - e), predicted_ keeps the bare continuation, so the correction is the
    // miss of the continuation alone: measured against the corrected prediction it alternated, and the
    // corrector needed 8-20 % more sweeps (chaplygin_ball, h = 0.02-0.5).
    if (havePrevious_) {
      const double ratio = h_ / lastStep_;
      if (ratio != lastRatio_) setExtrapolation(ratio);
      for (int j = 0; j < N; ++j) // column by column: each component's sum in one order (nodeSum)
        everhart::combine(Fnew_.data(), Fnew_.rows(), N, &extrapolate_(0, j), nullptr, F_.col(j).data());
      predicted_ = F_;
      if (ratio == 1) F_ += correction_;
    } else {
      F_ = f1_.replicate(1, N);
      predicted_ = F_;
    }
    F_.col(0) = f1_;
    predicted_.col(0) = f1_;
    const double error = correct<N>(h);
    double next = h_;
    if (tolerance_ > 0) {
      // IAS15 (Rein & Spiegel 2015, eq. 11): the step that brings the last coefficient to the tolerance; a
      // step more than 4 times too long is redone, and a step grows at most 4 times
      next = error > 0 ? h_ * std::pow(tolerance_ / error, 1.0 / (N - 1)) : 4 * h_;
      if (!std::isfinite(next)) next = h_ / 4;
      if (next < 0.25 * h_) {
        ++rejected_;
        if (attempt >= 30 || next < 1e-14 * std::max(1.0, std::abs(t_)))
          throw ComputationError(
              format("Everhart: the adaptive step fell to %g at t = %.12g (the tolerance %g "
                     "cannot be met; the solution may be singular there)",
                     next, t_, tolerance_) +
              nonFiniteField());
        h_ = next;
        continue;
      }
      next = std::min(next, 4 * h_);
    }
    // what the predictor missed, carried into the next prediction (not from the first step's constant guess)
    if (havePrevious_) correction_ = F_ - predicted_;
    // x1 = x0 + h sum_j b_j F_j, with compensated (Kahan) summation across steps.
    // The increment as f(x0) plus the weighted differences F_j - F_0: the weights of f(x0) add up to 1 by
    // construction. With sum_j b_j F_j instead, the stored b_j summed to 1 + 1.4e-17 and every step moved the
    // state that much too far along its chord: a bias that made the energy drift linearly (Brouwer's law
    // holds for rounding that is random, not for a fixed error of the method's coefficients).
    everhart::increment(F_.data(), F_.rows(), N, b_.data(), h, sum_.data());
    advanceCompensated(h, sum_, compensation_);
    evaluate(x_, f1_);
    havePrevious_ = true;
    lastStep_ = h_;
    h_ = next;
    return;
  }
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
  s.put(h_), s.put(lastStep_), s.put(static_cast<double>(rejected_));
  s.put(F_), s.put(predicted_), s.put(correction_), s.put(compensation_), s.put(f1_);
}

void Everhart::restore(Snapshot& s) {
  Integrator::restore(s);
  havePrevious_ = s.get() != 0;
  h_ = s.get(), lastStep_ = s.get(), rejected_ = s.getLong();
  s.get(F_), s.get(predicted_), s.get(correction_), s.get(compensation_), s.get(f1_);
  if (F_.rows() != x_.size() || F_.cols() != n_)
    throw InputError("checkpoint: saved for another Everhart order");
}

} // namespace rv
