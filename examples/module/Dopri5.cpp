#include "Dopri5.h"

#include "dynamics/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace rossler {

namespace {
// Hairer, Norsett & Wanner I, table 5.2 (DOPRI5)
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
// the fifth-order weights minus the fourth-order ones
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                 e6 = 22.0 / 525, e7 = -1.0 / 40;
// the continuous extension (Shampine 1986; Hairer's dopri5.f)
constexpr double d1 = -12715105075.0 / 11282082432, d3 = 87487479700.0 / 32700410799,
                 d4 = -10690763975.0 / 1880347072, d5 = 701980252875.0 / 199316789632,
                 d6 = -1453857185.0 / 822651844, d7 = 69997945.0 / 29380423;
} // namespace

const rv::ParameterTable& Dopri5::parameterTable() {
  static const rv::ParameterTable table{
      {.id = "tolerance",
       .label = "Tolerance",
       .defaultValue = 1e-10,
       .min = 1e-16,
       .max = 1e-2,
       .description = "error allowed per step (the embedded 4th-order estimate), absolute for components "
                      "below 1 and relative above"},
      {.id = "adaptive",
       .label = "Adaptive step",
       .defaultValue = 1,
       .min = 0,
       .max = 1,
       .description = "choose each step from the error estimate; no: the constant `step`",
       .choices = {"no", "yes"}},
      {.id = "step",
       .label = "Step",
       .defaultValue = 0.01,
       .min = 1e-12,
       .max = 1e3,
       .description = "the first step when adaptive, else the constant step"},
  };
  return table;
}

rv::IntegratorEntry Dopri5::entry() {
  return {"dopri5",
          "Dormand-Prince 5(4), explicit Runge-Kutta, adaptive step, dense output of order 4 "
          "(from the example module)",
          "Dormand & Prince, J. Comput. Appl. Math. 6 (1980) 19-26; Hairer, Norsett, Wanner I §II.5",
          &parameterTable(), [](const rv::ParameterValues& p) -> std::unique_ptr<rv::Integrator> {
            return std::make_unique<Dopri5>(p["tolerance"], p["step"], p["adaptive"] == 0);
          }};
}

Dopri5::Dopri5(double tolerance, double step, bool fixedStep)
    : tolerance_(tolerance), h_(step), fixed_(fixedStep) {
  if (!(tolerance > 0)) throw rv::InputError("integrator.tolerance: must be positive");
  if (!(step > 0) || !std::isfinite(step)) throw rv::InputError("integrator.step: must be positive");
}

void Dopri5::start(const rv::Model& model, double t0, const Eigen::VectorXd& x0, int direction) {
  requireFlow(model);
  Integrator::start(model, t0, x0, direction);
  for (auto* v : {&k1_, &k2_, &k3_, &k4_, &k5_, &k6_, &k7_, &y_, &err_, &r2_, &r3_, &r4_, &r5_})
    v->setZero(x0.size());
  evaluate(x_, k1_);
}

void Dopri5::step() {
  for (int attempt = 0;; ++attempt) {
    const double h = direction_ * h_;
    y_ = x_ + h * a21 * k1_;
    evaluate(y_, k2_);
    y_ = x_ + h * (a31 * k1_ + a32 * k2_);
    evaluate(y_, k3_);
    y_ = x_ + h * (a41 * k1_ + a42 * k2_ + a43 * k3_);
    evaluate(y_, k4_);
    y_ = x_ + h * (a51 * k1_ + a52 * k2_ + a53 * k3_ + a54 * k4_);
    evaluate(y_, k5_);
    y_ = x_ + h * (a61 * k1_ + a62 * k2_ + a63 * k3_ + a64 * k4_ + a65 * k5_);
    evaluate(y_, k6_);
    y_ = x_ + h * (b1 * k1_ + b3 * k3_ + b4 * k4_ + b5 * k5_ + b6 * k6_); // fifth order
    evaluate(y_, k7_);                                                    // = k1 of the next step (FSAL)
    err_ = h * (e1 * k1_ + e3 * k3_ + e4 * k4_ + e5 * k5_ + e6 * k6_ + e7 * k7_);
    double err = 0;
    for (Eigen::Index i = 0; i < x_.size(); ++i) {
      const double scale = std::max(1.0, std::max(std::abs(x_[i]), std::abs(y_[i])));
      err = std::max(err, std::abs(err_[i]) / (tolerance_ * scale));
    }
    if (!std::isfinite(err)) err = 1e10; // a blow-up inside the step: shorten it (checkFinite decides later)
    // the embedded estimate is of order 4: its error goes like h^5 (HNW I (4.13))
    const double grow = err > 0 ? std::clamp(0.9 * std::pow(err, -0.2), 0.2, 5.0) : 5.0;
    if (!fixed_ && err > 1) {
      h_ *= std::min(grow, 0.9);
      if (attempt >= 50 || h_ < 1e-14 * std::max(1.0, std::abs(t_)))
        throw rv::ComputationError("dopri5: the step fell to " + std::to_string(h_) +
                                   " at t = " + std::to_string(t_) + " (the tolerance cannot be met)");
      continue;
    }
    // the dense output's coefficients (Hairer's rcont2..rcont5), from the step's stages
    r2_ = y_ - x_;
    r3_ = h * k1_ - r2_;
    r4_ = r2_ - h * k7_ - r3_;
    r5_ = h * (d1 * k1_ + d3 * k3_ + d4 * k4_ + d5 * k5_ + d6 * k6_ + d7 * k7_);
    xPrev_ = x_;
    tPrev_ = t_;
    x_ = y_;
    t_ += h;
    k1_ = k7_;
    checkFinite();
    if (!fixed_) h_ *= grow;
    return;
  }
}

void Dopri5::interpolate(double t, Eigen::VectorXd& out) const {
  const double h = t_ - tPrev_;
  if (h == 0) {
    out = x_;
    return;
  }
  const double s = (t - tPrev_) / h, s1 = 1 - s;
  out = xPrev_ + s * (r2_ + s1 * (r3_ + s * (r4_ + s1 * r5_)));
}

void Dopri5::save(rv::Snapshot& s) const {
  Integrator::save(s);
  s.put(h_), s.put(k1_), s.put(r2_), s.put(r3_), s.put(r4_), s.put(r5_);
}

void Dopri5::restore(rv::Snapshot& s) {
  Integrator::restore(s);
  h_ = s.get();
  s.get(k1_), s.get(r2_), s.get(r3_), s.get(r4_), s.get(r5_);
}

} // namespace rossler
