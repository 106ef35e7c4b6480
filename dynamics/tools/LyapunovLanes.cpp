#include "dynamics/tools/LyapunovLanes.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/LaneField.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/tools/LaneStack.h"
#include "dynamics/tools/TangentSystem.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace rv {

namespace {

// the lane kernel and the run of each orbit, where they go on lanes; InputError for bad settings
struct LaneRuns {
  std::unique_ptr<LaneKernel> kernel;
  std::vector<std::unique_ptr<LyapunovRun>> runs;
  bool fused = false; ///< rk4 fused with the tangent equations; else an integrator on the stacked systems
};

// whether these runs go on lanes, asked of the settings, the models and the integrator alone: no run is
// started (a method whose start integrates, Adams's, would integrate whatever state it was given)
std::optional<LaneRuns> lanePlan(const std::vector<const Model*>& models, const IntegratorFactory& make,
                                 const LyapunovSettings& s) {
  if (s.mode != LyapunovSettings::Mode::Tangent || models.empty() || models.front()->isMap())
    return std::nullopt;
  const Model& model = *models.front();
  const int k = s.count > 0 ? s.count : model.info().coreDimension;
  if (k < 1 || k > model.info().coreDimension) return std::nullopt; // the scalar run says why
  LaneRuns r;
  r.kernel = laneKernelFor(models);
  if (!r.kernel || !r.kernel->compiledFor(k)) return std::nullopt;
  std::vector<double> probe(1); // the kernel's fixed counts of vectors (the same for tangentRhs)
  if (!r.kernel->tangentRk4(probe.data(), k, 0, 0)) return std::nullopt;
  // rk4 fused with the tangent equations where the model has that path (as LyapunovRun decides), else a
  // method that steps each lane as alone
  const auto integrator = make();
  const TangentSystem tangent(model, k);
  Eigen::VectorXd ask = Eigen::VectorXd::Zero(tangent.dimension());
  r.fused = dynamic_cast<const Rk4*>(integrator.get()) != nullptr && tangent.rk4Steps(ask, 0, 0);
  if (!r.fused && !integrator->stepLanesAlone(r.kernel->width())) return std::nullopt;
  return r;
}

// the lane plan and the run of each orbit; InputError for bad settings
std::optional<LaneRuns> laneRuns(const std::vector<const Model*>& models, const IntegratorFactory& make,
                                 const std::vector<Eigen::VectorXd>& x0s, const LyapunovSettings& s) {
  auto r = lanePlan(models, make, s);
  if (!r) return std::nullopt;
  for (std::size_t l = 0; l < x0s.size(); ++l)
    r->runs.push_back(std::make_unique<LyapunovRun>(*models[l], make, x0s[l], s));
  if (r->fused != (r->runs.front()->fusedStepSize() > 0))
    throw std::logic_error("lyapunovOnLanes: the plan and the run disagree on rk4's fused path");
  return r;
}

// W tangent systems (TangentSystem, k vectors) stacked component-major: the lanes' kernel is its field
class LaneTangents final : public LaneStack {
public:
  /// `models`: the lanes' models (the last one repeated into lanes left over)
  LaneTangents(const std::vector<const Model*>& models, const LaneKernel& kernel, int k)
      : LaneStack(*models.front(), kernel,
                  models.front()->dimension() + models.front()->info().coreDimension * k, "lyapunov lanes"),
        k_(k) {
    ownLaneSystems(models, [k](const Model& model) { return std::make_unique<TangentSystem>(model, k); });
  }
  void rhs(const double* y, double* dy) const override { kernel_.tangentRhs(y, k_, dy); }

private:
  int k_;
};

} // namespace

bool lyapunovRunsOnLanes(const std::vector<const Model*>& models, const IntegratorFactory& makeIntegrator,
                         const LyapunovSettings& settings) {
  return lanePlan(models, makeIntegrator, settings).has_value();
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
  // a run whose interval was taken again shorter (its vectors spread: LyapunovRun::closeAdvancedInterval)
  // no longer shares the lanes' time: it goes on alone, as the scalar run
  std::vector<bool> solo(count, false);
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
  const int k = runs.front()->exponentCount();
  const LaneTangents stacked(models, *lanes->kernel, k);
  constexpr long kChunk = 4096; // steps between looks at a stop request and at the state (as LyapunovRun)
  // the next interval of every active run on the lanes, from `lead`, an active run (lanes of runs done and
  // lanes left over take its orbit: a finished or failed orbit's state must not fail the batch); true when
  // advanced, false when stopped; the orbits that failed (a blow-up) marked in blewUp
  const auto onLanes = [&](std::size_t leadLane, long steps, std::vector<bool>& blewUp) {
    for (std::size_t l = 0; l < static_cast<std::size_t>(width); ++l) {
      const Eigen::VectorXd& x = runs[l < count && active(l) && !solo[l] ? l : leadLane]->tangentState();
      for (int j = 0; j < dimension; ++j)
        y[at(j, l)] = x[j];
    }
    if (lanes->fused) {
      for (long done = 0; done < steps; done += kChunk) {
        if (control.stopRequested()) return false;
        lanes->kernel->tangentRk4(y.data(), k, h, std::min(kChunk, steps - done));
        for (std::size_t l = 0; l < count; ++l)
          for (int j = 0; j < dimension && !blewUp[l]; ++j)
            blewUp[l] = !std::isfinite(y[at(j, l)]);
      }
      return true;
    }
    // as LyapunovRun takes an interval with its integrator: a fresh one from the interval's start, stepped
    // past its end and interpolated back; a failed step fails the batch, and each orbit goes alone
    const LyapunovRun& lead = *runs[leadLane];
    const double target = lead.time() + lead.nextSpan();
    try {
      auto integ = makeIntegrator();
      integ->stepLanesAlone(width); // each lane's steps controlled by its orbit and vectors, as alone
      integ->scaleErrorsByBlocks(models.front()->dimension(), models.front()->info().coreDimension);
      Eigen::VectorXd state =
          Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(y.size()));
      integ->start(stacked, lead.time(), state);
      if (!integ->advanceTo(target, state, [&] { return control.stopRequested(); })) return false;
      std::copy(state.begin(), state.end(), y.begin());
    } catch (const ComputationError&) {
      std::fill(blewUp.begin(), blewUp.end(), true);
    }
    return true;
  };
  const auto finishAlone = [&] {
    for (std::size_t l = 0; l < count; ++l)
      while (solo[l] && active(l))
        if (!alone(l)) return false;
    return true;
  };
  for (;;) {
    // the lanes' next interval: the same span and steps for every active run (one time, one step)
    long steps = -1;
    std::size_t leadLane = 0;
    for (std::size_t l = count; l-- > 0;) {
      if (!active(l) || solo[l]) continue;
      steps = lanes->fused ? runs[l]->nextFusedSteps() : 1;
      leadLane = l;
    }
    if (steps < 0) { // every run on the lanes done
      if (!finishAlone()) return std::vector<LyapunovLaneResult>{};
      break;
    }
    for (std::size_t l = 0; l < count; ++l)
      if (active(l) && !solo[l] &&
          (runs[l]->time() != runs[leadLane]->time() || runs[l]->nextSpan() != runs[leadLane]->nextSpan()))
        solo[l] = true;
    if (steps == 0) { // an interval the fused path does not make: each run alone
      for (std::size_t l = 0; l < count; ++l)
        if (active(l) && !solo[l] && !alone(l)) return std::vector<LyapunovLaneResult>{};
      continue;
    }
    std::vector<bool> blewUp(count, false);
    if (!onLanes(leadLane, steps, blewUp)) return std::vector<LyapunovLaneResult>{};
    for (std::size_t l = 0; l < count; ++l) {
      if (!active(l) || solo[l]) continue;
      if (blewUp[l]) { // from the interval's start, alone: the scalar run's failure, at its time
        if (!alone(l)) return std::vector<LyapunovLaneResult>{};
        continue;
      }
      Eigen::VectorXd& x = runs[l]->tangentState();
      for (int j = 0; j < dimension; ++j)
        x[j] = y[at(j, l)];
      if (!runs[l]->closeAdvancedInterval({}, control)) solo[l] = true;
    }
  }
  for (std::size_t l = 0; l < count; ++l)
    if (!failed[l]) results[l].result = runs[l]->result();
  return results;
}

} // namespace rv
