// LyapunovTool.cpp -- the lyapunov tool: the spectrum of Lyapunov exponents against time along the scene's
// trajectory (dynamics/tools/Lyapunov.h), resumable; its batch evaluation on lanes for sweeps
// (dynamics/tools/LyapunovLanes.h) and the narrowing of a sweep of its largest exponent to one vector. Its
// chart is BuiltinCharts.cpp's.
#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"
#include "dynamics/tools/Lyapunov.h"
#include "dynamics/tools/LyapunovLanes.h"
#include "dynamics/tools/ReturnMap.h"
#include "scenes/builtin/BuiltinTool.h"
#include "scenes/builtin/EstimatesRun.h"

#include <algorithm>

namespace rv {

namespace {

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
  explicit LyapunovToolRun(const Scene& scene)
      : EstimatesRun(scene, scene.settings(lyapunovSettingsTable(), "lyapunov")) {}
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
      scenes.front().settings(lyapunovSettingsTable(), "lyapunov"), control);
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
  const LyapunovSettings l = scene.settings(lyapunovSettingsTable(), "lyapunov");
  if (output != "max" || l.mode != LyapunovSettings::Mode::Tangent || l.successes != 0) return;
  auto narrowed = std::make_shared<ParameterValues>(scene.tool("lyapunov"));
  narrowed->set("count", 1);
  scene.tools["lyapunov"] = std::move(narrowed);
}

std::vector<double> lyapunovExponents(const Scene& scene, const ToolControl& control) {
  const ToolResult r = runTool(ToolRegistry::global().get("lyapunov"), scene, control);
  if (r.stopped) throw Stopped{};
  return r.fields.at("exponents").get<std::vector<double>>();
}

// lyapunov.positive: how many exponents exceed the sweep's options.zero
SweepQuantity positiveExponents() {
  SweepQuantity q{
      "lyapunov.positive", "lyapunov",
      "how many exponents exceed options.zero (finite-time estimates of zero exponents decay like "
      "1/t)",
      [](const SweepSpec&) { return std::vector<std::string>{"lyapunov.positive"}; },
      [](const SweepSpec& sp, const Scene& s, const ToolControl& c) {
        const double zero = sp.options->get("zero");
        const auto e = lyapunovExponents(s, c);
        return std::vector<double>{
            static_cast<double>(std::count_if(e.begin(), e.end(), [zero](double v) { return v > zero; }))};
      }};
  q.categorical = true;
  return q;
}

} // namespace

BuiltinTool lyapunovTool() {
  return {.entry = {.id = "lyapunov",
                    .title = "Lyapunov exponents",
                    .parent = "poincare",
                    .description = "the spectrum of exponents against time (a chart window)",
                    .section = "lyapunov",
                    .command = "lyapunov",
                    .commandHelp = "Lyapunov exponents along a scene's trajectory (Benettin)",
                    .chartView = "lyapunov",
                    .outputs =
                        {{"exponents", "the estimates at the end in Gram-Schmidt order (L1 the growth of one "
                                       "vector, L1 + L2 of areas, ...; largest first once converged)"},
                         {"max", "L1 at the end of lyapunov.time: the largest exponent once converged", true},
                         {"sum", "their sum (0 for a measure-preserving flow)"},
                         {"time", "the time reached"},
                         {"converged", "whether the stopping rule held"},
                         {"t", "the history's times (every lyapunov.output_period), beside L1, L2, ..."}},
                    .reference = "Benettin, Galgani, Giorgilli, Strelcyn, Meccanica 15 (1980) 9-30",
                    .computation = "dynamics/tools/Lyapunov.h (LyapunovRun)"},
          .settings = ToolSection{.title = "Lyapunov exponents", .table = &lyapunovSettingsTable().table()},
          .runner = ToolRunner{.start = [](const Scene& s) { return std::make_unique<LyapunovToolRun>(s); },
                               .tableName = "history",
                               .narrowTo = narrowLyapunov},
          .lanes = lyapunovOnLanesOf,
          .quantities = {positiveExponents()}};
}

} // namespace rv
