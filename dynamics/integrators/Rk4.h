// Rk4.h -- the classical fourth-order Runge-Kutta method with a fixed step (manual §2.2.1).
// Reference: E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, §II.1.
// Dense output: cubic Hermite interpolation through both ends of the step (local error O(h^4)).
#pragma once
#include "dynamics/integrators/Integrator.h"

namespace rv {

class Rk4 final : public Integrator {
public:
  explicit Rk4(double step) : h_(step) {}
  static IntegratorEntry entry();
  static const ParameterTable& parameterTable();

  void start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction = +1) override;
  void step() override;
  void interpolate(double t, Eigen::VectorXd& out) const override;
  void save(Snapshot& s) const override;
  void restore(Snapshot& s) override;
  double stepSize() const { return h_; }
  bool fixedStep() const override { return true; }
  /// Each component's stages read the state only through f: stacked orbits step as alone.
  bool stepLanesAlone(int) override { return true; }

private:
  template <int D> void stepWith();
  double h_;
  Eigen::VectorXd k1_, k2_, k3_, k4_, tmp_, fPrev_;
};

} // namespace rv
