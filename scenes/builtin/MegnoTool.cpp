// MegnoTool.cpp -- the megno tool: the chaos indicators MEGNO and FLI against time along the scene's
// trajectory (dynamics/tools/Megno.h), resumable, and its batch evaluation on lanes for sweeps
// (dynamics/tools/MegnoLanes.h). Its chart is BuiltinCharts.cpp's.
#include "dynamics/tools/Megno.h"
#include "dynamics/tools/MegnoLanes.h"
#include "dynamics/tools/ReturnMap.h"
#include "scenes/builtin/BuiltinTool.h"
#include "scenes/builtin/EstimatesRun.h"

namespace rv {

namespace {

// the megno tool's named outputs of an estimate: its result's fields, and what a sweep batching MEGNO on
// lanes reads (one definition)
nlohmann::json megnoFields(const MegnoEstimate& e) {
  return {{"megno", e.megno}, {"megno_rate", e.megnoRate}, {"y", e.y}, {"fli", e.fli}, {"time", e.time}};
}

// MEGNO and FLI along the scene's trajectory (dynamics/tools/Megno.h)
class MegnoToolRun final : public EstimatesRun<MegnoRun, MegnoEstimate> {
public:
  explicit MegnoToolRun(const Scene& scene)
      : EstimatesRun(scene, scene.settings(megnoSettingsTable(), "megno")) {}
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
  const auto results = megnoOnLanes(points->models, make, points->starts,
                                    scenes.front().settings(megnoSettingsTable(), "megno"), control);
  if (results.empty()) throw Stopped{};
  std::vector<LaneValues> values;
  values.reserve(results.size());
  for (const auto& r : results)
    values.push_back({{*numberIn(megnoFields(r.last), name)}, r.failure});
  return values;
}

} // namespace

BuiltinTool megnoTool() {
  return {
      .entry =
          {.id = "megno",
           .title = "MEGNO and FLI",
           .parent = "poincare",
           .description =
               "the chaos indicators against time: <Y> -> 2 on tori, -> 0 on stable periodic orbits of "
               "maps, ~ lambda t / 2 on chaotic orbits (a chart window)",
           .section = "megno",
           .command = "megno",
           .commandHelp = "the chaos indicators MEGNO and FLI along a scene's trajectory",
           .chartView = "megno",
           .outputs =
               {{"megno", "<Y>, the time-averaged MEGNO at the end of megno.time (2: torus, growing: chaos)",
                 true, "megno"},
                {"megno_rate", "<Y> / (t/2): tends to the largest Lyapunov exponent on chaotic orbits", true},
                {"y", "Y, the instantaneous MEGNO at the end"},
                {"fli", "ln |w(t)|, the fast Lyapunov indicator at the end of megno.time", true, "fli"},
                {"time", "the time reached"},
                {"t", "the history's times (every megno.output_period), beside megno, y and fli"}},
           .reference = "Cincotta & Simo, A&AS 147 (2000) 205; Froeschle, Lega & Gonczi, CeMDA 67 (1997) 41",
           .computation = "dynamics/tools/Megno.h (MegnoRun)"},
      .settings = ToolSection{.title = "MEGNO and FLI", .table = &megnoSettingsTable().table()},
      .runner = ToolRunner{.start = [](const Scene& s) { return std::make_unique<MegnoToolRun>(s); },
                           .tableName = "history"},
      .lanes = megnoOnLanesOf};
}

} // namespace rv
