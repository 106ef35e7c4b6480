// Megno.h -- the chaos indicators MEGNO and FLI along a trajectory of a flow or a map.
//
// MEGNO (Mean Exponential Growth factor of Nearby Orbits): with w a tangent vector and
// delta = |w|, Y(t) = (2/t) int_0^t s (d ln delta/ds) ds and <Y>(t) = (1/t) int_0^t Y(s) ds.
// <Y> -> 2 on quasi-periodic orbits (linear growth of |w|), -> 0 on stable periodic orbits of maps, and grows
// like lambda t / 2 on chaotic ones (lambda the largest Lyapunov exponent). Maps use the discrete sums
// Y(N) = (2/N) sum_k k ln(delta_k / delta_{k-1}), <Y>(N) = (1/N) sum_k Y(k).
// References: P. M. Cincotta, C. Simo, Astron. Astrophys. Suppl. 147 (2000) 205-228; P. M. Cincotta,
// C. M. Giordano, C. Simo, Physica D 182 (2003) 151-178; K. Gozdziewski et al., Astron. Astrophys. 378 (2001)
// 569-586 (the integrals as extra differential equations, as REBOUND does).
//
// FLI (Fast Lyapunov Indicator): ln |w(t)| of the tangent vector (Froeschle, Lega, Gonczi, Celest. Mech.
// Dyn. Astron. 67 (1997) 41-62), kept finite by renormalising w and adding up the logarithms.
#pragma once
#include "dynamics/core/SettingsTable.h"
#include "dynamics/core/Snapshot.h"
#include "dynamics/tools/Lyapunov.h"

#include <cmath>
#include <functional>
#include <memory>

namespace rv {

/// dA/dt = tau (w . w') / (w . w) of the MEGNO integrals, the sums taken in index order over the m
/// components found `stride` apart: the scalar run and the batched one (MegnoLanes.h) use this one formula,
/// so a lane's numbers are the scalar run's bit for bit.
inline double megnoIntegrand(double tau, const double* w, const double* dw, int m, int stride = 1) {
  double dot = 0, squared = 0;
  for (int i = 0; i < m; ++i) {
    dot += w[i * stride] * dw[i * stride];
    squared += w[i * stride] * w[i * stride];
  }
  return tau * dot / squared;
}

/// |w| summed in index order (as megnoIntegrand).
inline double tangentLength(const double* w, int m, int stride = 1) {
  double squared = 0;
  for (int i = 0; i < m; ++i)
    squared += w[i * stride] * w[i * stride];
  return std::sqrt(squared);
}

struct MegnoSettings {
  double maxTime = 1000;    ///< integration time (maps: iterations)
  double outputPeriod = 10; ///< time between streamed estimates
  double interval = 10;     ///< the tangent vector is renormalised (and flows restarted) this often
};

/// The scene section "megno": time, output_period, interval, each beside its member.
const SettingsTable<MegnoSettings>& megnoSettingsTable();

struct MegnoEstimate {
  double time = 0;
  double megno = 0;     ///< <Y>(t), the time-averaged MEGNO
  double y = 0;         ///< Y(t), the instantaneous MEGNO
  double megnoRate = 0; ///< <Y> / (t/2): tends to the largest Lyapunov exponent on chaotic orbits
  double fli = 0;       ///< ln |w(t)|, w(0) a unit vector
};

struct MegnoResult {
  MegnoEstimate last;
  bool stopped = false; ///< stopped by request before maxTime
};

/// The computation, resumable: run() goes on from where a stop left it.
class MegnoRun {
public:
  /// Throws InputError for bad settings.
  MegnoRun(const Model& model, IntegratorFactory makeIntegrator, const Eigen::VectorXd& x0,
           MegnoSettings settings);
  ~MegnoRun();
  /// Continues to maxTime or a stop request; `onEstimate` receives the estimates every output period.
  /// Returns true when finished. Throws ComputationError when the integration fails.
  bool run(const std::function<void(const MegnoEstimate&)>& onEstimate = {}, const ToolControl& control = {});
  const MegnoResult& result() const { return result_; }
  /// The system a flow's run integrates: the model with one tangent vector w in core coordinates, then tau, A
  /// and B (MegnoLanes.h stacks one per lane).
  static std::unique_ptr<Model> system(const Model& model);
  /// Saves the run at its last finished interval; restore() into a run built alike goes on bit-identically.
  void save(Snapshot& s) const;
  void restore(Snapshot& s);

private:
  class System;
  void start();
  bool flowInterval(const ToolControl& control);
  void mapIteration();
  void record();
  const Model& model_;
  IntegratorFactory make_;
  MegnoSettings s_;
  int n_, m_;
  double t_ = 0, nextOutput_, logNorm_ = 0;
  double sumA_ = 0, sumB_ = 0; ///< maps: sum k ln(delta_k/delta_{k-1}) and sum Y(k)
  Eigen::VectorXd state_;      ///< flows: x, w, then tau, A, B; maps: x, w
  std::unique_ptr<System> system_;
  std::unique_ptr<Integrator> integ_;
  MegnoResult result_;
};

/// Runs MEGNO and FLI from x0 to the end.
MegnoResult megno(const Model& model, const IntegratorFactory& makeIntegrator, const Eigen::VectorXd& x0,
                  const MegnoSettings& settings,
                  const std::function<void(const MegnoEstimate&)>& onEstimate = {},
                  const ToolControl& control = {});

} // namespace rv
