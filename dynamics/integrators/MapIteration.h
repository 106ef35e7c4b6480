// MapIteration.h -- the "integrator" of an explicit point map: one step applies the map once and advances the
// time by 1, so that sampling, playback and the tools treat maps and flows alike.
#pragma once
#include "dynamics/integrators/Integrator.h"

namespace rv {

class MapIteration final : public Integrator {
public:
  /// Throws InputError for backward iteration (the maps are not inverted).
  void start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction = +1) override;
  void step() override;
  /// A map has no motion between iterates: the state at the last iterate not after t.
  void interpolate(double t, Eigen::VectorXd& out) const override;
};

} // namespace rv
