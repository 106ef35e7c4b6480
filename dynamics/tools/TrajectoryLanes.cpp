#include "dynamics/tools/TrajectoryLanes.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/LaneField.h"
#include "dynamics/tools/LaneStack.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

namespace rv {

namespace {

// W orbits stacked component-major (y[c * W + l]: component c of lane l), the kernel's field alone (no
// tangent direction): each lane's field its model's right-hand side, bit for bit
class OrbitStack final : public LaneStack {
public:
  OrbitStack(const std::vector<const Model*>& models, const LaneKernel& kernel)
      : LaneStack(*models.front(), kernel, models.front()->dimension(), "orbit lanes") {}
  void rhs(const double* y, double* dy) const override { kernel_.tangentRhs(y, 0, dy); }
};

} // namespace

bool trajectoriesRunOnLanes(const std::vector<const Model*>& models,
                            const IntegratorFactory& makeIntegrator) {
  if (models.empty() || models.front()->isMap()) return false;
  const auto kernel = laneKernelFor(models);
  if (!kernel || !kernel->compiledFor(0)) return false;
  const auto integrator = makeIntegrator();
  return integrator->stepLanesAlone(kernel->width()) && !integrator->lanesStepOnTheirOwn();
}

namespace {
// the orbits stacked and an integrator started on them (integrating in `direction`), stepping lanes as alone
struct OrbitsOnLanes {
  std::unique_ptr<LaneKernel> kernel;
  std::unique_ptr<OrbitStack> stack;
  std::unique_ptr<Integrator> integ;
  int width = 0, n = 0;
  /// lane l's components of a stacked state
  void lane(const Eigen::VectorXd& stacked, int l, Eigen::VectorXd& out) const {
    for (int c = 0; c < n; ++c)
      out[c] = stacked[c * width + l];
  }
};
OrbitsOnLanes startOnLanes(const std::vector<const Model*>& models, const IntegratorFactory& makeIntegrator,
                           const std::vector<Eigen::VectorXd>& x0s, int direction) {
  if (x0s.empty() || x0s.size() != models.size())
    throw std::logic_error("orbits on lanes: one model per state");
  OrbitsOnLanes o;
  o.kernel = laneKernelFor(models);
  if (!o.kernel || models.front()->isMap())
    throw std::logic_error("orbits on lanes: these do not go on lanes");
  o.stack = std::make_unique<OrbitStack>(models, *o.kernel);
  o.width = o.kernel->width(), o.n = models.front()->dimension();
  const int count = static_cast<int>(x0s.size());
  Eigen::VectorXd y(static_cast<Eigen::Index>(o.n) * o.width);
  for (int l = 0; l < o.width; ++l) {
    const Eigen::VectorXd& x0 = x0s[static_cast<std::size_t>(std::min(l, count - 1))];
    if (x0.size() != o.n) throw InputError("the initial state has the wrong size");
    for (int c = 0; c < o.n; ++c)
      y[c * o.width + l] = x0[c];
  }
  o.integ = makeIntegrator();
  if (!o.integ->stepLanesAlone(o.width) || o.integ->lanesStepOnTheirOwn())
    throw std::logic_error("orbits on lanes: the method does not step lanes as alone with one time");
  o.integ->start(*o.stack, 0.0, y, direction);
  return o;
}
} // namespace

bool integrateOnLanes(const std::vector<const Model*>& models, const IntegratorFactory& makeIntegrator,
                      const std::vector<Eigen::VectorXd>& x0s, double time, const ToolControl& control,
                      const LaneStep& onStep) {
  const OrbitsOnLanes o = startOnLanes(models, makeIntegrator, x0s, +1);
  Integrator& integ = *o.integ;
  // as Scene's integrateTo, orbit by orbit: each step from its start to its end, the last cut at `time`
  const int count = static_cast<int>(x0s.size());
  std::vector<Eigen::VectorXd> previous(x0s.begin(), x0s.end()), now(x0s.size(), Eigen::VectorXd(o.n));
  Eigen::VectorXd end;
  double tPrevious = integ.time();
  while (tPrevious < time) {
    if (control.stopRequested()) return false;
    integ.step();
    const bool last = integ.time() >= time;
    if (last) integ.sampleAt(time, end);
    const double t = last ? time : integ.time();
    for (int l = 0; l < count; ++l) {
      const auto k = static_cast<std::size_t>(l);
      o.lane(last ? end : integ.state(), l, now[k]);
      onStep(l, tPrevious, previous[k], t, now[k]);
      std::swap(previous[k], now[k]);
    }
    if (last) break;
    tPrevious = t;
  }
  return true;
}

std::optional<std::vector<std::vector<MapPoint>>> mapPointsOnLanes(const std::vector<const Model*>& models,
                                                                   const IntegratorFactory& makeIntegrator,
                                                                   const std::vector<Eigen::VectorXd>& x0s,
                                                                   const SectionSettings& settings,
                                                                   const ToolControl& control) {
  if (settings.maxPoints <= 0) throw std::logic_error("mapPointsOnLanes: give the points' number");
  const OrbitsOnLanes o = startOnLanes(models, makeIntegrator, x0s, settings.backward ? -1 : +1);
  Integrator& integ = *o.integ;
  const int count = static_cast<int>(x0s.size()), direction = integ.direction();
  std::vector<SectionCrossings> crossings;
  for (int l = 0; l < count; ++l) {
    crossings.emplace_back(*models[static_cast<std::size_t>(l)], settings);
    crossings.back().start(integ.time(), x0s[static_cast<std::size_t>(l)]);
  }
  std::vector<std::vector<MapPoint>> points(x0s.size());
  std::vector<int> open(x0s.size(), 1);
  Eigen::VectorXd lane(o.n), stacked;
  int located = 0; // the lane whose crossing is located: the stack's dense output, read at that lane
  const SectionCrossings::Interpolate interpolate = [&](double t, Eigen::VectorXd& out) {
    integ.sampleAt(t, stacked);
    o.lane(stacked, located, out);
  };
  // as PoincareMap::next of each orbit alone: steps until its points are all there or the time is up
  while (std::ranges::count(open, 1) > 0) {
    if (control.stopRequested()) return std::nullopt;
    if (direction * integ.time() >= settings.maxTime) break;
    integ.step();
    for (int l = 0; l < count; ++l) {
      const auto k = static_cast<std::size_t>(l);
      if (!open[k]) continue;
      o.lane(integ.state(), l, lane);
      located = l;
      auto point = crossings[k].afterStep(integ.previousTime(), integ.time(), lane, direction, interpolate);
      if (!point) continue;
      points[k].push_back(std::move(*point));
      open[k] = static_cast<long>(points[k].size()) < settings.maxPoints;
    }
  }
  return points;
}

} // namespace rv
