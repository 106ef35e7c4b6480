// BuiltinTools.cpp -- rollviz's own tools, registered as a module's are: every front end (CLI command,
// Python method, GUI Tools tab and chart window, sweep quantities, describe-tool) is derived from each one's
// entry, settings table and runner. A new tool is a file that gives its BuiltinTool (BuiltinTool.h) and one
// line here (docs/development.md). Free of VTK (the fuzzers link it); the charts are BuiltinCharts.cpp.
#include "scenes/BuiltinTools.h"

#include "scenes/builtin/BuiltinTool.h"

#include <mutex>

namespace rv {

namespace {

// what ModuleLoader does with a module's tool: its entry, its section, its runner, lanes and quantities
void add(BuiltinTool tool) {
  const std::string id = tool.entry.id;
  if (tool.settings) {
    tool.settings->key = tool.entry.section;
    addToolSection(std::move(*tool.settings));
  }
  ToolRegistry::mutableGlobal().add(std::move(tool.entry));
  if (tool.runner) addToolRunner(id, std::move(*tool.runner));
  if (tool.lanes) addLanesEvaluator(id, std::move(tool.lanes));
  for (auto& q : tool.quantities)
    addSweepQuantity(std::move(q));
}

} // namespace

void registerBuiltinTools() {
  static std::once_flag once;
  std::call_once(once, [] {
    // in the order of the manual's tree, a parent before its children (`rollviz list tools`, the GUI's tree
    // and settings tabs)
    add(poincareTool());
    add(spectrumTool());
    add(lyapunovTool());
    add(megnoTool());
    add(map3dTool());
    add(plotTool());
    add(fixedPointTool());
    add(continuationTool());
    add(multipliersTool());
    add(separatrixTool());
    add(bifurcationTreeTool());
    add(bifurcationCurveTool());
    add(surfaceTool());
    add(ramTool());
    add(diagramTool());
    add(sweepTool());
  });
}

} // namespace rv
