#include "dynamics/integrators/Merson.h"

#include "dynamics/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace rv {

const ParameterTable& Merson::parameterTable() {
  static const ParameterTable table{
      {.id = "step",
       .label = "Step",
       .defaultValue = 1e-2,
       .min = 1e-14,
       .max = 1e3,
       .description = "initial step (the method then chooses its own)"},
      {.id = "precision",
       .label = "Precision",
       .defaultValue = 1e-10,
       .min = 1e-16,
       .max = 1,
       .description = "requested local truncation error per step (max norm)"},
      {.id = "min_step",
       .label = "Min. step",
       .defaultValue = 1e-10,
       .min = 1e-16,
       .max = 1e3,
       .description = "the step may not fall below this (an error, not a silent loss of accuracy)"},
      {.id = "max_step",
       .label = "Max. step",
       .defaultValue = 0.1,
       .min = 1e-14,
       .max = 1e3,
       .description = "the step may not grow beyond this"},
  };
  return table;
}

IntegratorEntry Merson::entry() {
  return {"merson", "Runge-Kutta-Merson 4(5), adaptive step",
          "Merson 1957; Hairer, Norsett, Wanner, Solving ODE I, §II.4", &parameterTable(),
          [](const ParameterValues& p) -> std::unique_ptr<Integrator> {
            return std::make_unique<Merson>(p["step"], p["precision"], p["min_step"], p["max_step"]);
          }};
}

Merson::Merson(double step, double precision, double minStep, double maxStep)
    : h_(step), precision_(precision), minStep_(minStep), maxStep_(maxStep) {
  if (minStep > maxStep) throw InputError("min_step must not exceed max_step");
  if (step < minStep || step > maxStep) throw InputError("step must lie in [min_step, max_step]");
}

void Merson::start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction) {
  Integrator::start(model, t0, x0, direction);
  for (auto* v : {&k1_, &k2_, &k3_, &k4_, &k5_, &tmp_, &fPrev_, &err_})
    v->resize(x0.size());
  rejected_ = 0;
  evaluate(x_, k1_);
}

void Merson::step() {
  for (;;) {
    const double h = direction_ * h_;
    tmp_ = x_ + (h / 3) * k1_;
    evaluate(tmp_, k2_);
    tmp_ = x_ + (h / 6) * (k1_ + k2_);
    evaluate(tmp_, k3_);
    tmp_ = x_ + (h / 8) * (k1_ + 3 * k3_);
    evaluate(tmp_, k4_);
    tmp_ = x_ + (h / 2) * (k1_ - 3 * k3_ + 4 * k4_);
    evaluate(tmp_, k5_);
    err_ = (h / 30) * (2 * k1_ - 9 * k3_ + 8 * k4_ - k5_);
    const double err = err_.head(controlled(err_.size())).lpNorm<Eigen::Infinity>();
    if (!std::isfinite(err) || err > precision_) {
      ++rejected_;
      const double shrink =
          std::isfinite(err) ? std::clamp(0.9 * std::pow(precision_ / err, 0.2), 0.1, 0.9) : 0.1;
      if (h_ <= minStep_) {
        std::ostringstream os;
        os << "Merson: the step reached its minimum " << minStep_ << " at t = " << t_
           << " with a local error " << err << " above the precision " << precision_
           << " (lower min_step or relax precision)";
        throw ComputationError(os.str());
      }
      h_ = std::max(minStep_, h_ * shrink);
      continue;
    }
    xPrev_ = x_;
    fPrev_ = k1_;
    x_ += (h / 6) * (k1_ + 4 * k4_ + k5_);
    tPrev_ = t_;
    t_ += h;
    checkFinite();
    evaluate(x_, k1_);
    const double grow = err > 0 ? std::clamp(0.9 * std::pow(precision_ / err, 0.2), 1.0, 5.0) : 5.0;
    h_ = std::min(maxStep_, h_ * grow);
    return;
  }
}

void Merson::interpolate(double t, Eigen::VectorXd& out) const {
  hermite(t, fPrev_, k1_, out);
}

void Merson::save(Snapshot& s) const {
  Integrator::save(s);
  s.put(h_), s.put(static_cast<double>(rejected_)), s.put(fPrev_), s.put(k1_);
}

void Merson::restore(Snapshot& s) {
  Integrator::restore(s);
  h_ = s.get(), rejected_ = s.getLong();
  s.get(fPrev_), s.get(k1_);
}

} // namespace rv
