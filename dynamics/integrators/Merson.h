// Merson.h -- the Runge-Kutta-Merson method: fourth order, five stages, with an embedded estimate of the
// local error that steers the step within [min step, max step] (manual §2.2.2). Reference: R. H. Merson, An
// operational method for the study of integration processes (1957); E. Hairer, S. P. Norsett, G. Wanner,
// Solving ODE I, §II.4 (table 4.1 and the error estimate). Dense output: cubic Hermite interpolation through
// both ends of the accepted step.
#pragma once
#include "dynamics/integrators/Integrator.h"

namespace rv {

class Merson final : public Integrator {
public:
  /// Throws InputError when the steps are inconsistent (min > max, step outside [min, max]).
  Merson(double step, double precision, double minStep, double maxStep);
  static IntegratorEntry entry();
  static const ParameterTable& parameterTable();

  void start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction = +1) override;
  /// One accepted step; throws ComputationError when the step would have to fall below min step.
  void step() override;
  void interpolate(double t, Eigen::VectorXd& out) const override;
  void save(Snapshot& s) const override;
  void restore(Snapshot& s) override;
  double nextStep() const { return h_; }
  long rejected() const { return rejected_; }

private:
  double h_, precision_, minStep_, maxStep_;
  long rejected_ = 0;
  Eigen::VectorXd k1_, k2_, k3_, k4_, k5_, tmp_, fPrev_, err_;
};

} // namespace rv
