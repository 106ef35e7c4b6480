#include "dynamics/integrators/Integrator.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/ExplainsNonFinite.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Adams.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Merson.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/integrators/Taylor.h"
#include "dynamics/integrators/Verner9.h"

#include <cmath>
#include <sstream>

namespace rv {

void Integrator::start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction) {
  if (x0.size() != model.dimension())
    throw InputError("initial state has " + std::to_string(x0.size()) + " components, " + model.info().id +
                     " needs " + std::to_string(model.dimension()));
  model_ = &model;
  t_ = tPrev_ = t0;
  x_ = xPrev_ = x0;
  direction_ = direction >= 0 ? +1 : -1;
  evaluations_ = 0;
}

void Integrator::save(Snapshot& s) const {
  s.put(t_), s.put(tPrev_), s.put(direction_), s.put(static_cast<double>(evaluations_));
  s.put(x_), s.put(xPrev_);
}

void Integrator::restore(Snapshot& s) {
  const auto n = x_.size();
  t_ = s.get(), tPrev_ = s.get(), direction_ = s.get() < 0 ? -1 : +1, evaluations_ = s.getLong();
  s.get(x_), s.get(xPrev_);
  if (x_.size() != n || xPrev_.size() != n)
    throw InputError("checkpoint: the saved state has another dimension");
}

void Integrator::requireFlow(const Model& model) {
  if (model.isMap()) throw InputError(model.info().id + " is a map: it is iterated, not integrated");
}

void Integrator::requireFinite(const Eigen::VectorXd& x, double t, const char* what) {
  // a NaN or an infinity anywhere makes the sum non-finite (so does a sum past 1e308: a blow-up too); one
  // vectorised reduction instead of a test per component
  if (!std::isfinite(x.sum())) {
    std::ostringstream os;
    os << what << " stopped being finite at t = " << t << " (blow-up; try a smaller step)";
    throw ComputationError(os.str());
  }
}

void Integrator::checkFinite() const {
  if (std::isfinite(x_.sum())) return;
  try {
    requireFinite(x_, t_, "the solution");
  } catch (const ComputationError& e) {
    // a model written as equations names the expression that went non-finite at the step's start
    const auto* explains = dynamic_cast<const ExplainsNonFinite*>(model_);
    const std::string cause =
        explains && xPrev_.size() == x_.size() ? explains->nonFiniteCause(xPrev_.data()) : "";
    if (cause.empty()) throw;
    throw ComputationError(std::string(e.what()) + "; " + cause);
  }
}

void Integrator::advanceCompensated(double h, const Eigen::VectorXd& increment,
                                    Eigen::VectorXd& compensation) {
  xPrev_ = x_;
  tPrev_ = t_;
  for (Eigen::Index i = 0; i < x_.size(); ++i) {
    const double y = increment[i] - compensation[i], sum = x_[i] + y;
    compensation[i] = (sum - x_[i]) - y;
    x_[i] = sum;
  }
  t_ = tPrev_ + h;
  checkFinite();
}

void Integrator::hermite(double t, const Eigen::VectorXd& fPrev, const Eigen::VectorXd& f,
                         Eigen::VectorXd& out) const {
  const double h = t_ - tPrev_;
  if (h == 0) {
    out = x_;
    return;
  }
  const double s = (t - tPrev_) / h, s2 = s * s, s3 = s2 * s;
  out = (2 * s3 - 3 * s2 + 1) * xPrev_ + ((s3 - 2 * s2 + s) * h) * fPrev + (-2 * s3 + 3 * s2) * x_ +
        ((s3 - s2) * h) * f;
}

const IntegratorRegistry& IntegratorRegistry::global() {
  return mutableGlobal();
}

void IntegratorRegistry::add(IntegratorEntry entry) {
  if (const IntegratorEntry* e = find(entry.id))
    throw InputError(alreadyRegistered("integrator", entry.id, e->origin));
  entries_.push_back(std::move(entry));
}

const IntegratorEntry* IntegratorRegistry::find(const std::string& id) const {
  for (const auto& e : entries_)
    if (e.id == id) return &e;
  return nullptr;
}

IntegratorRegistry& IntegratorRegistry::mutableGlobal() {
  static IntegratorRegistry registry = [] {
    IntegratorRegistry r;
    r.add(Rk4::entry());
    r.add(Merson::entry());
    r.add(Everhart::entry());
    r.add(Taylor::entry());
    r.add(Verner9::entry());
    r.add(Adams::entry());
    return r;
  }();
  return registry;
}

const IntegratorEntry& IntegratorRegistry::get(const std::string& id) const {
  std::string known;
  for (const auto& e : entries_) {
    if (e.id == id) return e;
    known += " " + e.id;
  }
  throw InputError("unknown integrator '" + id + "' (known:" + known + ")");
}

} // namespace rv
