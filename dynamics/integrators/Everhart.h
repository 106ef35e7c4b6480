// Everhart.h -- Everhart's implicit method for first-order systems (manual §2.2.3): on each step the
// right-hand side is approximated by its interpolation polynomial at Gauss-Radau spacings (the start of the
// step and the n - 1 left-Radau points), integrated exactly, and the node values are found by
// predictor-corrector iteration. With n nodes the method has order 2n - 1; the manual's orders 3, 7, ..., 27
// use n = 2, 4, ..., 14. References: E. Everhart, An efficient integrator that uses Gauss-Radau spacings, in
// Dynamics of Comets (1985),
//   185-202; H. Rein, D. S. Spiegel, IAS15, MNRAS 446 (2015) 1424 (stopping rule, compensated summation).
// The spacings and weights are computed at start-up in long double (no hard-coded tables).
#pragma once
#include "dynamics/integrators/Integrator.h"

#include <vector>

namespace rv {

class Everhart final : public Integrator {
public:
  /// `order` is rounded down to 3, 7, ..., 27 as the manual says; InputError below 3.
  Everhart(double step, int order, int iterations);
  static IntegratorEntry entry();
  static const ParameterTable& parameterTable();
  /// The largest of 3, 7, 11, ..., 27 not above `requested` (0 when requested < 3).
  static int effectiveOrder(int requested);

  void start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction = +1) override;
  /// One step; throws ComputationError when the state stops being finite.
  void step() override;
  void interpolate(double t, Eigen::VectorXd& out) const override;
  void save(Snapshot& s) const override;
  void restore(Snapshot& s) override;

  int order() const { return 2 * n_ - 1; }
  /// Spacings c_0 = 0 < c_1 < ... < c_{n-1} < 1 on the unit step.
  const std::vector<double>& spacings() const { return c_; }
  /// Quadrature weights b_j = integral over [0, 1] of the j-th Lagrange polynomial.
  const Eigen::VectorXd& weights() const { return b_; }
  /// Corrector iterations in the last step.
  int lastIterations() const { return lastIterations_; }

private:
  double h_;
  int n_, maxIterations_, lastIterations_ = 0;
  bool havePrevious_ = false;
  std::vector<double> c_;
  const std::vector<std::vector<long double>>* integrated_ = nullptr; // shared tables, see Everhart.cpp
  Eigen::MatrixXd A_, extrapolate_; // A(i, j) = int_0^{c_i} l_j; extrapolate(l, j) = l_l(1 + c_j)
  Eigen::VectorXd b_;
  Eigen::MatrixXd F_, Fnew_;               // right-hand side at the nodes (dim x n)
  Eigen::MatrixXd predicted_, correction_; // the last prediction and what the corrector changed in it
  Eigen::VectorXd f1_, y_, sum_, compensation_;
};

} // namespace rv
