#include "dynamics/integrators/Rk4.h"

#include "dynamics/core/Lanes.h"
#include "dynamics/integrators/Rk4Scheme.h"

namespace rv {

namespace {

// rk4Step (Rk4Scheme.h) on arrays of n doubles, four at a time in one AVX2 register (the rest one by one):
// the large systems -- orbits stacked on lanes (dynamics/tools/MegnoLanes.h) -- whose combinations of stages
// are a fair share of a step. Each element takes the Eigen expression's operations in its order (no fused
// multiply-add), so the state is the one rk4Step gives, bit for bit.
template <class Combine> [[gnu::always_inline]] inline void eachElement(long n, Combine&& combine) {
  long i = 0;
  for (; i + kLanes <= n; i += kLanes)
    combine.template operator()<Lanes>(i);
  for (; i < n; ++i)
    combine.template operator()<double>(i);
}

template <class T> [[gnu::always_inline]] inline T loadAt(const double* p, long i) {
  if constexpr (std::is_same_v<T, Lanes>)
    return Lanes::load(p + i);
  else
    return p[i];
}

template <class T> [[gnu::always_inline]] inline void storeAt(double* p, long i, const T& v) {
  if constexpr (std::is_same_v<T, Lanes>)
    v.store(p + i);
  else
    p[i] = v;
}

template <class Field>
[[gnu::target("avx2"), gnu::flatten]] void rk4StepAvx2(const Field& field, double h, long n, const double* y0,
                                                       const double* f0, double* k2, double* k3, double* k4,
                                                       double* tmp, double* y1) {
  const auto plusScaled = [n, y0, tmp](double c, const double* k) { // tmp = y0 + c k
    eachElement(n, [&]<class T>(long i) { storeAt(tmp, i, loadAt<T>(y0, i) + T(c) * loadAt<T>(k, i)); });
  };
  plusScaled(0.5 * h, f0);
  field(tmp, k2);
  plusScaled(0.5 * h, k2);
  field(tmp, k3);
  plusScaled(h, k3);
  field(tmp, k4);
  const double c = h / 6.0;
  eachElement(n, [&]<class T>(long i) {
    const T sum = loadAt<T>(f0, i) + T(2.0) * loadAt<T>(k2, i) + T(2.0) * loadAt<T>(k3, i) + loadAt<T>(k4, i);
    storeAt(y1, i, loadAt<T>(y0, i) + T(c) * sum);
  });
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
          },
          .independentOrbits = true};
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
    if (n >= 4 * kLanes && cpuHasAvx2()) {
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
