// ToolRunner.h -- the runnable part of a registered tool (dynamics/tools/ToolRegistry.h), in the layer that
// knows scenes: what the tool computes on a scene with its settings (the scene's section of the tool), under
// a stop/progress control, producing the outputs its entry declares, and how a result is drawn. Every front
// end derives its part from it: the CLI subcommand (the settings table's flags and the common ones), the
// Python method, the chart view (GUI chart window, `rollviz chart`), the sweep quantities (the outputs
// declared `quantity`), `describe-tool`. Modules add tools this way (scenes/Module.h).
#pragma once
#include "dynamics/tools/ToolControl.h"
#include "dynamics/tools/ToolRegistry.h"
#include "render/charts/Chart.h"
#include "render/export/VtkXmlFiles.h"
#include "scenes/Scene.h"

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace rv {

/// What one run of a tool produced.
struct ToolResult {
  /// The named outputs (numbers, strings, arrays): `--json`, the Python result's keys, sweep quantities.
  nlohmann::json fields = nlohmann::json::object();
  /// The rows it computed (the CSV of `-o`, the Python result's arrays); may have no columns.
  NamedColumns table;
  /// Stopped on request: the fields and rows hold what was computed until then.
  bool stopped = false;
};

/// How a tool runs on a scene and how its result is drawn.
struct ToolRunner {
  /// Runs the tool on the scene (its settings: scene.tool(entry.section)); polls control.stopRequested and
  /// reports control.progress. Throws InputError for settings it cannot use, ComputationError when the
  /// computation fails, and returns with `stopped` set when stopped.
  std::function<ToolResult(const Scene&, const ToolControl&)> run;
  /// Draws a result; empty: the table's columns against its first, titled with the quantities
  /// (SceneCharts.cpp draws both; this file stays free of VTK code, so the fuzzers link it).
  std::function<std::unique_ptr<Chart>(const Scene&, const ToolResult&)> chart = {};
};

/// Binds a runner to the registered tool `id` (its chart view is the entry's chartView); InputError when the
/// tool is not registered or already has one.
void addToolRunner(const std::string& id, ToolRunner runner);
/// The runner of tool `id`, or nullptr (a tool whose front ends are written by hand).
const ToolRunner* findToolRunner(const std::string& id);
/// The registered tool whose chart view is `view` and that has a runner, or nullptr.
const ToolEntry* runnableToolOfView(const std::string& view);

/// Runs tool `id` on the scene and checks that the result holds every field its entry declares (a runner
/// that forgets one is a ComputationError naming it, not a silent gap in some front end).
ToolResult runTool(const ToolEntry& tool, const Scene& scene, const ToolControl& control);

/// The result as one JSON object: the fields, and "stopped" when the run was stopped.
nlohmann::json toolResultJson(const ToolResult& result);

} // namespace rv
