// BuiltinModels.cpp -- the one list of built-in models (explicit, so static linking cannot drop any).
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/models/BallOnEllipsoid.h"
#include "dynamics/models/BallOnParaboloid.h"
#include "dynamics/models/ChaplyginBall.h"
#include "dynamics/models/EllipsoidOnPlane.h"
#include "dynamics/models/HenonHeiles.h"
#include "dynamics/models/Lorenz.h"
#include "dynamics/models/ParaboloidOnPlane.h"
#include "dynamics/models/PointMaps.h"

namespace rv {

namespace {
template <class M> ModelEntry entryOf() {
  return {&M::staticInfo(),
          [](const ParameterValues& p) -> std::unique_ptr<Model> { return std::make_unique<M>(p); }};
}
} // namespace

void registerBuiltinModels(ModelRegistry& registry) {
  registry.add(entryOf<ParaboloidOnPlane>());
  registry.add(entryOf<EllipsoidOnPlane>());
  registry.add(entryOf<BallOnEllipsoid>());
  registry.add(entryOf<BallOnParaboloid>());
  registry.add(entryOf<ChaplyginBall>());
  registry.add(entryOf<Lorenz>());
  registry.add(entryOf<HenonHeiles>());
  registry.add(entryOf<HenonMap>());
  registry.add(entryOf<StandardMap>());
}

} // namespace rv
