#include "dynamics/integrators/Merson.h"

#include "dynamics/core/Errors.h"
#include "dynamics/integrators/LaneStages.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <sstream>
#include <stdexcept>

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
       .description = "requested local error per step (max norm): absolute where |x| < 1, relative above"},
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
  if (laneSteps_ > 0)
    laneH_.assign(static_cast<std::size_t>(laneSteps_), h_), hs_ = laneH_, part_.resize(laneSteps_);
  evaluate(x_, k1_);
}

bool Merson::stepLanesAlone(int width) {
  if (width < 1) return false;
  takeLaneSteps(width);
  return true;
}

bool Merson::judge(double err, double& h, double t) {
  if (std::isfinite(err) && err <= precision_) {
    const double grow = err > 0 ? std::clamp(0.9 * std::pow(precision_ / err, 0.2), 1.0, 5.0) : 5.0;
    h = std::min(maxStep_, h * grow);
    return true;
  }
  ++rejected_;
  const double shrink =
      std::isfinite(err) ? std::clamp(0.9 * std::pow(precision_ / err, 0.2), 0.1, 0.9) : 0.1;
  if (h <= minStep_) {
    std::ostringstream os;
    os << "Merson: the step reached its minimum " << minStep_ << " at t = " << t << " with a local error "
       << err << " above the precision " << precision_ << " (lower min_step or relax precision)";
    throw ComputationError(os.str());
  }
  h = std::max(minStep_, h * shrink);
  return false;
}

void Merson::step() {
  if (laneSteps_ > 0) throw std::logic_error("Merson: lanes with steps of their own go with advanceTo");
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
    tmp_ = (h / 6) * (k1_ + 4 * k4_ + k5_); // the increment
    const double err = relativeError(err_.data(), x_.data(), tmp_.data(), 0, 1, controlled(err_.size()));
    double next = h_;
    if (!judge(err, next, t_)) {
      h_ = next;
      continue;
    }
    xPrev_ = x_;
    fPrev_ = k1_;
    x_ += tmp_;
    tPrev_ = t_;
    t_ += h;
    checkFinite();
    evaluate(x_, k1_);
    h_ = next;
    return;
  }
}

// step() on every lane at once, each with its own h (0 for a lane that stands still): each vector expression
// of step() as a lane stage (LaneStages.h), so every element is computed as step() computes it
void Merson::stepLanes(const std::vector<char>& behind) {
  const int width = laneSteps_;
  const Eigen::Index rows = x_.size() / width;
  for (std::size_t l = 0; l < behind.size(); ++l)
    hs_[l] = behind[l] ? direction_ * laneH_[l] : 0.0;
  // x + (h / divisor) (c_0 k_0 + ...) on every lane into out
  const auto stage = [&](const double* x, double divisor, std::initializer_list<double> c,
                         std::initializer_list<const double*> k, Eigen::VectorXd& out) {
    for (std::size_t l = 0; l < hs_.size(); ++l)
      part_[static_cast<Eigen::Index>(l)] = hs_[l] / divisor;
    lanes::stage(x, part_.data(), c.begin(), k.begin(), static_cast<int>(c.size()), rows, width, out.data());
  };
  stage(x_.data(), 3, {1}, {k1_.data()}, tmp_);
  evaluate(tmp_, k2_);
  stage(x_.data(), 6, {1, 1}, {k1_.data(), k2_.data()}, tmp_);
  evaluate(tmp_, k3_);
  stage(x_.data(), 8, {1, 3}, {k1_.data(), k3_.data()}, tmp_);
  evaluate(tmp_, k4_);
  stage(x_.data(), 2, {1, -3, 4}, {k1_.data(), k3_.data(), k4_.data()}, tmp_);
  evaluate(tmp_, k5_);
  stage(nullptr, 30, {2, -9, 8, -1}, {k1_.data(), k3_.data(), k4_.data(), k5_.data()}, err_);
  stage(nullptr, 6, {1, 4, 1}, {k1_.data(), k4_.data(), k5_.data()}, tmp_); // the increment, where accepted
  const Eigen::Index controlledRows = controlled(x_.size()) / width;
  bool moved = false;
  for (int l = 0; l < width; ++l) {
    const auto lane = static_cast<std::size_t>(l);
    if (!behind[lane]) continue;
    const double error = relativeError(err_.data(), x_.data(), tmp_.data(), l, width, controlledRows);
    if (!judge(error, laneH_[lane], laneTime_[lane])) continue;
    for (Eigen::Index i = l; i < x_.size(); i += width) {
      xPrev_[i] = x_[i], fPrev_[i] = k1_[i];
      x_[i] += tmp_[i];
    }
    lanePrevious_[lane] = laneTime_[lane];
    laneTime_[lane] += hs_[lane];
    moved = true;
  }
  if (!moved) return;
  checkFinite();
  evaluate(x_, k1_); // a lane that stood still gets its own f again, bit for bit
}

void Merson::interpolateLane(int lane, double t, Eigen::VectorXd& out) const {
  hermiteLane(lane, t, fPrev_, k1_, out);
}

void Merson::interpolate(double t, Eigen::VectorXd& out) const {
  hermite(t, fPrev_, k1_, out);
}

void Merson::save(Snapshot& s) const {
  if (laneSteps_ > 0) throw std::logic_error("Merson: lanes with steps of their own are not saved");
  Integrator::save(s);
  s.put(h_), s.put(static_cast<double>(rejected_)), s.put(fPrev_), s.put(k1_);
}

void Merson::restore(Snapshot& s) {
  Integrator::restore(s);
  h_ = s.get(), rejected_ = s.getLong();
  s.get(fPrev_), s.get(k1_);
}

} // namespace rv
