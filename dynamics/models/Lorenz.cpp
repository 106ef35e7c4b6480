#include "dynamics/models/Lorenz.h"

namespace rv {

const ModelInfo& Lorenz::staticInfo() {
  static const ModelInfo info{
      .id = "lorenz",
      .title = "Lorenz system (reference flow)",
      .reference = "E. N. Lorenz, J. Atmos. Sci. 20 (1963) 130-141",
      .parameters =
          {
              {.id = "sigma", .label = "sigma", .defaultValue = 10.0, .description = "Prandtl number"},
              {.id = "rho", .label = "rho", .defaultValue = 28.0, .description = "Rayleigh number ratio"},
              {.id = "beta", .label = "beta", .defaultValue = 8.0 / 3.0, .description = "geometric factor"},
          },
      .stateNames = {"x", "y", "z"},
      .coreDimension = 3,
      .section = "z",
  };
  return info;
}

Lorenz::Lorenz(const ParameterValues& p)
    : ModelWithField(staticInfo(), p), c_{p["sigma"], p["rho"], p["beta"]} {
  addStandardObservables();
}

template class ModelWithField<Lorenz, 3>;

} // namespace rv
