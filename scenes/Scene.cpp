#include "scenes/Scene.h"

namespace rv {

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

} // namespace rv
