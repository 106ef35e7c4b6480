#include "scenes/Scene.h"

namespace rv {

std::unique_ptr<Integrator> Scene::startIntegrator() const {
  auto integrator = integratorEntry->create(*integratorParameters);
  integrator->start(*model, 0.0, initialState);
  return integrator;
}

} // namespace rv
