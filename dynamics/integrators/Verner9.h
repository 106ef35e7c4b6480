// Verner9.h -- J. H. Verner's "most efficient" explicit Runge-Kutta pair of orders 9 and 8 (16 stages, the
// step taken with the 9th-order weights, the 8th-order ones only estimate the error) with its interpolant of
// order 8 (five more stages, of which the first is f at the step's end: four evaluations, made only when a
// step's dense output is asked for). Adaptive: the step keeps the estimated error per step below the
// tolerance, absolute for components below 1 and relative above. The state update is summed with
// compensation (Kahan), as in Everhart's method, so tolerances near rounding keep their digits.
// References: J. H. Verner, Numerically optimal Runge-Kutta pairs with interpolants, Numer. Algor. 53 (2010)
// 383-396 (the coefficients, from his published tables); E. Hairer, S. P. Norsett, G. Wanner, Solving ODE I,
// §II.4 (the step control, eq. 4.13, with safety factor 0.9 and growth between 0.2 and 5).
#pragma once
#include "dynamics/integrators/Integrator.h"

namespace rv {

class Verner9 final : public Integrator {
public:
  /// Adaptive with a positive `tolerance` (`step` is then the first step tried); `fixedStep` > 0 pins the
  /// step instead (the tolerance is then unused). Throws InputError for a tolerance or step that is not
  /// positive.
  Verner9(double tolerance, double step, bool fixedStep = false);
  static IntegratorEntry entry();
  static const ParameterTable& parameterTable();
  static constexpr int kStages = 16;      ///< stages of a step
  static constexpr int kDenseStages = 21; ///< stages the interpolant uses (17 = f at the step's end)

  /// Throws InputError for a map.
  void start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction = +1) override;
  /// One accepted step; throws ComputationError when the state stops being finite or the step would have
  /// to fall below rounding of the time.
  void step() override;
  /// The interpolant of order 8 on the last step (its four extra stages are evaluated at the first call
  /// in a step and kept).
  void interpolate(double t, Eigen::VectorXd& out) const override;
  void save(Snapshot& s) const override;
  void restore(Snapshot& s) override;
  bool fixedStep() const override { return fixed_; }

  /// The step the next step() will try.
  double stepSize() const { return h_; }
  /// Steps redone with a smaller step.
  long rejectedSteps() const { return rejected_; }
  /// Evaluations made for dense output (not counted in evaluations(): interpolate() is const).
  long denseEvaluations() const { return denseEvaluations_; }

private:
  /// y = x + h sum_{j < stage} A(stage, j) K_j
  void combine(int stage, const Eigen::VectorXd& x, double h, Eigen::VectorXd& y) const;

  double tolerance_, h_;
  bool fixed_;
  long rejected_ = 0;
  mutable long denseEvaluations_ = 0;
  mutable bool denseReady_ = false;                     ///< stages 18..21 of the last step are in K_
  mutable Eigen::MatrixXd K_;                           ///< the stages of the last step (dim x kDenseStages)
  mutable Eigen::VectorXd work_;                        ///< the interpolant's stage arguments
  Eigen::VectorXd y_, error_, sum_, compensation_, f1_; ///< sum_: the step's increment
};

} // namespace rv
