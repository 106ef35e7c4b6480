#include "dynamics/tools/ReturnMap.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"
#include "dynamics/tools/TangentSystem.h"

#include <Eigen/LU>
#include <cmath>
#include <numbers>

namespace rv {

namespace {
constexpr double twoPi = 2 * std::numbers::pi;

std::string pointText(const Eigen::VectorXd& x) {
  std::string s = "(";
  for (Eigen::Index i = 0; i < x.size(); ++i)
    s += format("%s%.10g", i ? ", " : "", x[i]);
  return s + ")";
}

} // namespace

ReturnMap::Return ReturnMap::firstReturn(const Model& system, const Eigen::VectorXd& start,
                                         const Eigen::VectorXd& x, const ToolControl& control) const {
  auto integ = make_();
  integ->start(system, 0.0, start, backward_ ? -1 : +1);
  SectionSettings s = s_;
  s.maxPoints = 1, s.maxTime = maxReturnTime_;
  PoincareMap map(system, std::move(integ), s);
  const auto p = map.next(control);
  if (control.stopRequested()) throw Stopped{}; // not a truncated result
  if (!p)
    throw ComputationError(format("the trajectory from %s does not return to the section within t = %g",
                                  pointText(x).c_str(), maxReturnTime_));
  return {Eigen::Map<const Eigen::VectorXd>(p->coordinates.data(), dimension()), map.lastState()};
}

ReturnMap::ReturnMap(const Model& model, IntegratorFactory makeIntegrator, SectionSettings section,
                     double maxReturnTime)
    : model_(model), make_(std::move(makeIntegrator)), s_(std::move(section)), maxReturnTime_(maxReturnTime) {
  if (s_.order < 1) throw InputError("the order of the map must be at least 1");
  if (!(maxReturnTime_ > 0)) throw InputError("the maximal return time must be positive");
  const auto find = [&](const std::string& id) -> const Observable* {
    const int i = model.findObservable(id);
    return i < 0 ? nullptr : &model.observables()[i];
  };
  names_ = model.info().mapCoordinates;
  if (names_.empty())
    throw InputError(model.info().id +
                     " has no map coordinates: its map cannot be searched for fixed points");
  if (!model.isMap()) {
    const std::string id = s_.observable.empty() ? model.info().section : s_.observable;
    section_ = find(id);
    if (!section_)
      throw InputError("poincare.section: unknown observable '" + id + "' of " + model.info().id);
  }
  for (const auto& n : names_) {
    const Observable* o = find(n);
    if (!o) throw InputError(model.info().id + ": no observable for the map coordinate " + n);
    coords_.push_back(o);
    periodic_.push_back(o->angle);
  }
  backward_ = s_.backward;
}

ReturnMap::ReturnMap(const ReturnMap& o)
    : model_(o.model_), make_(o.make_), s_(o.s_), maxReturnTime_(o.maxReturnTime_), names_(o.names_),
      coords_(o.coords_), section_(o.section_), periodic_(o.periodic_), backward_(o.backward_) {}

ReturnMap ReturnMap::inverse() const {
  ReturnMap r(*this);
  r.backward_ = !backward_;
  r.s_.backward = r.backward_;
  return r;
}

Eigen::VectorXd ReturnMap::difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  Eigen::VectorXd d = a - b;
  for (int i = 0; i < dimension(); ++i)
    if (periodic_[i]) d[i] = std::remainder(d[i], twoPi);
  return d;
}

Eigen::VectorXd ReturnMap::canonical(const Eigen::VectorXd& x) const {
  Eigen::VectorXd c = x;
  for (int i = 0; i < dimension(); ++i)
    if (periodic_[i]) c[i] -= twoPi * std::floor(c[i] / twoPi);
  return c;
}

Eigen::VectorXd ReturnMap::alignTo(const Eigen::VectorXd& x, const Eigen::VectorXd& reference) const {
  Eigen::VectorXd a = x;
  for (int i = 0; i < dimension(); ++i)
    if (periodic_[i]) a[i] -= twoPi * std::round((x[i] - reference[i]) / twoPi);
  return a;
}

Eigen::VectorXd ReturnMap::stateOf(const Eigen::VectorXd& x) const {
  if (!x.allFinite()) throw ComputationError("the map point " + pointText(x) + " is not finite");
  const std::vector<double> p(x.data(), x.data() + x.size());
  try {
    return model_.stateFromMap(p, MapPointSpec{.sectionValue = s_.value, .root = s_.root}, "map point");
  } catch (const InputError& e) {
    throw ComputationError("the point " + pointText(x) + " lies outside the region of allowed motion (" +
                           e.what() + ")");
  }
}

bool ReturnMap::allowed(const Eigen::VectorXd& x) const {
  try {
    stateOf(x);
    return true;
  } catch (const ComputationError&) {
    return false;
  }
}

Eigen::VectorXd ReturnMap::iterateMap(const Eigen::VectorXd& x, Eigen::MatrixXd* jacobian) const {
  const int n = model_.dimension();
  Eigen::VectorXd a = x, b(n);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> J(n, n);
  if (jacobian) jacobian->setIdentity(n, n);
  for (int k = 0; k < s_.order; ++k) {
    if (backward_) {
      b = invertMapOnce(a);
      if (jacobian) {
        model_.jacobian(b.data(), J.data());
        *jacobian = J.partialPivLu().solve(*jacobian); // D(P^-1) = (DP at the preimage)^-1
      }
    } else {
      model_.rhs(a.data(), b.data());
      if (jacobian) {
        model_.jacobian(a.data(), J.data());
        *jacobian = J * *jacobian;
      }
    }
    a.swap(b);
    if (!a.allFinite()) throw ComputationError("the map diverged from " + pointText(x));
  }
  return a;
}

Eigen::VectorXd ReturnMap::invertMapOnce(const Eigen::VectorXd& y) const {
  // Newton on P(z) = y from z = y (explicit maps have no inverse formula in general)
  const int n = model_.dimension();
  Eigen::VectorXd z = y, p(n);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> J(n, n);
  for (int it = 0; it < 60; ++it) {
    model_.rhs(z.data(), p.data());
    const Eigen::VectorXd r = difference(p, y);
    if (r.norm() <= 1e-15 * (1 + y.norm())) return z;
    model_.jacobian(z.data(), J.data());
    z -= J.partialPivLu().solve(r);
  }
  model_.rhs(z.data(), p.data());
  if (difference(p, y).norm() <= 1e-12 * (1 + y.norm())) return z;
  throw ComputationError("the inverse map did not converge at " + pointText(y));
}

Eigen::VectorXd ReturnMap::operator()(const Eigen::VectorXd& x, const ToolControl& control) const {
  ++evaluations_;
  if (model_.isMap()) return iterateMap(x, nullptr);
  return firstReturn(model_, stateOf(x), x, control).coordinates;
}

Linearization ReturnMap::linearize(const Eigen::VectorXd& x, const DerivativeSettings& s,
                                   const ToolControl& control) const {
  if (s.method == DerivativeMethod::Variational) return variational(x, control);
  return finiteDifferences(x, s, control);
}

Linearization ReturnMap::finiteDifferences(const Eigen::VectorXd& x, const DerivativeSettings& s,
                                           const ToolControl& control) const {
  if (!(s.linearRegion > 0) || !(s.zero > 0) || !(s.accuracy > 0))
    throw InputError("derivatives: the linear approximation region, accuracy and zero must be positive");
  const int d = dimension();
  Linearization lin{.image = (*this)(x, control), .jacobian = Eigen::MatrixXd(d, d)};
  std::string why;
  for (double h = s.linearRegion; h >= s.zero; h /= 2) {
    double worst = 0;
    bool ok = true;
    for (int i = 0; i < d && ok; ++i) {
      Eigen::VectorXd a = x, b = x;
      a[i] += h, b[i] -= h;
      try {
        const Eigen::VectorXd pa = difference((*this)(a, control), lin.image);
        const Eigen::VectorXd pb = difference((*this)(b, control), lin.image);
        lin.jacobian.col(i) = (pa - pb) / (2 * h);
        // how far the map bends over the step: |Map(x + dx) - Lin(x + dx)| for dx = +-h e_i
        worst = std::max(worst, 0.5 * (pa + pb).norm());
      } catch (const ComputationError& e) {
        ok = false, why = e.what();
      }
    }
    if (ok && worst <= s.accuracy) {
      lin.step = h;
      return lin;
    }
    if (ok) why = format("|Map(x + dx) - Lin(x + dx)| = %.3g at |dx| = %.3g", worst, h);
  }
  throw ComputationError(
      format("derivatives at %s: the step reached the value of zero (%g) before the linear "
             "approximation agreed with the map to %g; last: %s",
             pointText(x).c_str(), s.zero, s.accuracy, why.c_str()));
}

Eigen::RowVectorXd ReturnMap::observableGradient(const Observable& o, const Eigen::VectorXd& x) const {
  const int m = model_.info().coreDimension;
  Eigen::RowVectorXd g(m);
  Eigen::VectorXd y = x;
  for (int i = 0; i < m; ++i) {
    const double h = 6e-6 * std::max(1.0, std::abs(x[i])); // ~ eps^(1/3): balances truncation and rounding
    y[i] = x[i] + h;
    double fp = o.value(0, y.data());
    y[i] = x[i] - h;
    double fm = o.value(0, y.data());
    y[i] = x[i];
    double df = fp - fm;
    if (o.angle) df = std::remainder(df, twoPi);
    g[i] = df / (2 * h);
  }
  return g;
}

Linearization ReturnMap::variational(const Eigen::VectorXd& x, const ToolControl& control) const {
  const int d = dimension();
  if (model_.isMap()) {
    ++evaluations_;
    Linearization lin;
    lin.image = iterateMap(x, &lin.jacobian);
    return lin;
  }
  const int n = model_.dimension(), m = model_.info().coreDimension;
  // the completion's derivative DC (core components) by central differences: it is algebraic and cheap
  const Eigen::VectorXd s0 = stateOf(x);
  Eigen::MatrixXd DC(m, d);
  for (int j = 0; j < d; ++j) {
    const double h = 1e-6 * std::max(1.0, std::abs(x[j]));
    Eigen::VectorXd a = x, b = x;
    a[j] += h, b[j] -= h;
    Eigen::VectorXd sa, sb;
    double span = 2 * h;
    try {
      sa = stateOf(a);
    } catch (const ComputationError&) {
      sa = s0, span = h;
    }
    try {
      sb = stateOf(b);
    } catch (const ComputationError&) {
      if (span == h) throw;
      sb = s0, span = h;
    }
    DC.col(j) = (sa.head(m) - sb.head(m)) / span;
  }
  // the orbit with d tangent vectors, to the n-th return
  TangentSystem tangent(model_, d);
  Eigen::VectorXd start(n + m * d);
  start.head(n) = s0;
  for (int j = 0; j < d; ++j)
    start.segment(n + j * m, m) = DC.col(j);
  ++evaluations_;
  const Return r = firstReturn(tangent, start, x, control);
  const Eigen::VectorXd& S = r.state;
  const Eigen::VectorXd base = S.head(n);
  Eigen::MatrixXd V(m, d);
  for (int j = 0; j < d; ++j)
    V.col(j) = S.segment(n + j * m, m);
  // the return time moves with the point: project along the flow onto the section
  Eigen::VectorXd f(n);
  model_.rhs(base.data(), f.data());
  const Eigen::RowVectorXd ds = observableGradient(*section_, base);
  const double rate = ds.dot(f.head(m));
  if (std::abs(rate) < 1e-14)
    throw ComputationError("the orbit from " + pointText(x) + " touches the section tangentially");
  V -= f.head(m) * (ds * V) / rate;
  Linearization lin{.image = r.coordinates, .jacobian = Eigen::MatrixXd(d, d)};
  for (int i = 0; i < d; ++i)
    lin.jacobian.row(i) = observableGradient(*coords_[i], base) * V;
  return lin;
}

} // namespace rv
