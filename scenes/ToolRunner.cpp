#include "scenes/ToolRunner.h"

#include "dynamics/core/Errors.h"
#include "scenes/BuiltinTools.h"

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
  if (!runner.run && !runner.start) throw InputError("tool '" + id + "': a runner needs run or start");
  if (!runners().emplace(id, std::move(runner)).second)
    throw InputError("tool '" + id + "' already has a runner");
}

void addToolChart(const std::string& id,
                  std::function<std::unique_ptr<Chart>(const Scene&, const ToolResult&)> chart) {
  const auto it = runners().find(id);
  if (it == runners().end()) throw InputError("tool '" + id + "' has no runner to draw for");
  it->second.chart = std::move(chart);
}

const ToolRunner* findToolRunner(const std::string& id) {
  registerBuiltinTools(); // rollviz's own first, whichever front end asks (once; modules add theirs later)
  const auto it = runners().find(id);
  return it == runners().end() ? nullptr : &it->second;
}

const ToolEntry* runnableToolOfView(const std::string& view) {
  for (const auto& e : ToolRegistry::global().entries())
    if (!e.chartView.empty() && e.chartView == view && findToolRunner(e.id)) return &e;
  return nullptr;
}

namespace {
// a runner that computes at once, as a ToolRun: each advance computes from the start (deterministic: the
// same result), and it cannot be saved
class OneShotRun final : public ToolRun {
public:
  OneShotRun(const ToolRunner& runner, const ToolEntry& tool, Scene scene)
      : runner_(runner), tool_(tool), scene_(std::move(scene)) {}
  bool advance(const ToolControl& control) override {
    result_ = runner_.run(scene_, control);
    return !result_.stopped;
  }
  ToolResult result() const override { return result_; }
  void save(Snapshot&) const override { refuse(); }
  void restore(Snapshot&) override { refuse(); }

private:
  [[noreturn]] void refuse() const {
    throw InputError("--checkpoint: " + tool_.id + " cannot save a run to go on from");
  }
  const ToolRunner& runner_;
  const ToolEntry& tool_;
  Scene scene_;
  ToolResult result_;
};

const ToolRunner& runnerOf(const ToolEntry& tool) {
  const ToolRunner* runner = findToolRunner(tool.id);
  if (!runner) throw InputError("tool '" + tool.id + "' cannot run on a scene by itself");
  return *runner;
}
} // namespace

std::unique_ptr<ToolRun> startTool(const ToolEntry& tool, const Scene& scene) {
  const ToolRunner& runner = runnerOf(tool);
  if (runner.start) return runner.start(scene);
  return std::make_unique<OneShotRun>(runner, tool, scene);
}

bool resumable(const ToolEntry& tool) {
  const ToolRunner* runner = findToolRunner(tool.id);
  return runner && runner->start;
}

void addRow(ToolResult& result, const ToolControl& control, const std::vector<double>& row,
            const std::vector<std::string>& text) {
  result.table.addRow(row);
  for (std::size_t i = 0; i < result.text.size() && i < text.size(); ++i)
    result.text[i].values.push_back(text[i]);
  if (!control.row) return;
  StreamedRow streamed{result.table.names, row, {}, text};
  for (const auto& t : result.text)
    streamed.textNames.push_back(t.name);
  streamed.textNames.resize(text.size());
  control.row(streamed);
}

void addNote(ToolResult& result, const ToolControl& control, std::string note) {
  if (control.note) control.note(note);
  result.notes.push_back(std::move(note));
}

void putTable(Snapshot& state, const NamedColumns& table) {
  state.put(static_cast<double>(table.names.size()));
  for (const auto& column : table.values)
    state.put(Eigen::VectorXd(
        Eigen::Map<const Eigen::VectorXd>(column.data(), static_cast<Eigen::Index>(column.size()))));
}

void getTable(Snapshot& state, NamedColumns& table) {
  if (state.getLong() != static_cast<long>(table.names.size()))
    throw InputError("checkpoint: saved with other columns");
  table.values.assign(table.names.size(), {});
  for (auto& column : table.values) {
    Eigen::VectorXd v;
    state.get(v);
    if (&column != &table.values.front() && v.size() != table.rows())
      throw InputError("checkpoint: saved columns of different lengths");
    column.assign(v.data(), v.data() + v.size());
  }
}

void checkToolResult(const ToolEntry& tool, const ToolResult& r) {
  // an output named in angle brackets ("<map coordinates>") stands for columns named by the scene: not
  // checked
  if (!r.stopped)
    for (const auto& o : tool.outputs)
      if (o.name.rfind('<', 0) != 0 && !r.fields.contains(o.name) &&
          std::find(r.table.names.begin(), r.table.names.end(), o.name) == r.table.names.end() &&
          std::none_of(r.text.begin(), r.text.end(), [&](const TextColumn& t) { return t.name == o.name; }))
        throw ComputationError(fmt::format("tool '{}' did not produce its output '{}'", tool.id, o.name));
}

ToolResult runTool(const ToolEntry& tool, const Scene& scene, const ToolControl& control) {
  const auto run = startTool(tool, scene);
  const bool finished = run->advance(control);
  ToolResult r = run->result();
  r.stopped = !finished;
  checkToolResult(tool, r);
  return r;
}

std::string sweepQuantityId(const ToolEntry& tool, const ToolOutput& output) {
  return output.quantityName.empty() ? tool.id + "." + output.name : output.quantityName;
}

std::vector<SceneOverride> argumentSettings(const ToolRunner& runner, const std::string& name,
                                            const std::string& value) {
  for (const auto& a : runner.arguments)
    if (a.name == name) return a.toSettings(value);
  throw InputError(name + ": not an argument of the tool");
}

nlohmann::json toolResultJson(const ToolResult& result) {
  nlohmann::json j = result.fields;
  if (result.stopped) j["stopped"] = true;
  return j;
}

} // namespace rv
