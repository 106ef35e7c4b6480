// Merson.h -- the Runge-Kutta-Merson method: fourth order, five stages, with an embedded estimate of the
// local error that steers the step within [min step, max step] (manual §2.2.2) -- the manual's absolute
// precision where |x| < 1, relative above (the scale sc_i of Hairer, Norsett, Wanner, eq. II.4.10).
// Reference: R. H. Merson, An operational method for the study of integration processes (1957); E. Hairer,
// S. P. Norsett, G. Wanner, Solving ODE I, §II.4 (table 4.1 and the error estimate). Dense output: cubic
// Hermite interpolation through both ends of the accepted step. On lanes (stepLanesAlone) each orbit has its
// own step, time and error.
#pragma once
#include "dynamics/integrators/Integrator.h"

#include <vector>

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
  /// Yes: each lane takes steps of its own length under its own error control, the steps and states it would
  /// take alone, bit for bit (advanceTo only).
  bool stepLanesAlone(int width) override;
  void save(Snapshot& s) const override;
  void restore(Snapshot& s) override;
  double nextStep() const { return h_; }
  long rejected() const { return rejected_; }

protected:
  void stepLanes(const std::vector<char>& behind) override;
  void interpolateLane(int lane, double t, Eigen::VectorXd& out) const override;

private:
  /// A step's error against the precision: true, the next step `h` grown, when within it; false, `h` shrunk,
  /// when not (ComputationError where `h` is at its minimum already, at time t).
  bool judge(double err, double& h, double t);
  double h_, precision_, minStep_, maxStep_;
  std::vector<double> laneH_, hs_; ///< on lanes: each lane's next step, and this round's signed steps
  Eigen::VectorXd part_;           ///< on lanes: a fraction of each lane's step (h / 3, ...)
  long rejected_ = 0;
  Eigen::VectorXd k1_, k2_, k3_, k4_, k5_, tmp_, fPrev_, err_;
};

} // namespace rv
