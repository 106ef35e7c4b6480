#include "dynamics/integrators/MapIteration.h"

#include "dynamics/core/Errors.h"

namespace rv {

void MapIteration::start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction) {
  if (!model.isMap())
    throw InputError(model.info().id + " is a flow: it needs an integrator, not map iteration");
  if (direction < 0) throw InputError(model.info().id + ": backward iteration of a map is not supported");
  Integrator::start(model, t0, x0, direction);
}

void MapIteration::step() {
  xPrev_ = x_;
  model_->rhs(xPrev_.data(), x_.data());
  ++evaluations_;
  tPrev_ = t_;
  t_ += 1;
  checkFinite();
}

void MapIteration::interpolate(double t, Eigen::VectorXd& out) const {
  out = t >= t_ ? x_ : xPrev_;
}

} // namespace rv
