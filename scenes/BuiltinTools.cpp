// BuiltinTools.cpp -- the runners of rollviz's own tools that run through scenes/ToolRunner.h, registered in
// one place: every front end (CLI command, Python method, GUI Tools tab and chart window, sweep quantities,
// describe-tool) is derived from the entry and its runner, as for a module's tools. Free of VTK (the fuzzers
// link it); their charts are scenes/BuiltinCharts.cpp.
#include "scenes/BuiltinTools.h"

#include "dynamics/core/Diagram.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"
#include "dynamics/tools/FourierSpectrum.h"
#include "dynamics/tools/Lyapunov.h"
#include "dynamics/tools/LyapunovLanes.h"
#include "dynamics/tools/Megno.h"
#include "dynamics/tools/MegnoLanes.h"
#include "dynamics/tools/ReturnMap.h"
#include "scenes/FixedPointJson.h"
#include "scenes/SceneTools.h"
#include "scenes/Sweep.h"
#include "scenes/ToolRunner.h"

#include <cmath>
#include <mutex>

namespace rv {

namespace {

bool startsCurve(const TypeChange& change, CurveKind kind) {
  switch (kind) {
  case CurveKind::Fold:
    return change.kind == TypeChange::Kind::Fold || change.kind == TypeChange::Kind::MultiplierPlusOne;
  case CurveKind::PeriodDoubling:
    return change.kind == TypeChange::Kind::MultiplierMinusOne;
  case CurveKind::NeimarkSacker:
    return change.kind == TypeChange::Kind::NeimarkSacker;
  }
  return false;
}

// The curve of the first fold / period doubling / Neimark-Sacker point of the scene's continuation, in the
// plane of continuation.parameter and bifurcation_curve.second_parameter.
ToolResult runBifurcationCurve(const Scene& scene, const ToolControl& control) {
  const SceneMap s(scene);
  const ContinuationSettings c = s.continuation();
  BifurcationCurveSettings cs = bifurcationCurveSettingsTable().read(scene.tool("bifurcation_curve"));
  cs.search = s.search();
  cs.first = c.parameter;
  cs.eventAccuracy = c.bifurcationAccuracy;
  const auto& doc = scene.document;
  if (doc.contains("bifurcation_curve") && doc["bifurcation_curve"].contains("second_parameter"))
    cs.second = doc["bifurcation_curve"]["second_parameter"].get<std::string>();
  if (cs.second.empty())
    throw InputError("bifurcation_curve.second_parameter: give the curve's second parameter (the first is "
                     "continuation.parameter, " +
                     c.parameter + ")");
  if (cs.second == cs.first)
    throw InputError("bifurcation_curve.second_parameter: " + cs.second +
                     " is the continued parameter already; give another");

  // the start: the first such bifurcation along the continuation
  ToolResult result;
  const auto continuation = s.continuationRun();
  std::string failure;
  try {
    if (!continuation->run(control)) {
      result.stopped = true;
      return result;
    }
  } catch (const ComputationError& e) {
    failure = e.what(); // a family that ends may still have passed the bifurcation
  }
  const TypeChange* found = nullptr;
  for (const auto& t : continuation->changes())
    if (!found && startsCurve(t, cs.kind)) found = &t;
  if (!found) {
    std::string seen;
    for (const auto& t : continuation->changes())
      seen += (seen.empty() ? "" : "; ") + describe(t, c.parameter);
    throw ComputationError(format("bifurcation_curve: the continuation in %s finds no %s point%s%s%s",
                                  c.parameter.c_str(), toString(cs.kind),
                                  seen.empty() ? "" : (" (it finds: " + seen + ")").c_str(),
                                  failure.empty() ? "" : "; it ends: ", failure.c_str()));
  }

  const RunSpec& spec = s.spec();
  const ModelAt2 modelAt = [entry = spec.model, values = spec.modelParameters, first = cs.first,
                            second = cs.second](double p, double q) {
    ParameterValues v = values;
    v.set(first, p, "bifurcation curve in " + first);
    v.set(second, q, "bifurcation curve in " + second);
    return entry->create(v);
  };
  const double q0 = spec.modelParameters[cs.second];
  BifurcationCurveResult r;
  try {
    bifurcationCurve(modelAt, s.integrators(), s.section(), found->parameter, q0, found->at.fixedPoint.point,
                     cs, control, {}, &r);
  } catch (const Stopped&) {
    result.stopped = true;
  }

  const ReturnMap map = s.map();
  result.table.names = {cs.first, cs.second};
  for (const auto& n : map.coordinateNames())
    result.table.names.push_back(n);
  for (const auto& p : r.points) {
    std::vector<double> row{p.first, p.second};
    for (double x : toVector(p.fixedPoint.point))
      row.push_back(x);
    result.table.addRow(row);
  }
  nlohmann::json events = nlohmann::json::array();
  for (const auto& e : r.events)
    events.push_back({{"what", e.what},
                      {cs.first, e.at.first},
                      {cs.second, e.at.second},
                      {"point", toVector(e.at.fixedPoint.point)},
                      {"multipliers", multipliersJson(e.at.fixedPoint.multipliers)}});
  result.fields = {{"kind", toString(cs.kind)},
                   {"parameters", {cs.first, cs.second}},
                   {"start",
                    {{cs.first, found->parameter},
                     {cs.second, q0},
                     {"point", toVector(found->at.fixedPoint.point)},
                     {"found", describe(*found, c.parameter)}}},
                   {"points", r.points.size()},
                   {"events", events},
                   {"end", r.end}};
  return result;
}

// A run of estimates against time (dynamics/tools: MegnoRun, LyapunovRun): its fields are the last
// estimate's, its table the history of estimates (every output period), the table's columns named at the
// first estimate.
template <class Run, class Estimate> class EstimatesRun : public ToolRun {
public:
  template <class Settings>
  EstimatesRun(const Scene& scene, const Settings& settings)
      : model_(scene.model), spec_(scene.runSpec()),
        run_(
            *model_, [this] { return spec_.makeIntegrator(*model_); }, scene.initialState, settings) {}
  bool advance(const ToolControl& control) override {
    return run_.run(
        [this](const Estimate& e) {
          if (history_.rows() && history_.values[0].back() == e.time) return; // the last may come twice
          const std::vector<double> row = this->row(e);
          if (history_.names.empty()) name(row.size());
          history_.addRow(row);
        },
        control);
  }
  void save(Snapshot& state) const override {
    run_.save(state);
    state.put(static_cast<double>(history_.names.size()));
    putTable(state, history_);
  }
  void restore(Snapshot& state) override {
    run_.restore(state);
    const long width = state.getLong();
    history_ = {};
    if (width > 0) name(static_cast<std::size_t>(width));
    getTable(state, history_);
  }

protected:
  /// The history's row of an estimate: t first.
  virtual std::vector<double> row(const Estimate& e) const = 0;
  /// The names of a row of `width` numbers.
  virtual std::vector<std::string> columns(std::size_t width) const = 0;
  const Run& run() const { return run_; }
  const NamedColumns& history() const { return history_; }

private:
  void name(std::size_t width) {
    history_.names = columns(width);
    history_.values.resize(width);
  }
  std::shared_ptr<const Model> model_;
  RunSpec spec_;
  Run run_;
  NamedColumns history_;
};

} // namespace

nlohmann::json megnoFields(const MegnoEstimate& e) {
  return {{"megno", e.megno}, {"megno_rate", e.megnoRate}, {"y", e.y}, {"fli", e.fli}, {"time", e.time}};
}

namespace {

// MEGNO and FLI along the scene's trajectory (dynamics/tools/Megno.h)
class MegnoToolRun final : public EstimatesRun<MegnoRun, MegnoEstimate> {
public:
  explicit MegnoToolRun(const Scene& scene) : EstimatesRun(scene, scene.megno) {}
  ToolResult result() const override {
    const MegnoEstimate& e = run().result().last;
    ToolResult r;
    r.fields = megnoFields(e);
    r.table = history();
    return r;
  }

private:
  std::vector<double> row(const MegnoEstimate& e) const override { return {e.time, e.megno, e.y, e.fli}; }
  std::vector<std::string> columns(std::size_t) const override { return {"t", "megno", "y", "fli"}; }
};

// the lyapunov tool's numbers
nlohmann::json lyapunovFields(const LyapunovResult& l) {
  nlohmann::json fields{{"exponents", l.last.exponents},
                        {"max", l.last.exponents.empty() ? 0.0 : l.last.exponents.front()},
                        {"sum", l.last.sum()},
                        {"time", l.last.time},
                        {"converged", l.converged}};
  if (!l.warning.empty()) fields["warning"] = l.warning; // digits lost all the same, and what helps
  return fields;
}

// the Lyapunov exponents along the scene's trajectory (dynamics/tools/Lyapunov.h)
class LyapunovToolRun final : public EstimatesRun<LyapunovRun, LyapunovEstimate> {
public:
  explicit LyapunovToolRun(const Scene& scene) : EstimatesRun(scene, scene.lyapunov) {}
  ToolResult result() const override {
    ToolResult r;
    r.fields = lyapunovFields(run().result());
    r.table = history();
    return r;
  }

private:
  std::vector<double> row(const LyapunovEstimate& e) const override {
    std::vector<double> v{e.time};
    v.insert(v.end(), e.exponents.begin(), e.exponents.end());
    return v;
  }
  std::vector<std::string> columns(std::size_t width) const override {
    std::vector<std::string> names{"t"};
    for (std::size_t i = 1; i < width; ++i)
      names.push_back(format("L%zu", i));
    return names;
  }
};

// the Fourier spectrum of spectrum.function along the scene's trajectory (dynamics/tools/FourierSpectrum.h)
ToolResult runSpectrum(const Scene& scene, const ToolControl& control) {
  const SpectrumSettings& s = scene.spectrum;
  if (s.function.empty()) throw InputError("the scene has no spectrum.function (the observable to expand)");
  auto integ = scene.startIntegrator();
  const SpectrumResult r = fourierSpectrum(*scene.model, *integ, s, control);
  ToolResult out;
  out.table.names = {"frequency", "amplitude"};
  out.table.values = {r.frequency, r.amplitude};
  nlohmann::json peaks = nlohmann::json::array();
  for (const auto& p : r.peaks)
    peaks.push_back({{"frequency", p.frequency}, {"amplitude", p.amplitude}});
  out.fields = {{"function", s.function}, {"peaks", peaks}, {"step", r.step}, {"samples", r.samples}};
  out.stopped = control.stopRequested();
  return out;
}

// The bifurcation diagram (manual §2.3.10): the model's branches sampled over their parameter, and the
// scene's point on the diagram's plane (dynamics/core/Diagram.h). Its settings (scene section "diagram"):
// which diagram, one branch, the parameter's range and step.
ToolResult runDiagram(const Scene& scene, const ToolControl&) {
  const nlohmann::json section = scene.document.value("diagram", nlohmann::json::object());
  const auto diagrams = scene.model->diagrams();
  const Diagram& d = findDiagram(diagrams, section.value("diagram", std::string()), "diagram.diagram",
                                 scene.model->info().id);
  const std::string only = section.value("branch", std::string());
  const DiagramPoint state = d.place(scene.initialState.data());
  ToolResult r;
  r.table.names = {"parameter", d.axes[0], d.axes[1]};
  r.table.values.resize(3);
  r.text = {{"branch", {}, 0}};
  nlohmann::json branches = nlohmann::json::array(), all = nlohmann::json::array();
  bool found = only.empty();
  for (const auto& b : d.branches) {
    branches.push_back({{"id", b.id},
                        {"description", b.description},
                        {"parameter", b.parameter},
                        {"min", b.min},
                        {"max", b.max},
                        {"step", b.step}});
    if (!only.empty() && b.id != only) continue;
    found = true;
    const double lo = section.value("min", b.min), hi = section.value("max", b.max),
                 step = section.value("step", b.step);
    if (!(step > 0) || !(hi >= lo))
      throw InputError("diagram.min, max, step: need min <= max and step > 0 (branch " + b.id + ")");
    const long n = static_cast<long>(std::floor((hi - lo) / step * (1 + 1e-12)));
    if (n > 10'000'000) throw InputError("diagram.step: more than 1e7 points");
    for (long k = 0; k <= n; ++k) {
      const double s = lo + static_cast<double>(k) * step;
      for (const DiagramPoint& p : b.points(s)) {
        r.table.addRow({s, p[0], p[1]});
        r.text[0].values.push_back(b.id);
      }
    }
  }
  if (!found) {
    std::string known;
    for (const auto& b : d.branches)
      known += " " + b.id;
    throw InputError("diagram.branch " + only + ": no such branch of " + d.id + " (branches:" + known + ")");
  }
  r.table.addRow({0, state[0], state[1]}); // the scene's point, last
  r.text[0].values.emplace_back("state");
  for (const auto& x : diagrams)
    all.push_back(x.id);
  r.fields = {{"diagram", d.id}, {"title", d.title},     {"axes", d.axes},
              {"diagrams", all}, {"branches", branches}, {"state", state}};
  return r;
}

} // namespace

namespace {
// A tool's output `name` from its fields, where it is a number.
std::optional<double> numberIn(const nlohmann::json& fields, const std::string& name) {
  const auto f = fields.find(name);
  if (f == fields.end() || !f->is_number()) return std::nullopt;
  return f->get<double>();
}

// The megno tool's batch evaluation (a LanesEvaluator, scenes/Sweep.h): its output `name` at several points
// at once (dynamics/tools/MegnoLanes.h), on a flow whose model has a lane kernel, integrated by a method
// that steps stacked orbits as alone (Integrator::stepLanesAlone: rk4, everhart at a fixed step) -- where
// each lane is the scalar run bit for bit, so a point's value cannot depend on the points beside it, and a
// sweep stays the same file on any threads, ranks and resumption. (An adaptive step or adams's adaptive
// start would make a point take its neighbours' steps: those run one at a time.)
std::optional<std::vector<LaneValues>>
megnoOnLanesOf(const std::string& name, const std::vector<Scene>& scenes, const ToolControl& control) {
  if (!numberIn(megnoFields(MegnoEstimate{}), name)) return std::nullopt; // not a number: one at a time
  const auto points = pointsOnLanes(scenes);
  if (!points) return std::nullopt;
  const IntegratorFactory make = [&] { return points->run.makeIntegrator(*points->models.front()); };
  if (!megnoRunsOnLanes(points->models, make)) return std::nullopt;
  const auto results = megnoOnLanes(points->models, make, points->starts, scenes.front().megno, control);
  if (results.empty()) throw Stopped{};
  std::vector<LaneValues> values;
  values.reserve(results.size());
  for (const auto& r : results)
    values.push_back({{*numberIn(megnoFields(r.last), name)}, r.failure});
  return values;
}

// The lyapunov tool's batch evaluation: the tangent method's fused rk4 steps of several orbits at once, or
// a method that steps lanes as alone (everhart at a fixed step) on the stacked tangent systems
// (dynamics/tools/LyapunovLanes.h), each lane the scalar run bit for bit.
std::optional<std::vector<LaneValues>>
lyapunovOnLanesOf(const std::string& name, const std::vector<Scene>& scenes, const ToolControl& control) {
  if (!numberIn(lyapunovFields(LyapunovResult{}), name)) return std::nullopt;
  const auto points = pointsOnLanes(scenes);
  if (!points) return std::nullopt;
  const auto results = lyapunovOnLanes(
      points->models, [&] { return points->run.makeIntegrator(*points->models.front()); }, points->starts,
      scenes.front().lyapunov, control);
  if (!results) return std::nullopt;
  if (results->empty()) throw Stopped{};
  std::vector<LaneValues> values;
  values.reserve(results->size());
  for (const auto& r : *results)
    values.push_back({{*numberIn(lyapunovFields(r.result), name)}, r.failure});
  return values;
}
// the largest exponent alone: one tangent vector. Its vector is advanced, projected and normalised
// (Householder's first column) without reading the others, so L1 is the spectrum's to the integrator's
// accuracy (bit for bit with fixed-step rk4; an adaptive method's steps and the intervals see every vector
// that rides along); the stopping rule (successes) and the perturbed method's halving read every exponent,
// so those keep them all.
void narrowLyapunov(const std::string& output, Scene& scene) {
  LyapunovSettings& l = scene.lyapunov;
  if (output == "max" && l.mode == LyapunovSettings::Mode::Tangent && l.successes == 0) l.count = 1;
}
} // namespace

void registerBuiltinTools() {
  static std::once_flag once;
  std::call_once(once, [] {
    addToolRunner("bifurcation_curve", {runBifurcationCurve});
    addToolRunner("spectrum", {runSpectrum});
    addToolRunner("diagram", {runDiagram});
    registerGridTools();
    registerMapTools();
    registerPoincareTools();
    addLanesEvaluator("lyapunov", lyapunovOnLanesOf);
    addToolRunner("lyapunov", {.start = [](const Scene& s) { return std::make_unique<LyapunovToolRun>(s); },
                               .tableName = "history",
                               .narrowTo = narrowLyapunov});
    addLanesEvaluator("megno", megnoOnLanesOf);
    addToolRunner("megno", {.start = [](const Scene& s) { return std::make_unique<MegnoToolRun>(s); },
                            .tableName = "history"});
  });
}

} // namespace rv
