// Lyapunov.h -- the spectrum of Lyapunov exponents along a trajectory by the generalised Benettin algorithm
// (manual §2.3.3): k tangent vectors (or k perturbed trajectories) re-orthonormalised by QR every interval,
// the logarithms of the stretches accumulated. Reference: G. Benettin, L. Galgani, A. Giorgilli, J.-M.
// Strelcyn, Meccanica 15 (1980) 9-30; the tangent mode integrates the variational equations with the model's
// exact (AutoDiff) Jacobian.
#pragma once
#include "dynamics/core/ParameterTable.h"
#include "dynamics/integrators/Integrator.h"
#include "dynamics/tools/ToolControl.h"

#include <algorithm>
#include <functional>
#include <memory>
#include <vector>

namespace rv {

struct LyapunovSettings {
  enum class Mode { Tangent, Perturbed };
  Mode mode = Mode::Tangent;
  int count = 0;                 ///< number of exponents; 0: the core dimension
  double interval = 1.0;         ///< one iteration time between re-orthonormalisations (maps: iterations)
  double perturbation = 1e-8;    ///< initial perturbation (perturbed mode)
  double maxPerturbation = 1e-4; ///< perturbed mode: an interval is cut short (by halving) beyond this
  int estimateEvery = 10;        ///< iterations between the compared estimates
  double accuracy = 1e-4;        ///< estimates this close count as a successful comparison
  int successes = 0;             ///< stop after this many successful comparisons in a row (0: never)
  double outputPeriod = 10;      ///< time between streamed estimates
  bool renormalizeIntegrals =
      false;             ///< keep tangent vectors on the integrals' level set (trivial exponents vanish)
  double maxTime = 1000; ///< stop at this time at the latest
};

/// The scene section "lyapunov" (the one declaration of the settings' defaults and ranges).
const ParameterTable& lyapunovTable();
LyapunovSettings lyapunovSettings(const ParameterValues& v);

struct LyapunovEstimate {
  double time = 0;
  std::vector<double> exponents;
  double sum() const;
};

struct LyapunovResult {
  LyapunovEstimate last;
  bool converged = false;
  bool stopped = false; ///< stopped by request before maxTime
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
  bool finished() const { return t_ >= s_.maxTime || result_.converged; }
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
  double nextSpan() const { return std::min(interval_, s_.maxTime - t_); }
  Eigen::VectorXd& tangentState() { return state_; }
  void closeAdvancedInterval(const std::function<void(const LyapunovEstimate&)>& onEstimate,
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
  void project();
  bool interval(const ToolControl& control);
  void close(double span);
  void recordEstimate(const std::function<void(const LyapunovEstimate&)>& onEstimate,
                      const ToolControl& control);
  long fusedSteps(double span) const;
  bool advanceFused(long steps, const ToolControl& control);
  const Model& model_;
  IntegratorFactory make_;
  LyapunovSettings s_;
  int m_, n_, k_;
  double interval_, t_ = 0, nextOutput_;
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
