// Lyapunov.h -- the spectrum of Lyapunov exponents along a trajectory by the generalised Benettin algorithm
// (manual §2.3.3): k tangent vectors (or k perturbed trajectories) re-orthonormalised by QR every interval,
// the logarithms of the stretches accumulated. Reference: G. Benettin, L. Galgani, A. Giorgilli, J.-M.
// Strelcyn, Meccanica 15 (1980) 9-30; the tangent mode integrates the variational equations with the model's
// exact (AutoDiff) Jacobian, the steps controlled by the orbit and the vectors together (the vectors of a
// strongly contracting direction need steps the orbit does not), as DynamicalSystems.jl's tangent integrator.
// The interval adapts (tangent mode): one in which a vector lost more than `spread` of its scale -- shrunk
// by that factor, or cancelled against the ones before it in Gram-Schmidt (|v_j| / R_jj: the digits QR
// loses, Higham, Accuracy and Stability, Thm 19.4) -- is taken again at half the length, and the length
// grows back to `interval` where the vectors keep well within it; so every exponent of a flow whose
// exponents span tens per unit time stays finite and right with no setting (Geist, Parlitz, Lauterborn,
// Prog. Theor. Phys. 83 (1990) 875: re-orthonormalise before the vectors' ratio nears the precision).
#pragma once
#include "dynamics/core/SettingsTable.h"
#include "dynamics/integrators/Integrator.h"
#include "dynamics/tools/ToolControl.h"

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rv {

struct LyapunovSettings {
  enum class Mode { Tangent, Perturbed };
  Mode mode = Mode::Tangent;
  int count = 0;         ///< number of exponents; 0: the core dimension
  double interval = 1.0; ///< the longest time between re-orthonormalisations (maps: iterations)
  double spread = 1e3;   ///< tangent mode: an interval whose vectors lose more than this is halved; 0: fixed
  double transient = 0;  ///< time integrated first, its stretches discarded (the vectors align meanwhile)
  double perturbation = 1e-8;    ///< initial perturbation (perturbed mode)
  double maxPerturbation = 1e-4; ///< perturbed mode: an interval is cut short (by halving) beyond this
  int estimateEvery = 10;        ///< iterations between the compared estimates
  double accuracy = 1e-4;        ///< estimates this close count as a successful comparison
  int successes = 0;             ///< stop after this many successful comparisons in a row (0: never)
  double outputPeriod = 10;      ///< time between streamed estimates
  bool renormalizeIntegrals =
      false;             ///< keep tangent vectors on the integrals' level set (trivial exponents vanish)
  double maxTime = 1000; ///< time over which the exponents are averaged, after the transient
};

/// The scene section "lyapunov", each parameter beside its member.
const SettingsTable<LyapunovSettings>& lyapunovSettingsTable();

struct LyapunovEstimate {
  double time = 0;
  std::vector<double> exponents;
  double sum() const;
};

struct LyapunovResult {
  LyapunovEstimate last;
  bool converged = false;
  bool stopped = false; ///< stopped by request before maxTime
  /// Where precision was lost all the same (an interval at its shortest whose vectors still spread beyond
  /// the bound), what it means and which setting helps; empty when none was.
  std::string warning;
};

class TangentSystem;

/// The algorithm as a resumable computation: run() goes on from where a stop left it.
class LyapunovRun {
public:
  /// Throws InputError for bad settings.
  LyapunovRun(const Model& model, IntegratorFactory makeIntegrator, const Eigen::VectorXd& x0,
              LyapunovSettings settings);
  ~LyapunovRun();
  /// Continues until maxTime, convergence or a stop request; `onEstimate` receives the running estimates
  /// every output period. Returns true when finished (maxTime or converged). Throws ComputationError on a
  /// failed step.
  bool run(const std::function<void(const LyapunovEstimate&)>& onEstimate = {},
           const ToolControl& control = {});
  const LyapunovResult& result() const { return result_; }
  /// Whether the run is over (its time reached, or converged).
  bool finished() const { return t_ >= endTime() || result_.converged; }
  /// One interval and its estimate: what run() repeats. False when stopped on the way (nothing changes).
  bool advanceOneInterval(const std::function<void(const LyapunovEstimate&)>& onEstimate,
                          const ToolControl& control);

  /// Runs advanced together on SIMD lanes (LyapunovLanes.h) take an interval in three parts: its advance --
  /// the number of fused rk4 steps of fusedStepSize() that make it (0 where the fused path does not apply),
  /// or an integrator from time() over nextSpan() (a fresh one each interval, as run() starts them) -- of the
  /// state (x, then the tangent vectors, as TangentSystem lays them out), and the interval's close once
  /// advanced (the estimate as run() makes it).
  long nextFusedSteps() const;
  double fusedStepSize() const { return fusedStep_; }
  double time() const { return t_; }
  double nextSpan() const { return std::min(span_, endTime() - t_); }
  Eigen::VectorXd& tangentState() { return state_; }
  /// Closes the interval advanced over nextSpan(); false when it is taken again, shorter (its vectors spread
  /// beyond `spread`): the run is then back at its start, tangentState() and nextSpan() anew.
  bool closeAdvancedInterval(const std::function<void(const LyapunovEstimate&)>& onEstimate,
                             const ToolControl& control);
  int exponentCount() const { return k_; }
  /// Whether the interval is taken by the tangent method (not perturbed orbits).
  bool tangentMode() const { return tangent_ != nullptr; }
  /// Saves the run at its last finished interval (every interval restarts the integrators from there):
  /// restore() into a run built from the same model, settings and start goes on bit-identically.
  void save(Snapshot& s) const;
  void restore(Snapshot& s);

private:
  void startAll(double t0);
  void project(const Eigen::VectorXd& x, Eigen::MatrixXd& V) const;
  bool interval(const ToolControl& control);
  bool close(double span);
  double shorterSpan(double span) const;
  double endTime() const { return s_.transient + s_.maxTime; }
  void recordEstimate(const std::function<void(const LyapunovEstimate&)>& onEstimate,
                      const ToolControl& control);
  long fusedSteps(double span) const;
  bool advanceFused(long steps, const ToolControl& control);
  const Model& model_;
  IntegratorFactory make_;
  LyapunovSettings s_;
  int m_, n_, k_;
  double interval_, t_ = 0, nextOutput_;
  double span_;          ///< the next interval's length (tangent mode: adapted to the vectors' spread)
  double tStart_ = 0;    ///< where the averaging began (the transient's end)
  double fusedStep_ = 0; ///< the rk4 step when the model fuses it with its tangent equations, else 0
  int successes_ = 0;
  Eigen::VectorXd logs_, x_, state_;
  Eigen::MatrixXd V_;
  std::vector<Eigen::VectorXd> history_;
  std::unique_ptr<TangentSystem> tangent_;
  std::vector<std::unique_ptr<Integrator>> integs_;
  LyapunovResult result_;
};

/// Runs the algorithm from x0 to the end; `onEstimate` receives the running estimates every output period.
/// Throws InputError for bad settings, ComputationError when the integration fails.
LyapunovResult lyapunovExponents(const Model& model, const IntegratorFactory& makeIntegrator,
                                 const Eigen::VectorXd& x0, const LyapunovSettings& settings,
                                 const std::function<void(const LyapunovEstimate&)>& onEstimate = {},
                                 const ToolControl& control = {});

} // namespace rv
