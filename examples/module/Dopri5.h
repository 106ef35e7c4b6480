// Dopri5.h -- the Dormand-Prince 5(4) Runge-Kutta pair: seven stages (the last is the first of the next
// step), local extrapolation (the step advances with the fifth-order solution), the step chosen from the
// embedded fourth-order estimate, and the continuous extension of order 4 as dense output (Shampine's
// coefficients, as in Hairer's DOPRI5).
// References: J. R. Dormand, P. J. Prince, J. Comput. Appl. Math. 6 (1980) 19-26; E. Hairer, S. P. Norsett,
// G. Wanner, Solving Ordinary Differential Equations I, 2nd ed., Springer 1993, §II.5 (table 5.2) and §II.6
// (dense output); L. F. Shampine, Math. Comp. 46 (1986) 135-150.
#pragma once
#include "dynamics/integrators/Integrator.h"

namespace rossler {

class Dopri5 final : public rv::Integrator {
public:
  /// A fixed step when `fixedStep` (for measuring the order), else `step` is the first step.
  Dopri5(double tolerance, double step, bool fixedStep);
  static rv::IntegratorEntry entry();
  static const rv::ParameterTable& parameterTable();

  void start(const rv::Model& model, double t0, const Eigen::VectorXd& x0, int direction = +1) override;
  /// One accepted step; throws ComputationError when the step collapses or the state stops being finite.
  void step() override;
  void interpolate(double t, Eigen::VectorXd& out) const override;
  void save(rv::Snapshot& s) const override;
  void restore(rv::Snapshot& s) override;
  bool fixedStep() const override { return fixed_; }

private:
  double tolerance_, h_;
  bool fixed_;
  Eigen::VectorXd k1_, k2_, k3_, k4_, k5_, k6_, k7_, y_, err_;
  Eigen::VectorXd r2_, r3_, r4_, r5_; ///< the dense output's coefficients on the last step
};

} // namespace rossler
