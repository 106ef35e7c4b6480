#include "dynamics/integrators/Rk4.h"

#include "dynamics/core/Lanes.h"
#include "dynamics/core/Rk4Scheme.h"

namespace rv {

namespace {

// the large systems -- orbits stacked on lanes (dynamics/tools/MegnoLanes.h) -- whose combinations of stages
// are a fair share of a step: four elements in one AVX2 register
template <class Field>
[[gnu::target("avx2"), gnu::flatten]] void rk4StepAvx2(const Field& field, double h, long n, const double* y0,
                                                       const double* f0, double* k2, double* k3, double* k4,
                                                       double* tmp, double* y1) {
  rk4StepOnArrays<4>(field, h, n, y0, f0, k2, k3, k4, tmp, y1);
}

} // namespace

const ParameterTable& Rk4::parameterTable() {
  static const ParameterTable table{
      {.id = "step",
       .label = "Step",
       .defaultValue = 1e-3,
       .min = 1e-12,
       .max = 1e3,
       .description = "constant integration step"},
  };
  return table;
}

IntegratorEntry Rk4::entry() {
  return {.id = "rk4",
          .title = "Runge-Kutta 4, fixed step",
          .reference = "Hairer, Norsett, Wanner, Solving ODE I, §II.1",
          .parameters = &parameterTable(),
          .create = [](const ParameterValues& p) -> std::unique_ptr<Integrator> {
            return std::make_unique<Rk4>(p["step"]);
          }};
}

void Rk4::start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction) {
  Integrator::start(model, t0, x0, direction);
  const auto n = x0.size();
  k2_.resize(n), k3_.resize(n), k4_.resize(n), tmp_.resize(n), fPrev_.resize(n);
  k1_.resize(n);
  evaluate(x_, k1_); // k1 of the next step is f at the current state: kept, and used for dense output
}

void Rk4::step() {
  // small systems (tangent systems of low-dimensional models: Lorenz with three vectors is 12) take a path
  // with the size fixed at compile time: the same arithmetic per component, without the dynamic-size
  // loops' overhead, which is most of the cost when the right-hand side is a few nanoseconds
  switch (x_.size()) {
  case 3:
    return stepWith<3>();
  case 4:
    return stepWith<4>();
  case 6:
    return stepWith<6>();
  case 12:
    return stepWith<12>();
  case 20:
    return stepWith<20>();
  default:
    return stepWith<Eigen::Dynamic>();
  }
}

template <int D> void Rk4::stepWith() {
  using V = Eigen::Matrix<double, D, 1>;
  using M = Eigen::Map<V>;
  const Eigen::Index n = x_.size();
  const double h = direction_ * h_;
  // keep the step's start for dense output by swapping buffers, not copying them
  xPrev_.swap(x_);
  fPrev_.swap(k1_);
  M x(x_.data(), n), x0(xPrev_.data(), n), f0(fPrev_.data(), n), k2(k2_.data(), n), k3(k3_.data(), n),
      k4(k4_.data(), n), tmp(tmp_.data(), n);
  const auto field = [this](const M& y, M& dy) {
    model_->rhs(y.data(), dy.data());
    ++evaluations_;
  };
  if constexpr (D == Eigen::Dynamic) {
    // above 16 components: at 16 (the Chaplygin ball's state) the call into the AVX2 function cost more than
    // it saved -- Rk4Chaplygin 1.05x odeint with it, 1.00-1.01x without (bench_dynamics, 2026-11-29)
    if (n > 16 && cpuHasAvx2()) {
      rk4StepAvx2([&](const double* y, double* dy) { model_->rhs(y, dy), ++evaluations_; }, h, n, x0.data(),
                  f0.data(), k2.data(), k3.data(), k4.data(), tmp.data(), x.data());
    } else {
      rk4Step(field, h, x0, f0, k2, k3, k4, tmp, x);
    }
  } else {
    rk4Step(field, h, x0, f0, k2, k3, k4, tmp, x);
  }
  tPrev_ = t_;
  t_ = tPrev_ + h;
  checkFinite();
  evaluate(x_, k1_); // k1 of the next step, and the derivative at this end for dense output
}

void Rk4::interpolate(double t, Eigen::VectorXd& out) const {
  hermite(t, fPrev_, k1_, out);
}

void Rk4::save(Snapshot& s) const {
  Integrator::save(s);
  s.put(fPrev_), s.put(k1_);
}

void Rk4::restore(Snapshot& s) {
  Integrator::restore(s);
  s.get(fPrev_), s.get(k1_);
}

} // namespace rv
