// Everhart.h -- Everhart's implicit method for first-order systems (manual §2.2.3): on each step the
// right-hand side is approximated by its interpolation polynomial at Gauss-Radau spacings (the start of the
// step and the n - 1 left-Radau points), integrated exactly, and the node values are found by
// predictor-corrector iteration. With n nodes the method has order 2n - 1; the manual's orders 3, 7, ..., 27
// use n = 2, 4, ..., 14. References: E. Everhart, An efficient integrator that uses Gauss-Radau spacings, in
// Dynamics of Comets (1985),
//   185-202; H. Rein, D. S. Spiegel, IAS15, MNRAS 446 (2015) 1424 (stopping rule, compensated summation).
// The spacings and weights are computed at start-up in long double (no hard-coded tables). As in IAS15: the
// predictor shifts the last step's polynomial onto the new step and adds the correction the last prediction
// missed, the corrector stops when its change falls below rounding or stops shrinking, the state update is
// summed with compensation, the node arithmetic has its node count fixed at compile time and allocates
// nothing; optionally (adaptive) the step follows IAS15's rule on the polynomial's last coefficient.
#pragma once
#include "dynamics/integrators/Integrator.h"

#include <cstdint>
#include <vector>

namespace rv {

class Everhart final : public Integrator {
public:
  /// `order` is rounded down to 3, 7, ..., 27 as the manual says; InputError below 3. A positive `tolerance`
  /// makes the step adaptive (`step` is then the first one): IAS15's rule, the largest last coefficient of
  /// the polynomial of the right-hand side relative to its largest value, kept near the tolerance.
  Everhart(double step, int order, int iterations, double tolerance = 0);
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
  /// At a fixed step: each lane's corrector iterates until that lane converges (the others' values frozen
  /// once they have), so each orbit takes the iterations, and the steps, it takes alone.
  bool stepLanesAlone(int width) override;

  int order() const { return 2 * n_ - 1; }
  bool fixedStep() const override { return tolerance_ <= 0; }
  /// The step the next step() will try (the last one taken, or the adapted one).
  double stepSize() const { return h_; }
  /// Steps redone with a smaller step (adaptive only).
  long rejectedSteps() const { return rejected_; }
  /// Spacings c_0 = 0 < c_1 < ... < c_{n-1} < 1 on the unit step.
  const std::vector<double>& spacings() const { return c_; }
  /// Quadrature weights b_j = integral over [0, 1] of the j-th Lagrange polynomial.
  const Eigen::VectorXd& weights() const { return b_; }
  /// Corrector iterations in the last step.
  int lastIterations() const { return lastIterations_; }

private:
  template <int N> void stepWith();
  template <int N> double correct(double h);
  template <int N> void correctLanes(double h);
  template <int N> void nodeSum(double h, int j);
  /// The predictor's extrapolation for a step `ratio` times the last one: l_l(1 + ratio c_j).
  void setExtrapolation(double ratio);

  double h_, tolerance_;
  int n_, maxIterations_, lastIterations_ = 0;
  int lanes_ = 1; ///< orbits stacked component-major (stepLanesAlone), each converging on its own
  /// The corrector's stopping rule for one orbit: the changes of the sweeps so far.
  struct Convergence {
    double previousChange = 0, changeBefore = 0;
    bool converged = false;
    /// Whether sweep `sweep`, which changed the nodes by `relative`, leaves only rounding (remembered).
    bool reached(int sweep, double relative);
  };
  // each lane's corrector (correctLanes): its rule, this sweep's change and scale, and whether it is open
  // (all ones) or converged (zero), as everhart::scanLanes takes them
  std::vector<Convergence> laneRules_;
  std::vector<double> laneChange_, laneScale_;
  std::vector<std::int64_t> laneOpen_;
  long rejected_ = 0;
  bool havePrevious_ = false;
  double lastStep_ = 0;  ///< length of the last step taken
  double lastRatio_ = 1; ///< the step ratio extrapolate_ was made for
  std::vector<double> c_;
  const std::vector<std::vector<long double>>* integrated_ = nullptr; // shared tables, see Everhart.cpp
  Eigen::MatrixXd A_, extrapolate_;        // A(i, j) = int_0^{c_i} l_j; extrapolate(l, j) = l_l(1 + c_j)
  Eigen::VectorXd b_, leading_;            // leading_(j): weight of F_j in the polynomial's last coefficient
  Eigen::MatrixXd F_, Fnew_;               // right-hand side at the nodes (dim x n)
  Eigen::MatrixXd predicted_, correction_; // the last prediction and what the corrector changed in it
  Eigen::VectorXd f1_, y_, sum_, compensation_;
};

} // namespace rv
