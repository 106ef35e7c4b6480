#include "scenes/Scene.h"

#include "dynamics/integrators/MapIteration.h"

namespace rv {

std::unique_ptr<Integrator> Scene::startIntegrator() const {
  std::unique_ptr<Integrator> integrator =
      model->isMap() ? std::make_unique<MapIteration>() : integratorEntry->create(*integratorParameters);
  integrator->start(*model, 0.0, initialState);
  return integrator;
}

} // namespace rv
