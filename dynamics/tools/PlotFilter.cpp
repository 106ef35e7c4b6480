#include "dynamics/tools/PlotFilter.h"

#include "dynamics/core/Errors.h"
#include "dynamics/integrators/TimeSampler.h"

#include <algorithm>
#include <cmath>

namespace rv {

const ParameterTable& plotTable() {
  const PlotSettings d;
  static const ParameterTable t{
      {.id = "period",
       .label = "Period",
       .defaultValue = d.period,
       .min = 1e-300,
       .description = "the change of the output condition between two points"},
      {.id = "max_points",
       .label = "Max. number of points",
       .defaultValue = static_cast<double>(d.maxPoints),
       .min = 1,
       .max = 1e15,
       .description = "the most points drawn for one trajectory",
       .integer = true},
      {.id = "time_limit",
       .label = "Time limit",
       .defaultValue = d.timeLimit,
       .min = 1e-300,
       .description = "integration time at most"},
      {.id = "hold_proportions",
       .label = "Hold proportions",
       .defaultValue = 0,
       .min = 0,
       .max = 1,
       .description = "equal scales on the axes",
       .integer = true,
       .choices = {"no", "yes"}},
      {.id = "point_type",
       .label = "Point type",
       .defaultValue = 1,
       .min = 0,
       .max = 2,
       .description = "the size of the points drawn: 2, 4 or 7 pixels",
       .integer = true,
       .choices = {"small", "middle", "big"}},
  };
  return t;
}

void applyPlotTable(const ParameterValues& v, PlotSettings& s) {
  s.period = v["period"];
  s.maxPoints = static_cast<long>(v["max_points"]);
  s.timeLimit = v["time_limit"];
}

PlotSampler::PlotSampler(const Model& model, const PlotSettings& s, const std::string& context)
    : settings_(s) {
  if (!s.wholeState && s.axes.size() != 2 && s.axes.size() != 3)
    throw InputError(context + ".axes: give 2 or 3 observables");
  if (!(s.period > 0 && std::isfinite(s.period))) throw InputError(context + ".period: must be positive");
  if (s.maxPoints < 1) throw InputError(context + ".max_points: must be at least 1");
  const auto find = [&](const std::string& id, const std::string& field) {
    const int k = model.findObservable(id);
    if (k < 0)
      throw InputError(context + "." + field + ": unknown observable '" + id + "' of " + model.info().id);
    return model.observables()[k].value;
  };
  const char* names[3] = {"x", "y", "z"};
  for (std::size_t i = 0; i < s.axes.size() && !s.wholeState; ++i)
    axes_.push_back(find(s.axes[i], names[i]));
  dimension_ = model.dimension();
  condition_ = find(s.condition, "condition");
}

std::vector<double> PlotSampler::valuesAt(double t, const double* x) const {
  if (settings_.wholeState) {
    std::vector<double> v{t};
    v.insert(v.end(), x, x + dimension_);
    return v;
  }
  std::vector<double> v;
  for (const auto& f : axes_)
    v.push_back(f(t, x));
  return v;
}

bool PlotSampler::offer(double t, const double* x) {
  if (full()) return false;
  const double c = condition_(t, x);
  if (started_ && std::abs(c - last_) < settings_.period) return false;
  started_ = true;
  last_ = c;
  values_ = valuesAt(t, x);
  ++kept_;
  return true;
}

void PlotSampler::offerStep(const Integrator& in,
                            const std::function<void(const std::vector<double>&)>& keep) {
  if (settings_.condition != "t") {
    if (offer(in.time(), in.state().data())) keep(values_);
    return;
  }
  if (!started_) started_ = true, last_ = in.previousTime();
  const int dir = in.direction();
  for (double t = last_ + dir * kept_ * settings_.period; !full() && dir * (in.time() - t) >= 0;
       t = last_ + dir * kept_ * settings_.period) {
    in.sampleAt(t, work_);
    values_ = valuesAt(t, work_.data());
    ++kept_;
    keep(values_);
  }
}

std::vector<std::vector<double>> samplePlot(const Model& model, Integrator& integrator, const PlotSettings& s,
                                            const ToolControl& control, const std::string& context) {
  PlotSampler sampler(model, s, context);
  std::vector<std::vector<double>> points;
  const auto progress = [&] { control.progress(static_cast<double>(points.size()) / s.maxPoints); };
  if (s.condition == "t") {
    // in time: exactly at the multiples of the period, from the dense output
    const long n = std::min(s.maxPoints, static_cast<long>(s.timeLimit / s.period) + 1);
    sampleUniform(integrator, s.period, n, [&](double t, const Eigen::VectorXd& x) {
      points.push_back(sampler.valuesAt(t, x.data()));
      progress();
      return !control.stopRequested();
    });
    return points;
  }
  const double t0 = integrator.time();
  if (sampler.offer(t0, integrator.state().data())) points.push_back(sampler.values());
  while (!sampler.full() && !control.stopRequested() && std::abs(integrator.time() - t0) < s.timeLimit) {
    integrator.step();
    if (sampler.offer(integrator.time(), integrator.state().data())) {
      points.push_back(sampler.values());
      progress();
    }
  }
  return points;
}

} // namespace rv
