#include "dynamics/integrators/Taylor.h"

#include "dynamics/core/Errors.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace rv {

const ParameterTable& Taylor::parameterTable() {
  static const ParameterTable table{
      {.id = "tolerance",
       .label = "Tolerance",
       .defaultValue = 1e-15,
       .min = 1e-16,
       .max = 1e-2,
       .description = "error allowed per step, absolute for components below 1 and relative above; it sets "
                      "the order (ceil(-ln(tolerance)/2 + 1): 19 at 1e-15) and, when adaptive, the step"},
      {.id = "order",
       .label = "Order",
       .defaultValue = 0,
       .min = 0,
       .max = kMaxOrder,
       .description = "order of the series; 0 takes it from the tolerance",
       .integer = true},
      {.id = "adaptive",
       .label = "Adaptive step",
       .defaultValue = 1,
       .min = 0,
       .max = 1,
       .description = "choose each step from the series' last two coefficients (Jorba and Zou); no: the "
                      "constant `step`",
       .choices = {"no", "yes"}},
      {.id = "step",
       .label = "Step",
       .defaultValue = 0.1,
       .min = 1e-12,
       .max = 1e3,
       .description = "constant integration step when the step is not adaptive"},
  };
  return table;
}

IntegratorEntry Taylor::entry() {
  return {"taylor",
          "Taylor series by automatic differentiation of the model, order from the tolerance, adaptive step",
          "Jorba and Zou, Exp. Math. 14 (2005); Biscani and Izzo, MNRAS 504 (2021)", &parameterTable(),
          [](const ParameterValues& p) -> std::unique_ptr<Integrator> {
            return std::make_unique<Taylor>(p["tolerance"], static_cast<int>(p["order"]),
                                            p["adaptive"] != 0 ? 0.0 : p["step"]);
          }};
}

int Taylor::orderFor(double tolerance) {
  if (!(tolerance > 1e-300)) return kMaxOrder + 1; // refused by the constructor (and no overflow to int here)
  return std::max(2, static_cast<int>(std::ceil(-std::log(tolerance) / 2 + 1)));
}

Taylor::Taylor(double tolerance, int order, double step)
    : step_(step), order_(order > 0 ? order : orderFor(tolerance)) {
  if (!(tolerance > 0)) throw InputError("integrator.tolerance: must be positive");
  if (order <= 0 && order_ > kMaxOrder)
    throw InputError("integrator.tolerance: too small for the taylor method (order at most " +
                     std::to_string(kMaxOrder) + ")");
  if (order_ > kMaxOrder)
    throw InputError("integrator.order: at most " + std::to_string(kMaxOrder) + " for the taylor method");
  if (order_ < 1) throw InputError("integrator.order: at least 1");
}

void Taylor::start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction) {
  requireFlow(model);
  Integrator::start(model, t0, x0, direction);
  const auto n = x0.size();
  X_.setZero(n, order_ + 1);
  increment_.setZero(n);
  compensation_.setZero(n);
  lastStep_ = 0;
  model.recordField(tape_, x_.data()); // throws InputError for a model it cannot expand: before any step
  tape_.prepare(order_);
}

void Taylor::expand() {
  const int n = static_cast<int>(x_.size());
  if (tape_.branches()) { // the field took a branch on a value: record it again at this state
    model_->recordField(tape_, x_.data());
    tape_.prepare(order_);
  } else {
    tape_.setInputs(x_.data());
  }
  X_.col(0) = x_;
  // x^[k] = f^[k-1] / k: each order of the inputs comes from the order below of the field
  for (int k = 1; k <= order_; ++k) {
    for (int i = 0; i < n; ++i) {
      const double xk = tape_.output(i, k - 1) / k;
      X_(i, k) = xk;
      tape_.coefficients(i)[k] = xk;
    }
    if (k < order_) tape_.evaluate(k);
  }
  // counted as one evaluation per sweep of the tape (a sweep at order k costs ~k per product)
  evaluations_ += order_;
}

double Taylor::chooseStep() const {
  // rho = min over the last two orders j of (1 / |x^[j]|)^(1/j), each component measured against
  // max(1, |x_i|) (absolute below 1, relative above); h = rho / e^2 * exp(-0.7 / (p - 1))
  double rho = std::numeric_limits<double>::infinity();
  for (int j = std::max(1, order_ - 1); j <= order_; ++j) {
    double norm = 0;
    for (Eigen::Index i = 0, c = controlled(x_.size()); i < c; ++i)
      norm = std::max(norm, std::abs(X_(i, j)) / std::max(1.0, std::abs(x_[i])));
    if (norm > 0) rho = std::min(rho, std::pow(1 / norm, 1.0 / j));
  }
  // the series ends (a polynomial solution, an equilibrium): any step is exact; take a unit one
  if (!std::isfinite(rho)) return 1.0;
  return rho / (std::numbers::e * std::numbers::e) * std::exp(-0.7 / std::max(1, order_ - 1));
}

void Taylor::step() {
  expand();
  const double h = direction_ * (step_ > 0 ? step_ : chooseStep());
  // Horner from the top: increment = sum_{k>=1} X_k h^k
  increment_ = X_.col(order_);
  for (int k = order_ - 1; k >= 1; --k)
    increment_ = increment_ * h + X_.col(k);
  increment_ *= h;
  lastStep_ = h;
  advanceCompensated(h, increment_, compensation_);
}

void Taylor::interpolate(double t, Eigen::VectorXd& out) const {
  if (lastStep_ == 0) {
    out = x_;
    return;
  }
  if (t == t_) {
    out = x_;
    return;
  }
  const double tau = t - tPrev_;
  out = X_.col(order_);
  for (int k = order_ - 1; k >= 0; --k)
    out = out * tau + X_.col(k);
}

void Taylor::save(Snapshot& s) const {
  Integrator::save(s);
  s.put(lastStep_), s.put(X_), s.put(compensation_);
}

void Taylor::restore(Snapshot& s) {
  Integrator::restore(s);
  const auto rows = X_.rows(), cols = X_.cols();
  lastStep_ = s.get();
  s.get(X_), s.get(compensation_);
  if (X_.rows() != rows || X_.cols() != cols || compensation_.size() != rows)
    throw InputError("checkpoint: the saved Taylor series has another order or dimension");
}

} // namespace rv
