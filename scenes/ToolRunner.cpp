#include "scenes/ToolRunner.h"

#include "dynamics/core/Errors.h"

#include <algorithm>
#include <fmt/core.h>
#include <map>

namespace rv {

namespace {
std::map<std::string, ToolRunner>& runners() {
  static std::map<std::string, ToolRunner> r;
  return r;
}
} // namespace

void addToolRunner(const std::string& id, ToolRunner runner) {
  (void)ToolRegistry::global().get(id); // InputError for an unknown tool
  if (!runner.run) throw InputError("tool '" + id + "': a runner needs a run function");
  if (!runners().emplace(id, std::move(runner)).second)
    throw InputError("tool '" + id + "' already has a runner");
}

const ToolRunner* findToolRunner(const std::string& id) {
  const auto it = runners().find(id);
  return it == runners().end() ? nullptr : &it->second;
}

const ToolEntry* runnableToolOfView(const std::string& view) {
  for (const auto& e : ToolRegistry::global().entries())
    if (!e.chartView.empty() && e.chartView == view && findToolRunner(e.id)) return &e;
  return nullptr;
}

ToolResult runTool(const ToolEntry& tool, const Scene& scene, const ToolControl& control) {
  const ToolRunner* runner = findToolRunner(tool.id);
  if (!runner) throw InputError("tool '" + tool.id + "' cannot run on a scene by itself");
  ToolResult r = runner->run(scene, control);
  // an output named in angle brackets ("<map coordinates>") stands for columns named by the scene: not
  // checked
  if (!r.stopped)
    for (const auto& o : tool.outputs)
      if (o.name.rfind('<', 0) != 0 && !r.fields.contains(o.name) &&
          std::find(r.table.names.begin(), r.table.names.end(), o.name) == r.table.names.end())
        throw ComputationError(fmt::format("tool '{}' did not produce its output '{}'", tool.id, o.name));
  return r;
}

nlohmann::json toolResultJson(const ToolResult& result) {
  nlohmann::json j = result.fields;
  if (result.stopped) j["stopped"] = true;
  return j;
}

} // namespace rv
