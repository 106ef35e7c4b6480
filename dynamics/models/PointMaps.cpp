#include "dynamics/models/PointMaps.h"

namespace rv {

const ModelInfo& HenonMap::staticInfo() {
  static const ModelInfo info{
      .id = "henon_map",
      .title = "Henon map (reference point map)",
      .reference = "M. Henon, Comm. Math. Phys. 50 (1976) 69",
      .parameters = {{.id = "a", .label = "a", .defaultValue = 1.4, .description = "x' = 1 - a x^2 + y"},
                     {.id = "b",
                      .label = "b",
                      .defaultValue = 0.3,
                      .description = "y' = b x (b = -1: area-preserving)"}},
      .stateNames = {"x", "y"},
      .coreDimension = 2,
      .mapCoordinates = {"x", "y"},
      .kind = ModelKind::Map,
  };
  return info;
}

HenonMap::HenonMap(const ParameterValues& p) : ModelWithField(staticInfo(), p), a_(p["a"]), b_(p["b"]) {
  addStandardObservables();
}

const ModelInfo& StandardMap::staticInfo() {
  static const ModelInfo info{
      .id = "standard_map",
      .title = "Chirikov standard map (reference area-preserving map)",
      .reference = "B. V. Chirikov, Phys. Rep. 52 (1979) 263",
      .parameters = {{.id = "K", .label = "K", .defaultValue = 0.9, .description = "p' = p + K sin(theta)"}},
      .stateNames = {"theta", "p"},
      .coreDimension = 2,
      .mapCoordinates = {"theta", "p"},
      .kind = ModelKind::Map,
  };
  return info;
}

StandardMap::StandardMap(const ParameterValues& p) : ModelWithField(staticInfo(), p), K_(p["K"]) {
  addStandardObservables();
  for (auto& o : observables_) // both coordinates live on the torus
    if (o.id == "theta" || o.id == "p") o.angle = true;
}

template class ModelWithField<HenonMap, 2>;
template class ModelWithField<StandardMap, 2>;

} // namespace rv
