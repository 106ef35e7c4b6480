// SweepTool.cpp -- the sweep tool: a chart of regimes over a grid (scenes/Sweep.h), and the quantities it
// reads along each point's trajectory itself, on no tool's result (observable.NAME, reversal). Its front
// ends are written by hand (app/cli/SweepCommand.cpp, the GUI's sweep window), so it has no runner; its
// settings are a sweep file's "options" (sweepOptionsTable), not a scene section.
#include "dynamics/core/Errors.h"
#include "dynamics/core/NaN.h"
#include "dynamics/tools/ToolSettings.h"
#include "dynamics/tools/TrajectoryLanes.h"
#include "scenes/builtin/BuiltinTool.h"

#include <cmath>
#include <limits>
#include <memory>

namespace rv {

namespace {

// the observable named after a quantity's prefix, or the default
const Observable& namedObservable(const Scene& scene, const std::string& name) {
  const int k = scene.model->findObservable(name);
  if (k < 0) throw InputError("no observable '" + name + "' in " + scene.model->info().id);
  return scene.model->observables()[static_cast<std::size_t>(k)];
}

// the scene's trajectory up to `time`: `onStep(t0, x0, t1, x1)` sees every step, the last one cut at `time`
template <class OnStep>
void integrateTo(const Scene& scene, double time, const ToolControl& control, OnStep onStep) {
  auto integ = scene.startIntegrator();
  Eigen::VectorXd prev = integ->state(), end;
  double tPrev = integ->time();
  while (tPrev < time) {
    if (control.stopRequested()) throw Stopped{};
    integ->step();
    if (integ->time() >= time) {
      integ->sampleAt(time, end);
      onStep(tPrev, prev, time, end);
      return;
    }
    onStep(tPrev, prev, integ->time(), integ->state());
    prev = integ->state();
    tPrev = integ->time();
  }
}

// What a trajectory quantity reads along one orbit: each step as integrateTo gives it, and its values at the
// end. One reading per point, whether the point's orbit is integrated alone or on a lane beside others.
struct OrbitReading {
  std::function<void(double t0, const Eigen::VectorXd& x0, double t1, const Eigen::VectorXd& x1)> onStep;
  std::function<std::vector<double>()> values;
};
using ReadingOf = OrbitReading (*)(const SweepSpec&, const Scene&);

// observable.NAME: the value at the end, or the time average by the trapezoidal rule
OrbitReading observableReading(const SweepSpec& sp, const Scene& s) {
  struct Sums {
    double sum = 0, last = 0;
  };
  const Observable& f = namedObservable(s, sp.quantityName);
  const double time = sp.options->get("time");
  const bool mean = sp.options->choice("statistic") == "mean";
  auto sums = std::make_shared<Sums>();
  sums->last = f.value(0, s.initialState.data());
  return {[&f, sums](double t0, const Eigen::VectorXd& x0, double t1, const Eigen::VectorXd& x1) {
            const double v = f.value(t1, x1.data());
            sums->sum += 0.5 * (f.value(t0, x0.data()) + v) * (t1 - t0);
            sums->last = v;
          },
          [sums, mean, time] { return std::vector<double>{mean ? sums->sum / time : sums->last}; }};
}

// reversal[.NAME]: whether the observable (the spin about the vertical) changed sign, when first (linear
// interpolation in the step), and its value at the end
OrbitReading reversalReading(const SweepSpec& sp, const Scene& s) {
  struct Sign {
    double start = 0, at = kNaN, end = 0;
  };
  const Observable& f = namedObservable(s, sp.quantityName.empty() ? "omega_vertical" : sp.quantityName);
  auto sign = std::make_shared<Sign>();
  sign->start = sign->end = f.value(0, s.initialState.data());
  return {[&f, sign](double t0, const Eigen::VectorXd& x0, double t1, const Eigen::VectorXd& x1) {
            const double a = f.value(t0, x0.data()), b = f.value(t1, x1.data());
            if (std::isnan(sign->at) && sign->start != 0 && b * sign->start < 0)
              sign->at = a == b ? t1 : t0 + (t1 - t0) * a / (a - b);
            sign->end = b;
          },
          [sign] {
            return std::vector<double>{std::isnan(sign->at) ? 0.0 : 1.0, sign->at, sign->end};
          }};
}
// a trajectory quantity at one point: its scene's orbit to options.time, read
auto alongTheOrbit(ReadingOf reading) {
  return [reading](const SweepSpec& sp, const Scene& s, const ToolControl& c) {
    const OrbitReading r = reading(sp, s);
    integrateTo(s, sp.options->get("time"), c, r.onStep);
    return r.values();
  };
}

// a trajectory quantity at several points at once, their orbits on SIMD lanes (dynamics/tools/
// TrajectoryLanes.h): each lane's steps are its orbit's alone, bit for bit, so each reading is the one-at-a-
// time one; a failed step sends the points to be integrated alone (where each fails, or not, as alone)
auto alongTheOrbitsOnLanes(ReadingOf reading) {
  return [reading](const SweepSpec& sp, const std::vector<Scene>& scenes,
                   const ToolControl& c) -> std::optional<std::vector<LaneValues>> {
    const auto points = pointsOnLanes(scenes);
    if (!points) return std::nullopt;
    const IntegratorFactory make = [&] { return points->run.makeIntegrator(*points->models.front()); };
    if (!trajectoriesRunOnLanes(points->models, make)) return std::nullopt;
    std::vector<OrbitReading> readings;
    readings.reserve(scenes.size());
    for (const Scene& s : scenes)
      readings.push_back(reading(sp, s));
    const auto onStep = [&](int lane, double t0, const Eigen::VectorXd& x0, double t1,
                            const Eigen::VectorXd& x1) {
      readings[static_cast<std::size_t>(lane)].onStep(t0, x0, t1, x1);
    };
    try {
      if (!integrateOnLanes(points->models, make, points->starts, sp.options->get("time"), c, onStep))
        throw Stopped{};
    } catch (const ComputationError&) {
      return std::nullopt;
    }
    std::vector<LaneValues> values;
    values.reserve(readings.size());
    for (const OrbitReading& r : readings)
      values.push_back({r.values(), nullptr});
    return values;
  };
}

// observable.NAME: an observable at the end of options.time, or its time average
SweepQuantity observableQuantity() {
  SweepQuantity q{
      "observable.", "",
      "observable.NAME: the observable's value at options.time, or its time average over [0, time] "
      "(options.statistic)",
      [](const SweepSpec& sp) { return std::vector<std::string>{sp.quantity->id + sp.quantityName}; },
      alongTheOrbit(observableReading)};
  q.evaluateLanes = alongTheOrbitsOnLanes(observableReading);
  return q;
}

// reversal[.NAME]: whether the spin about the vertical (or an observable) changed sign
SweepQuantity reversalQuantity() {
  SweepQuantity q{
      "reversal",
      "",
      "reversal[.NAME]: whether the spin about the vertical (or the observable NAME) changed sign "
      "within options.time (1/0), when it first did (linear interpolation) and its value at the end",
      [](const SweepSpec&) {
        return std::vector<std::string>{"reversed", "reversal_at", "spin_end"};
      },
      alongTheOrbit(reversalReading),
      /*needsMap=*/false,
      /*cloud=*/false,
      /*optionalName=*/true};
  q.evaluateLanes = alongTheOrbitsOnLanes(reversalReading);
  q.categorical = true; // refined where it reverses or not
  return q;
}

} // namespace

BuiltinTool sweepTool() {
  // its own quantities along the scene's trajectory (observable., reversal) read no tool's result
  return {
      .entry = {.id = "sweep",
                .title = "Chart of regimes (sweep)",
                .description =
                    "a number one of the tools above yields (its sweep quantities), over a grid of one or "
                    "two model parameters, scene keys or initial map points; on threads or MPI ranks "
                    "(docs/sweeps.md)",
                .command = "sweep",
                .commandHelp =
                    "a chart of regimes: a tool's number over a grid of parameters or initial points "
                    "(docs/sweeps.md); runs on threads, or on ranks under mpirun",
                .outputs = {{"<axes>", "the grid point's axis values (the first axis fastest)"},
                            {"<quantity columns>",
                             "the quantity: one column, or several (orbit, reversal, ...)"},
                            {"seconds", "what the point cost"},
                            {"status", "ok, or failed: the reason"}},
                .reference =
                    "Cincotta & Simo, A&AS 147 (2000) 205 (MEGNO charts); Polychronopoulos & Kuck, IEEE TC "
                    "36 (1987) 1425 (guided self-scheduling)",
                .computation = "dynamics/jobs/SweepStore.h (the store, chunks and threads); scenes/Sweep.h "
                               "(evaluateSweepPoint); app/cli/SweepMpi.h (the ranks)",
                .options = &sweepOptionsTable()},
      .quantities = {observableQuantity(), reversalQuantity()}};
}

} // namespace rv
