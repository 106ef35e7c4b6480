// Taylor.h -- the Taylor series method: on each step the solution's Taylor coefficients to order p are
// computed exactly (up to rounding) by automatic differentiation of the model's templated field
// (TaylorTape.h), the step is chosen from the last two coefficients, and the series is summed. The series
// itself is the dense output, so Poincare crossings and video frames are located on it.
// References: A. Jorba, M. Zou, Experimental Mathematics 14 (2005) 99-117 (the order p = -ln(eps)/2 + 1 and
// the step rho / e^2 from the last two coefficients); F. Biscani, D. Izzo, MNRAS 504 (2021) 2614 (heyoka:
// the safety factor exp(-0.7 / (p - 1)) and the mixed absolute/relative tolerance).
#pragma once
#include "dynamics/core/TaylorTape.h"
#include "dynamics/integrators/Integrator.h"

namespace rv {

class Taylor final : public Integrator {
public:
  /// `order` 0 takes the order from the tolerance; `step` > 0 fixes the step (then the tolerance only
  /// chooses the order). Throws InputError for an order above kMaxOrder.
  Taylor(double tolerance, int order, double step = 0);
  static constexpr int kMaxOrder = 60;
  static IntegratorEntry entry();
  static const ParameterTable& parameterTable();
  /// Jorba and Zou's order for a tolerance: ceil(-ln(tolerance) / 2 + 1), at least 2.
  static int orderFor(double tolerance);

  /// Throws InputError for a map or a model without a templated field.
  void start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction = +1) override;
  /// One step; throws ComputationError when the state stops being finite.
  void step() override;
  /// The last step's Taylor polynomial at t.
  void interpolate(double t, Eigen::VectorXd& out) const override;
  void save(Snapshot& s) const override;
  void restore(Snapshot& s) override;
  bool fixedStep() const override { return step_ > 0; }

  int order() const { return order_; }
  /// The length of the last step (signed with the direction).
  double lastStep() const { return lastStep_; }
  /// Taylor coefficients of the last step: column k holds x^(k)(t0) / k!.
  const Eigen::MatrixXd& coefficients() const { return X_; }
  /// Operations evaluated per order on the model's compiled tape (what one order of the expansion costs).
  int tapeLength() const { return tape_.usedCount(); }

private:
  /// Fills X_ with the coefficients at x_.
  void expand();
  /// Jorba and Zou's step from the last two coefficients, with heyoka's safety factor.
  double chooseStep() const;

  double step_;
  int order_;
  double lastStep_ = 0;
  taylor::Tape tape_;
  Eigen::MatrixXd X_;
  Eigen::VectorXd increment_, compensation_;
};

} // namespace rv
