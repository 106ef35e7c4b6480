#include "dynamics/integrators/Integrator.h"

#include "dynamics/core/Errors.h"
#include "dynamics/integrators/Rk4.h"

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

void Integrator::checkFinite() const {
  if (!x_.allFinite()) {
    std::ostringstream os;
    os << "the solution stopped being finite at t = " << t_ << " (blow-up; try a smaller step)";
    throw ComputationError(os.str());
  }
}

const IntegratorRegistry& IntegratorRegistry::builtin() {
  static const IntegratorRegistry registry = [] {
    IntegratorRegistry r;
    r.add(Rk4::entry());
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
