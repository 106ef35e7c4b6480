#include "dynamics/integrators/TimeSampler.h"

namespace rv {

bool sampleUniform(Integrator& integrator, double every, long count,
                   const std::function<bool(double, const Eigen::VectorXd&)>& visit) {
  const double t0 = integrator.time();
  const int dir = integrator.direction();
  Eigen::VectorXd x(integrator.state().size());
  for (long k = 0; k < count; ++k) {
    const double t = t0 + dir * static_cast<double>(k) * every;
    while (dir * (integrator.time() - t) < 0)
      integrator.step();
    if (t == integrator.time())
      x = integrator.state();
    else
      integrator.interpolate(t, x);
    if (!visit(t, x)) return false;
  }
  return true;
}

} // namespace rv
