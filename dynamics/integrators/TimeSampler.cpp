#include "dynamics/integrators/TimeSampler.h"
#include "dynamics/core/Errors.h"

#include <cmath>

namespace rv {

bool sampleUniform(Integrator& integrator, double every, long count,
                   const std::function<bool(double, const Eigen::VectorXd&)>& visit) {
  const double t0 = integrator.time();
  const int dir = integrator.direction();
  Eigen::VectorXd x(integrator.state().size());
  for (long k = 0; k < count; ++k) {
    const double t = t0 + dir * static_cast<double>(k) * every;
    integrator.advanceTo(t, x);
    if (!visit(t, x)) return false;
  }
  return true;
}

bool sampleAt(Integrator& integrator, const std::vector<double>& times,
              const std::function<bool(double, const Eigen::VectorXd&)>& visit) {
  const int dir = integrator.direction();
  double last = integrator.previousTime(); // a resumed integrator's last step still holds its dense output
  for (const double t : times) {
    if (!std::isfinite(t) || dir * (t - last) < 0)
      throw InputError("t_eval: the times must be finite and run " +
                       std::string(dir > 0 ? "forward (ascending)" : "backward (descending)") +
                       " from the start, one direction only");
    last = t;
  }
  Eigen::VectorXd x(integrator.state().size());
  for (const double t : times) {
    integrator.advanceTo(t, x);
    if (!visit(t, x)) return false;
  }
  return true;
}

} // namespace rv
