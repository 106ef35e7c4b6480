// TestModels.h -- small models with known solutions, shared by the integrator tests.
#pragma once
#include "dynamics/core/ModelWithField.h"

#include <cmath>

namespace rv::test {

inline const ModelInfo& coupledOscillatorInfo() {
  static const ModelInfo info{.id = "oscillator", .stateNames = {"q", "p", "s"}, .coreDimension = 3};
  return info;
}
/// q'' = -q with s' = q p (a non-linear coupling): from (1, 0, 0), q = cos t, p = -sin t, s = (cos^2 t - 1) /
/// 2 exactly, so no reference run (whose own error would hide a method's near rounding) is needed.
struct CoupledOscillator : ModelWithField<CoupledOscillator, 3> {
  CoupledOscillator()
      : ModelWithField(coupledOscillatorInfo(), ParameterValues(coupledOscillatorInfo().parameters)) {}
  template <class S> void field(const Vec<S>& x, Vec<S>& dx) const {
    dx[0] = x[1], dx[1] = -x[0], dx[2] = x[0] * x[1];
  }
  /// The solution from (1, 0, 0) at t.
  static Eigen::VectorXd exact(double t) {
    Eigen::VectorXd x(3);
    x << std::cos(t), -std::sin(t), (std::cos(t) * std::cos(t) - 1) / 2;
    return x;
  }
};

inline const ModelInfo& blowupInfo() {
  static const ModelInfo info{.id = "blowup", .stateNames = {"y"}, .coreDimension = 1};
  return info;
}
/// y' = y^2: from y(0) = 1 it blows up at t = 1.
struct Blowup : ModelWithField<Blowup, 1> {
  Blowup() : ModelWithField(blowupInfo(), ParameterValues(blowupInfo().parameters)) {}
  template <class S> void field(const Vec<S>& x, Vec<S>& dx) const { dx[0] = x[0] * x[0]; }
};

} // namespace rv::test
