// Lyapunov.h -- the spectrum of Lyapunov exponents along a trajectory by the generalised Benettin algorithm
// (manual §2.3.3): k tangent vectors (or k perturbed trajectories) re-orthonormalised by QR every interval, the
// logarithms of the stretches accumulated.
// Reference: G. Benettin, L. Galgani, A. Giorgilli, J.-M. Strelcyn, Meccanica 15 (1980) 9-30; the tangent mode
// integrates the variational equations with the model's exact (AutoDiff) Jacobian.
#pragma once
#include "dynamics/integrators/Integrator.h"
#include "dynamics/tools/ToolControl.h"

#include <functional>
#include <memory>
#include <vector>

namespace rv {

struct LyapunovSettings {
  enum class Mode { Tangent, Perturbed };
  Mode mode = Mode::Tangent;
  int count = 0;                   ///< number of exponents; 0: the core dimension
  double interval = 1.0;           ///< one iteration time between re-orthonormalisations (maps: iterations)
  double perturbation = 1e-8;      ///< initial perturbation (perturbed mode)
  double maxPerturbation = 1e-4;   ///< perturbed mode: an interval is cut short (by halving) beyond this
  int estimateEvery = 10;          ///< iterations between the compared estimates
  double accuracy = 1e-4;          ///< estimates this close count as a successful comparison
  int successes = 0;               ///< stop after this many successful comparisons in a row (0: never)
  double outputPeriod = 10;        ///< time between streamed estimates
  bool renormalizeIntegrals = false; ///< keep tangent vectors on the integrals' level set (trivial exponents vanish)
  double maxTime = 1000;           ///< stop at this time at the latest
};

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

using IntegratorFactory = std::function<std::unique_ptr<Integrator>()>;

/// Runs the algorithm from x0; `onEstimate` receives the running estimates every output period.
/// Throws InputError for bad settings, ComputationError when the integration fails.
LyapunovResult lyapunovExponents(const Model& model, const IntegratorFactory& makeIntegrator, const Eigen::VectorXd& x0,
                                 const LyapunovSettings& settings,
                                 const std::function<void(const LyapunovEstimate&)>& onEstimate = {},
                                 const ToolControl& control = {});

} // namespace rv
