#include "dynamics/jobs/RunSpec.h"

#include "dynamics/integrators/MapIteration.h"

#include <sstream>

namespace rv {

std::unique_ptr<Integrator> RunSpec::makeIntegrator(const Model& m) const {
  if (m.isMap()) return std::make_unique<MapIteration>();
  return integrator->create(integratorParameters);
}

std::function<std::unique_ptr<Model>(double)> RunSpec::modelAt(const std::string& id) const {
  return [entry = model, values = modelParameters, id](double v) {
    ParameterValues p = values;
    p.set(id, v, "continuation of " + id);
    return entry->create(p);
  };
}

std::string RunSpec::describe() const {
  std::ostringstream os;
  const auto list = [&](const ParameterValues& p) {
    const auto& specs = p.table().specs();
    for (std::size_t i = 0; i < specs.size(); ++i)
      os << (i ? ", " : "") << specs[i].id << "=" << p.values()[i];
  };
  if (model->info->kind != ModelKind::Map) { // an explicit map is iterated, not integrated
    os << integrator->id << "(";
    list(integratorParameters);
    os << ") ";
  }
  os << model->info->id << "(";
  list(modelParameters);
  os << ")";
  return os.str();
}

} // namespace rv
