#include "dynamics/tools/LyapunovLanes.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/LaneField.h"

#include <cmath>
#include <memory>

namespace rv {

namespace {

// the lane kernel and the run of each orbit, where they go on lanes; InputError for bad settings
struct LaneRuns {
  std::unique_ptr<LaneKernel> kernel;
  std::vector<std::unique_ptr<LyapunovRun>> runs;
};

std::optional<LaneRuns> laneRuns(const std::vector<const Model*>& models, const IntegratorFactory& make,
                                 const std::vector<Eigen::VectorXd>& x0s, const LyapunovSettings& s) {
  if (s.mode != LyapunovSettings::Mode::Tangent) return std::nullopt;
  LaneRuns r;
  r.kernel = laneKernelFor(models);
  if (!r.kernel) return std::nullopt;
  for (std::size_t l = 0; l < x0s.size(); ++l) {
    r.runs.push_back(std::make_unique<LyapunovRun>(*models[l], make, x0s[l], s));
    if (r.runs.back()->fusedStepSize() == 0) return std::nullopt; // not rk4: each alone
  }
  std::vector<double> probe(1);
  if (!r.kernel->tangentRk4(probe.data(), r.runs.front()->exponentCount(), 0, 0))
    return std::nullopt; // more exponents than the fused path takes
  return r;
}

} // namespace

bool lyapunovRunsOnLanes(const std::vector<const Model*>& models, const IntegratorFactory& makeIntegrator,
                         const LyapunovSettings& settings) {
  if (models.empty()) return false;
  std::vector<Eigen::VectorXd> starts(models.size(), Eigen::VectorXd::Zero(models.front()->dimension()));
  return laneRuns(models, makeIntegrator, starts, settings).has_value();
}

std::optional<std::vector<LyapunovLaneResult>> lyapunovOnLanes(const std::vector<const Model*>& models,
                                                               const IntegratorFactory& makeIntegrator,
                                                               const std::vector<Eigen::VectorXd>& x0s,
                                                               const LyapunovSettings& s,
                                                               const ToolControl& control) {
  if (x0s.empty() || x0s.size() != models.size())
    throw std::logic_error("lyapunovOnLanes: one model per state");
  auto lanes = laneRuns(models, makeIntegrator, x0s, s);
  if (!lanes) return std::nullopt;
  auto& runs = lanes->runs;
  const std::size_t count = runs.size();
  std::vector<LyapunovLaneResult> results(count);
  std::vector<bool> failed(count, false);
  const auto active = [&](std::size_t l) { return !failed[l] && !runs[l]->finished(); };
  // an orbit's interval alone: as the scalar run takes it, failing (or not) as it fails alone
  const auto alone = [&](std::size_t l) {
    try {
      return runs[l]->advanceOneInterval({}, control);
    } catch (const ComputationError&) {
      results[l].failure = std::current_exception();
      failed[l] = true;
      return true;
    }
  };
  const int dimension = static_cast<int>(runs.front()->tangentState().size());
  const int width = lanes->kernel->width();
  std::vector<double> y(static_cast<std::size_t>(dimension) * static_cast<std::size_t>(width));
  const auto at = [width](int component, std::size_t lane) { // component-major: y[j * width + l]
    return static_cast<std::size_t>(component) * static_cast<std::size_t>(width) + lane;
  };
  const double h = runs.front()->fusedStepSize();
  constexpr long kChunk = 4096; // steps between looks at a stop request and at the state (as LyapunovRun)
  for (;;) {
    // the lanes' next interval: the same span and steps for every active run (one time, one step)
    long steps = -1;
    for (std::size_t l = 0; l < count; ++l)
      if (active(l)) steps = runs[l]->nextFusedSteps();
    if (steps < 0) break; // every run done
    if (steps == 0) {     // an interval the fused path does not make: each run alone
      for (std::size_t l = 0; l < count; ++l)
        if (active(l) && !alone(l)) return std::vector<LyapunovLaneResult>{};
      continue;
    }
    for (int l = 0; l < width; ++l) { // lanes left over repeat the last orbit
      const Eigen::VectorXd& x =
          runs[std::min<std::size_t>(static_cast<std::size_t>(l), count - 1)]->tangentState();
      for (int j = 0; j < dimension; ++j)
        y[at(j, static_cast<std::size_t>(l))] = x[j];
    }
    std::vector<bool> blewUp(count, false);
    for (long done = 0; done < steps; done += kChunk) {
      if (control.stopRequested()) return std::vector<LyapunovLaneResult>{};
      lanes->kernel->tangentRk4(y.data(), runs.front()->exponentCount(), h, std::min(kChunk, steps - done));
      for (std::size_t l = 0; l < count; ++l)
        for (int j = 0; j < dimension && !blewUp[l]; ++j)
          blewUp[l] = !std::isfinite(y[at(j, l)]);
    }
    for (std::size_t l = 0; l < count; ++l) {
      if (!active(l)) continue;
      if (blewUp[l]) { // from the interval's start, alone: the scalar run's failure, at its time
        if (!alone(l)) return std::vector<LyapunovLaneResult>{};
        continue;
      }
      Eigen::VectorXd& x = runs[l]->tangentState();
      for (int j = 0; j < dimension; ++j)
        x[j] = y[at(j, l)];
      runs[l]->closeFusedInterval({}, control);
    }
  }
  for (std::size_t l = 0; l < count; ++l)
    if (!failed[l]) results[l].result = runs[l]->result();
  return results;
}

} // namespace rv
