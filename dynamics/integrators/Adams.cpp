#include "dynamics/integrators/Adams.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/OneLane.h"
#include "dynamics/integrators/AdamsKernels.h"
#include "dynamics/integrators/Verner9.h"

#include <cmath>
#include <string>

namespace rv {

const ParameterTable& Adams::parameterTable() {
  static const ParameterTable table{
      {.id = "order",
       .label = "Order",
       .defaultValue = 12,
       .min = 2,
       .max = kMaxOrder,
       .description = "order of the corrector; the predictor uses the last order - 1 derivatives (the "
                      "higher the order, the shorter the longest stable step)",
       .integer = true},
      {.id = "step",
       .label = "Step",
       .defaultValue = 0.025,
       .min = 1e-12,
       .max = 1e3,
       .description = "constant integration step"},
  };
  return table;
}

IntegratorEntry Adams::entry() {
  return {"adams",
          "Adams-Bashforth-Moulton predictor-corrector (PECE), constant step, two evaluations a step",
          "Hairer, Norsett, Wanner, Solving ODE I, §III.1; Shampine and Gordon (1975)", &parameterTable(),
          [](const ParameterValues& p) -> std::unique_ptr<Integrator> {
            return std::make_unique<Adams>(p["step"], static_cast<int>(p["order"]));
          }};
}

Adams::Adams(double step, int order) : h_(step), k_(order - 1) {
  if (!(step > 0) || !std::isfinite(step)) throw InputError("integrator.step: must be positive");
  if (order < 2 || order > kMaxOrder)
    throw InputError("integrator.order: between 2 and " + std::to_string(kMaxOrder) +
                     " for the adams method");
  // gamma_j = 1 - sum_{i<j} gamma_i / (j + 1 - i) (HNW §III.1: the coefficients of -t / ((1 - t) ln(1 - t))),
  // in long double: the subtractions cancel
  std::array<long double, kMaxOrder> gamma{};
  for (int j = 0; j <= k_; ++j) {
    long double s = 0;
    for (int i = 0; i < j; ++i)
      s += gamma[i] / (j + 1 - i);
    gamma[j] = 1 - s;
    gamma_[j] = static_cast<double>(gamma[j]);
  }
  // binom(u + j - 1, j) = binom(u + j - 2, j - 1) (u + j - 1) / j, as polynomials in u, then integrated
  std::array<std::array<long double, kMaxOrder>, kMaxOrder> poly{};
  poly[0][0] = 1;
  for (int j = 1; j < k_; ++j)
    for (int m = 0; m <= j; ++m)
      poly[j][m] = ((m > 0 ? poly[j - 1][m - 1] : 0.0L) + (j - 1) * poly[j - 1][m]) / j;
  for (int j = 0; j < k_; ++j)
    for (int m = 0; m <= j; ++m)
      integrated_[j][m] = static_cast<double>(poly[j][m] / (m + 1));
}

void Adams::start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction) {
  requireFlow(model);
  Integrator::start(model, t0, x0, direction);
  const auto n = x0.size();
  D_.setZero(n, k_);
  startStates_.setZero(n, k_);
  predicted_.resize(n), fp_.resize(n), sum_.resize(n), increment_.resize(n);
  compensation_.setZero(n);
  taken_ = 0;
  // the starting values at t0 + j h, j < k: Verner's pair near rounding, read off its interpolant; on lanes
  // orbit by orbit (its adaptive steps read the whole state), each as alone
  startStates_.col(0) = x0;
  if (lanes_ == 1) {
    startingValues(model, t0, x0, startStates_);
  } else {
    for (int l = 0; l < lanes_; ++l) {
      const OneLane lane(model, lanes_, l, x0);
      Eigen::MatrixXd states(lane.dimension(), k_);
      const Model* own = model.laneSystem(l);
      startingValues(own != nullptr ? *own : lane, t0, lane.of(x0), states);
      for (int j = 1; j < k_; ++j)
        lane.put(states.col(j), startStates_.col(j));
    }
  }
  double t = t0;
  for (int j = 1; j < k_; ++j)
    t += direction_ * h_;
  tD_ = t;
  // their derivatives, and the backward differences at the last one: D_j = nabla^j f_{k-1}
  Eigen::MatrixXd f(n, k_);
  for (int j = 0; j < k_; ++j) {
    model_->rhs(startStates_.col(j).data(), f.col(j).data());
    ++evaluations_;
  }
  for (int j = 0; j < k_; ++j) {
    D_.col(j) = f.col(k_ - 1);
    for (int i = k_ - 1; i > j; --i)
      f.col(i) -= f.col(i - 1);
  }
}

void Adams::startingValues(const Model& model, double t0, const Eigen::VectorXd& x0,
                           Eigen::MatrixXd& states) {
  if (k_ < 2) return;
  Verner9 starter(1e-15, h_);
  // controlled like the steps that follow (controlBy: a tangent system's orbit alone), per orbit on lanes
  if (controlled_ > 0) starter.controlBy(controlled_ / lanes_);
  starter.scaleErrorsByBlocks(blockHead_, blockSize_); // a tangent system's orbit and vectors, each its scale
  starter.start(model, t0, x0, direction_);
  Eigen::VectorXd at(x0.size());
  double t = t0;
  for (int j = 1; j < k_; ++j) {
    t += direction_ * h_;
    while (direction_ * (starter.time() - t) < 0)
      starter.step();
    starter.interpolate(t, at);
    states.col(j) = at;
  }
  evaluations_ += starter.evaluations() + starter.denseEvaluations();
}

bool Adams::stepLanesAlone(int width) {
  if (width < 1) return false;
  lanes_ = width;
  return true;
}

void Adams::step() {
  const double h = direction_ * h_;
  if (taken_ + 1 < k_) { // a starting value
    xPrev_ = x_;
    tPrev_ = t_;
    x_ = startStates_.col(++taken_);
    t_ = tPrev_ + h;
    return;
  }
  const Eigen::Index n = x_.size();
  // P: the explicit formula on nabla^j f_n; the differences summed for nabla^k f at the predicted point
  adams::predict(D_.data(), n, k_, gamma_.data(), h, x_.data(), increment_.data(), sum_.data(),
                 predicted_.data(), avx2_);
  model_->rhs(predicted_.data(), fp_.data()); // E
  ++evaluations_;
  // C: the predictor plus h gamma_k nabla^k f^p_{n+1}, nabla^k f^p_{n+1} = f^p - sum_{j<k} nabla^j f_n
  const double gk = h * gamma_[static_cast<std::size_t>(k_)];
  for (Eigen::Index i = 0; i < n; ++i)
    increment_[i] += gk * (fp_[i] - sum_[i]);
  advanceCompensated(h, increment_, compensation_);
  // E: f at the corrected point, and the differences moved to it
  model_->rhs(x_.data(), fp_.data());
  ++evaluations_;
  adams::shift(D_.data(), n, k_, fp_.data(), avx2_);
  ++taken_;
  tD_ = t_;
}

void Adams::integratedWeights(double s, double* weights) const {
  for (int j = 0; j < k_; ++j) {
    const auto& c = integrated_[static_cast<std::size_t>(j)];
    double acc = 0;
    for (int m = j; m >= 0; --m)
      acc = acc * s + c[static_cast<std::size_t>(m)];
    weights[j] = acc * s;
  }
}

void Adams::interpolate(double t, Eigen::VectorXd& out) const {
  if (t == t_ || t_ == tPrev_) {
    out = x_;
    return;
  }
  // x(t) = x(t_) + h (int_0^s - int_0^{s_end}) p(u) du, p the polynomial through the derivatives in D_ (at
  // tD_ + u h); s_end = 0 once the starting values are behind
  const double h = direction_ * h_;
  integratedWeights((t - tD_) / h, weights_.data());
  integratedWeights((t_ - tD_) / h, weightsEnd_.data());
  out = x_;
  for (int j = 0; j < k_; ++j)
    out +=
        (h * (weights_[static_cast<std::size_t>(j)] - weightsEnd_[static_cast<std::size_t>(j)])) * D_.col(j);
}

void Adams::save(Snapshot& s) const {
  Integrator::save(s);
  s.put(static_cast<double>(taken_)), s.put(tD_);
  s.put(D_), s.put(startStates_), s.put(compensation_);
}

void Adams::restore(Snapshot& s) {
  Integrator::restore(s);
  const auto rows = D_.rows(), cols = D_.cols();
  taken_ = s.getLong(), tD_ = s.get();
  s.get(D_), s.get(startStates_), s.get(compensation_);
  if (D_.rows() != rows || D_.cols() != cols || startStates_.cols() != cols || compensation_.size() != rows)
    throw InputError("checkpoint: the saved Adams differences have another order or dimension");
}

} // namespace rv
