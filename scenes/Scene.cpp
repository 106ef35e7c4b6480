#include "scenes/Scene.h"

#include "dynamics/core/Errors.h"

#include <array>
#include <cmath>

namespace rv {

void applyPlotTable(const ParameterValues& v, PlotView& plot) {
  applyPlotTable(v, plot.settings);
  plot.chart.holdProportions = v.choice("hold_proportions") == "yes";
  plot.chart.pointSize = std::array{2.0f, 4.0f, 7.0f}.at(static_cast<std::size_t>(v["point_type"]));
}

std::unique_ptr<Integrator> Scene::startIntegrator() const {
  auto integrator = runSpec().makeIntegrator(*model);
  integrator->start(*model, 0.0, initialState);
  return integrator;
}

RunSpec Scene::runSpec() const {
  RunSpec spec(*modelEntry, *integratorEntry);
  spec.modelParameters = model->parameters();
  spec.integratorParameters = *integratorParameters;
  spec.initialState = initialState;
  return spec;
}

std::vector<int> observableColumns(const Model& model, const std::vector<std::string>& ids,
                                   const std::string& what) {
  std::vector<int> cols;
  for (const auto& c : ids) {
    const int i = model.findObservable(c);
    if (i < 0)
      throw InputError(what + ": unknown observable '" + c + "' of " + model.info().id +
                       " (rollviz describe " + model.info().id + ")");
    cols.push_back(i);
  }
  if (cols.empty()) throw InputError(what + ": give at least one observable");
  return cols;
}

bool sampleColumns(const Scene& scene, double time, double every, const std::vector<int>& columns,
                   const std::function<bool(double, const std::vector<double>&)>& visit,
                   const std::function<bool(double)>& keepGoing) {
  // a time that is a whole number of periods up to rounding still gets its last row
  const long rows = static_cast<long>(std::floor(time / every * (1 + 1e-12))) + 1;
  const auto& obs = scene.model->observables();
  auto integrator = scene.startIntegrator();
  const int dir = integrator->direction();
  Eigen::VectorXd x(integrator->state().size());
  std::vector<double> row(columns.size());
  // TimeSampler's sampleUniform, with a question at every step: rows may lie many steps apart
  const auto stop = [&] { return keepGoing && !keepGoing(integrator->time()); };
  for (long k = 0; k < rows; ++k) {
    const double t = dir * static_cast<double>(k) * every;
    if (!integrator->advanceTo(t, x, stop)) return false;
    for (std::size_t c = 0; c < columns.size(); ++c)
      row[c] = obs[columns[c]].value(t, x.data());
    if (!visit(t, row)) return false;
  }
  return true;
}

bool sameMap(const Scene& a, const Scene& b) {
  if (a.modelEntry != b.modelEntry || a.integratorEntry != b.integratorEntry) return false;
  if (a.model->parameters().values() != b.model->parameters().values()) return false;
  if (a.integratorParameters->values() != b.integratorParameters->values()) return false;
  const SectionSettings &p = a.poincare, &q = b.poincare;
  return p.observable == q.observable && p.value == q.value && p.checkDirection == q.checkDirection &&
         p.direction == q.direction && p.accuracy == q.accuracy && p.backward == q.backward &&
         p.manySheeted == q.manySheeted && p.root == q.root && p.order == q.order && p.maxTime == q.maxTime;
}

} // namespace rv
