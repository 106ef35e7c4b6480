// RunSpec.h -- what a trajectory needs, in dynamics terms: the model kind and its parameter values, the
// integration method and its parameters, the initial state. Tasks rebuild their model and integrators from
// it.
#pragma once
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Integrator.h"

#include <functional>
#include <memory>

namespace rv {

struct RunSpec {
  RunSpec(const ModelEntry& model, const IntegratorEntry& integrator)
      : model(&model), modelParameters(model.info->parameters), integrator(&integrator),
        integratorParameters(*integrator.parameters) {}
  const ModelEntry* model;
  ParameterValues modelParameters;
  const IntegratorEntry* integrator;
  ParameterValues integratorParameters;
  Eigen::VectorXd initialState;

  std::unique_ptr<Model> makeModel() const { return model->create(modelParameters); }
  /// The model at values of one parameter (for continuation); InputError outside the parameter's range.
  std::function<std::unique_ptr<Model>(double)> modelAt(const std::string& parameter) const;
  /// A fresh integrator of the method (MapIteration for explicit maps), not started.
  std::unique_ptr<Integrator> makeIntegrator(const Model& m) const;
  /// "method(step=..., ...) problem(energy=..., ...)".
  std::string describe() const;
};

} // namespace rv
