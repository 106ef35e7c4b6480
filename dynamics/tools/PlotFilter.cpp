#include "dynamics/tools/PlotFilter.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/TimeSampler.h"

#include <algorithm>
#include <cmath>

namespace rv {

std::vector<std::vector<double>> samplePlot(const Model& model, Integrator& integrator, const PlotSettings& s,
                                            const ToolControl& control, const std::string& context) {
  if (s.axes.size() != 2 && s.axes.size() != 3) throw InputError(context + ".axes: give 2 or 3 observables");
  if (!(s.period > 0 && std::isfinite(s.period))) throw InputError(context + ".period: must be positive");
  if (s.maxPoints < 1) throw InputError(context + ".max_points: must be at least 1");
  const auto find = [&](const std::string& id, const std::string& field) {
    const int k = model.findObservable(id);
    if (k < 0)
      throw InputError(context + "." + field + ": unknown observable '" + id + "' of " + model.info().id);
    return model.observables()[k].value;
  };
  std::vector<std::function<double(double, const double*)>> axes;
  const char* names[3] = {"x", "y", "z"};
  for (std::size_t i = 0; i < s.axes.size(); ++i)
    axes.push_back(find(s.axes[i], names[i]));
  std::vector<std::vector<double>> points;
  const auto emit = [&](double t, const double* x) {
    std::vector<double> p;
    for (const auto& f : axes)
      p.push_back(f(t, x));
    points.push_back(std::move(p));
    control.progress(static_cast<double>(points.size()) / s.maxPoints);
  };
  if (s.condition == "t") {
    const long n = std::min(s.maxPoints, static_cast<long>(s.timeLimit / s.period) + 1);
    sampleUniform(integrator, s.period, n, [&](double t, const Eigen::VectorXd& x) {
      emit(t, x.data());
      return !control.stopRequested();
    });
    return points;
  }
  const auto cond = find(s.condition, "condition");
  double last = cond(integrator.time(), integrator.state().data());
  emit(integrator.time(), integrator.state().data());
  const double t0 = integrator.time();
  while (static_cast<long>(points.size()) < s.maxPoints && !control.stopRequested() &&
         std::abs(integrator.time() - t0) < s.timeLimit) {
    integrator.step();
    const double c = cond(integrator.time(), integrator.state().data());
    if (std::abs(c - last) >= s.period) {
      emit(integrator.time(), integrator.state().data());
      last = c;
    }
  }
  return points;
}

} // namespace rv
