// Adams.h -- the Adams-Bashforth-Moulton predictor-corrector in PECE mode with a constant step: the explicit
// Adams formula on the last k derivatives predicts, f is evaluated there, the implicit (Moulton) formula of
// one order more corrects, and f is evaluated at the corrected point for the next step -- two evaluations a
// step whatever the order, where a Runge-Kutta method of order 8 spends 13. On a smooth motion at tight
// accuracy this is the cheapest method per digit (what orbit propagators use); its price is a stability
// region that shrinks with the order: too long a step blows up (reported as a state that stops being finite).
// Backward-difference form (nabla^j f), so the step costs O(k n) besides the two evaluations; the first k - 1
// steps (the starting values) come from Verner's 9(8) pair at a tolerance near rounding, read off its
// interpolant at the nodes. Dense output: the interpolating polynomial of the last k derivatives, integrated.
// The state update is summed with compensation (Kahan).
// References: E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I (1993), §III.1
// (explicit and implicit Adams methods in backward differences, their coefficients gamma_j, the
// predictor-corrector modes); L. F. Shampine, M. K. Gordon, Computer Solution of Ordinary Differential
// Equations (1975). The corrector is written as the predictor plus h gamma_k nabla^k f at the predicted point
// (the implicit formula of order k + 1 equals the explicit one of order k plus that term, as
// gamma_k = gamma*_0 + ... + gamma*_k).
#pragma once
#include "dynamics/integrators/AdamsKernels.h"
#include "dynamics/integrators/Integrator.h"

#include <array>

namespace rv {

class Adams final : public Integrator {
public:
  static constexpr int kMaxOrder = 14;
  /// Order `order` (2..kMaxOrder: the predictor uses the last order - 1 derivatives) at the constant step
  /// `step`. Throws InputError naming the parameter for an order out of range or a step that is not positive.
  Adams(double step, int order);
  static IntegratorEntry entry();
  static const ParameterTable& parameterTable();

  /// Throws InputError for a map. Computes the starting values (the first order - 2 steps) at once.
  void start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction = +1) override;
  /// One step of `step`: the starting values first, then PECE steps. Throws ComputationError when the state
  /// stops being finite (a step past the method's stability region does that).
  void step() override;
  /// The integral of the polynomial through the last order - 1 derivatives (of the starting values while
  /// they last): exact at the step's end, of the method's order inside.
  void interpolate(double t, Eigen::VectorXd& out) const override;
  void save(Snapshot& s) const override;
  void restore(Snapshot& s) override;
  bool fixedStep() const override { return true; }
  /// Yes: a PECE step is component by component, and the starting values are computed orbit by orbit.
  bool stepLanesAlone(int width) override;

  int order() const { return k_ + 1; }

private:
  /// int_0^s binom(u + j - 1, j) du, j = 0..k-1: the weights of nabla^j f in x(t_D + s h) - x(t_D).
  void integratedWeights(double s, double* weights) const;
  /// Columns 1..k-1 of `states`: the states at t0 + j h from x0 (Verner's pair near rounding).
  void startingValues(const Model& model, double t0, const Eigen::VectorXd& x0, Eigen::MatrixXd& states);

  double h_;
  int k_;                                 ///< past derivatives the predictor uses (order - 1)
  std::array<double, kMaxOrder> gamma_{}; ///< explicit Adams coefficients gamma_0..gamma_k
  /// integrated_[j][m]: the coefficient of s^(m+1) in int_0^s binom(u + j - 1, j) du
  std::array<std::array<double, kMaxOrder>, kMaxOrder> integrated_{};
  bool avx2_ = adams::avx2Available(); ///< the kernels' path (AdamsKernels.h: bit-identical either way)
  int lanes_ = 1;                      ///< orbits stacked component-major (stepLanesAlone)
  long taken_ = 0;                     ///< steps since start()
  double tD_ = 0;                      ///< the time of the newest derivative in D_
  Eigen::MatrixXd D_;                  ///< nabla^j f at tD_ (dim x k)
  Eigen::MatrixXd startStates_;        ///< the starting values (dim x k)
  Eigen::VectorXd predicted_, fp_, sum_, increment_, compensation_;
  mutable std::array<double, kMaxOrder> weights_{}, weightsEnd_{};
};

} // namespace rv
