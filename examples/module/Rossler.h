// Rossler.h -- the Roessler system, a flow with a chaotic attractor: dx/dt = -y - z, dy/dt = x + a y,
// dz/dt = b + z (x - c). At a = b = 0.2, c = 5.7 its Lyapunov spectrum is about (0.0714, 0, -5.39) (J. C.
// Sprott, Chaos and Time-Series Analysis, Oxford 2003); the exponents sum to the time average of the
// divergence, a + <x> - c.
// Reference: O. E. Roessler, An equation for continuous chaos, Phys. Lett. A 57 (1976) 397-398.
#pragma once
#include "dynamics/core/ModelWithField.h"

namespace rossler {

class Rossler final : public rv::ModelWithField<Rossler, 3> {
public:
  explicit Rossler(const rv::ParameterValues& params);
  static const rv::ModelInfo& staticInfo();

  template <class S> void field(const Vec<S>& x, Vec<S>& dx) const {
    dx[0] = -x[1] - x[2];
    dx[1] = x[0] + a_ * x[1];
    dx[2] = b_ + x[2] * (x[0] - c_);
  }

private:
  double a_, b_, c_;
};

} // namespace rossler
