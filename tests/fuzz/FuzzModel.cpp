// libFuzzer target: any bytes as a model file (docs/models.md). Reading either succeeds -- and the model then
// gives its field, Jacobian and integrals at a state and takes a few integration steps -- or fails with
// InputError / ComputationError; any other exception, a crash, a sanitizer report, a hang or unbounded memory
// is a bug. Seeded with examples/models/ and examples/rolling/ (tests/fuzz/run.sh).
#include "dynamics/core/Errors.h"
#include "dynamics/core/ExplainsNonFinite.h"
#include "dynamics/integrators/Integrator.h"
#include "scenes/JsonFields.h"
#include "scenes/ModelFile.h"
#include "scenes/SceneLoader.h"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

// interpreted: a compiler run per input would be slow and fill the cache of compiled models
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  rv::setModelCompilation(rv::ModelCompilation::Off);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const rv::ModelEntry& entry = rv::modelEntryFromJson(rv::parseSceneJson(in, "fuzz.json"), "fuzz.json");
    const auto model = entry.create(rv::ParameterValues(entry.info->parameters));
    const int n = model->dimension();
    Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, 0.1, 0.9), dx(n);
    Eigen::MatrixXd jac(n, n);
    model->rhs(x.data(), dx.data());
    model->jacobian(x.data(), jac.data());
    (void)model->integrals(x.data());
    if (const auto* e = dynamic_cast<const rv::ExplainsNonFinite*>(model.get()))
      (void)e->nonFiniteCause(x.data());
    if (!model->isMap()) {
      const rv::IntegratorEntry& rk4 = rv::IntegratorRegistry::global().get("rk4");
      auto integrator = rk4.create(rv::ParameterValues(*rk4.parameters));
      integrator->start(*model, 0, x);
      for (int i = 0; i < 5; ++i)
        integrator->step();
    }
  } catch (const rv::InputError&) {
  } catch (const rv::ComputationError&) {
  }
  return 0;
}
