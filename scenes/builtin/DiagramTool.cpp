// DiagramTool.cpp -- the diagram tool (topological analysis, manual §2.3.10): a bifurcation diagram of the
// model on the plane of first integrals (dynamics/core/Diagram.h), with the scene's point. Its chart is
// BuiltinCharts.cpp's.
#include "dynamics/core/Diagram.h"
#include "dynamics/core/Errors.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/builtin/BuiltinTool.h"

#include <cmath>

namespace rv {

namespace {

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

BuiltinTool diagramTool() {
  return {
      .entry =
          {.id = "diagram",
           .title = "Topological analysis",
           .description = "the bifurcation diagram on the plane of first integrals",
           .section = "diagram",
           .command = "diagram",
           .commandHelp = "a bifurcation diagram on the plane of first integrals, with the scene's point",
           .chartView = "bifurcation",
           .outputs = {{"branch", "CSV: the branch's id (the last row, \"state\", is the scene's point)"},
                       {"parameter", "CSV: the branch's parameter"},
                       {"<the diagram's axes>", "CSV: the point on the diagram's plane"},
                       {"diagram", "the diagram's id"},
                       {"title", "what the diagram shows"},
                       {"axes", "the names of its two axes (first integrals)"},
                       {"diagrams", "the ids of every diagram of the problem"},
                       {"branches", "each branch: id, description, parameter and its default min, max, step"},
                       {"state", "the scene's point on the diagram"}},
           .reference = "manual §2.3.10",
           .computation = "dynamics/core/Diagram.h (each model's diagrams(), e.g. "
                          "dynamics/models/ChaplyginDiagram.h); runner scenes/builtin/DiagramTool.cpp"},
      .settings = ToolSection{.title = "Topological analysis", .table = &diagramTable()},
      .runner = ToolRunner{.run = runDiagram}};
}

} // namespace rv
