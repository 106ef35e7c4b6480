// ToolCommands.cpp -- the command of every tool with a runner (scenes/ToolRunner.h: rollviz's own and a
// module's), derived from its registry entry: the tools of dynamics/tools run in the foreground, with
// progress on a terminal and Ctrl-C keeping what was computed (exit 130).
#include "app/cli/Checkpoint.h"
#include "app/cli/Commands.h"
#include "app/cli/Output.h"
#include "app/cli/Progress.h"
#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "dynamics/io/FileNames.h"
#include "render/export/VtkXmlFiles.h"
#include "scenes/SectionTextKeys.h"
#include "scenes/ToolRunner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fmt/core.h>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

namespace rv {

namespace {

// A grid result as image data: the coordinate columns are its axes, the others its arrays.
void writeGridVti(const std::string& path, const ToolResult& r) {
  const ToolGrid& g = r.grid;
  ImageGrid image;
  image.size = g.size;
  image.origin = g.origin;
  image.spacing = g.spacing;
  image.axisNames.assign(r.table.names.begin(), r.table.names.begin() + g.coordinates);
  image.arrays.names.assign(r.table.names.begin() + g.coordinates, r.table.names.end());
  image.arrays.values.assign(r.table.values.begin() + g.coordinates, r.table.values.end());
  writeImageVti(path, image);
}

// the table's numbers round-trip exact, its text columns in their places
void writeTableCsv(FILE* f, const ToolResult& r) {
  const NamedColumns& t = r.table;
  // the columns in order: a text column's index is -1 - its place in r.text
  std::vector<long> order;
  for (std::size_t c = 0; c <= t.names.size(); ++c) {
    for (std::size_t x = 0; x < r.text.size(); ++x)
      if (std::min(r.text[x].at, t.names.size()) == c) order.push_back(-1 - static_cast<long>(x));
    if (c < t.names.size()) order.push_back(static_cast<long>(c));
  }
  for (std::size_t i = 0; i < order.size(); ++i) {
    const long c = order[i];
    std::fprintf(
        f, "%s%s", i ? "," : "",
        (c < 0 ? r.text[static_cast<std::size_t>(-1 - c)].name : t.names[static_cast<std::size_t>(c)])
            .c_str());
  }
  std::fprintf(f, "\n");
  for (long k = 0; k < t.rows(); ++k) {
    const auto row = static_cast<std::size_t>(k);
    for (std::size_t i = 0; i < order.size(); ++i) {
      const long c = order[i];
      if (c < 0)
        std::fprintf(f, "%s%s", i ? "," : "",
                     r.text[static_cast<std::size_t>(-1 - c)].values.at(row).c_str());
      else
        std::fprintf(f, "%s%.17g", i ? "," : "", t.values[static_cast<std::size_t>(c)][row]);
    }
    std::fprintf(f, "\n");
  }
}

} // namespace

namespace {

// A bad value met after the flags became scene settings names the flag it came from ("--param Q: ..."):
// `given` maps each scene key set by a flag to the flag as typed.
[[noreturn]] void rethrowNamingTheFlag(const InputError& e, const std::map<std::string, std::string>& given) {
  const std::string message = e.what();
  for (const auto& [key, flag] : given)
    if (message.find(key) != std::string::npos &&
        message.find(flag.substr(0, flag.find(' '))) == std::string::npos)
      throw InputError(flag + ": " + message);
  throw e;
}

// the declared outputs in their order, then any other field, as "name = value"
void printFields(const ToolEntry& tool, const ToolResult& r) {
  std::vector<std::string> names;
  for (const auto& output : tool.outputs)
    if (r.fields.contains(output.name)) names.push_back(output.name);
  for (const auto& [name, value] : r.fields.items())
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  for (const auto& name : names) {
    const auto& value = r.fields[name];
    fmt::print("{} = {}\n", name,
               value.is_number_float() ? fmt::format("{:.10g}", value.get<double>()) : value.dump());
  }
}

} // namespace

Command addRegisteredToolCommand(CLI::App* cmd, const ToolEntry& tool) {
  struct Options {
    SceneArgs scene;
    std::string output;
    bool json = false;
    std::string checkpoint;
    std::map<std::string, std::string> settings;  // --KEY of the settings table, by key
    std::map<std::string, std::string> arguments; // --NAME of the runner's arguments, by name
    std::map<std::string, bool> flags;            // --NAME of the runner's arguments that take no value
  };
  auto o = std::make_shared<Options>();
  const ToolRunner& runner = *findToolRunner(tool.id);
  addSceneArgs(cmd, o->scene);
  const auto isArgument = [&runner](const std::string& name) {
    return std::any_of(runner.arguments.begin(), runner.arguments.end(),
                       [&](const ToolArgument& a) { return a.name == name; });
  };
  const ToolSection* section = findToolSection(tool.section);
  if (section) {
    for (const auto& p : section->table->specs())
      if (!isArgument(p.id))
        cmd->add_option("--" + p.id, o->settings[p.id],
                        p.description + " (default: the scene's " + tool.section + "." + p.id + ")");
    for (const auto& t : sectionTextKeys(section->key))
      if (!isArgument(t.key))
        cmd->add_option("--" + t.key, o->settings[t.key],
                        t.description + (t.description.find("(default:") != std::string::npos
                                             ? " (scene key " + tool.section + "." + t.key + ")"
                                             : " (default: the scene's " + tool.section + "." + t.key + ")"));
  }
  for (const auto& a : runner.arguments)
    if (a.flag)
      cmd->add_flag("--" + a.name, o->flags[a.name], a.description);
    else
      cmd->add_option("--" + a.name, o->arguments[a.name], a.description)->type_name(a.valueName);
  // the outputs mix the result's fields with its table's columns, which the object does not hold
  cmd->add_flag("--json", o->json,
                "print the result's fields as one JSON object (of the outputs `rollviz describe-tool " +
                    tool.id + "` lists, those that are not the table's columns); -o FILE writes the table");
  std::vector<std::string> formats{".csv"};
  std::string what =
      runner.tableIsResult ? "CSV file (default: standard output)" : "CSV file: the tool's table";
  if (runner.grid) formats.emplace_back(".vti"), what += "; a .vti file is image data for ParaView";
  if (runner.cloud)
    formats.emplace_back(".vtp"),
        what += "; a .vtp file is a point cloud for ParaView, the columns point data";
  cmd->add_option("-o,--output", o->output, what)->check(writesOneOf(formats));
  if (resumable(tool)) addCheckpointOption(cmd, o->checkpoint);
  return {cmd, [o, &tool, &runner, section] {
            std::vector<std::string> sets = o->scene.sets;
            std::map<std::string, std::string> given; // scene key -> the flag that set it
            for (const auto& [key, value] : o->settings)
              if (!value.empty()) {
                sets.push_back(section->key + "." + key + "=" + value);
                given.emplace(section->key + "." + key, "--" + key + " " + value);
              }
            const auto apply = [&](const std::string& name, const std::string& value,
                                   const std::string& typed) {
              try {
                for (const auto& s : argumentSettings(runner, name, value)) {
                  sets.push_back(s.key + "=" + s.value);
                  given.emplace(s.key, typed);
                }
              } catch (const InputError& e) {
                throw InputError(typed + ": " + e.what());
              }
            };
            for (const auto& [name, value] : o->arguments)
              if (!value.empty()) apply(name, value, "--" + name + " " + value);
            for (const auto& [name, on] : o->flags)
              if (on) apply(name, "", "--" + name);
            SceneArgs args{o->scene.scene, sets};
            const bool vti = hasExtension(o->output, ".vti"), vtp = hasExtension(o->output, ".vtp");
            // a table that is the result goes to standard output without -o (not beside --json's object)
            const bool tableOut = !o->output.empty() || (runner.tableIsResult && !o->json);
            std::optional<Scene> loaded;
            std::unique_ptr<ToolRun> run;
            try {
              loaded.emplace(args.load());
              run = startTool(tool, *loaded);
            } catch (const InputError& e) {
              rethrowNamingTheFlag(e, given);
            }
            const Scene& scene = *loaded;
            std::unique_ptr<Output> out;
            if (vti || vtp)
              checkWritable(o->output, "-o");
            else if (tableOut)
              out = std::make_unique<Output>(o->output);
            Progress progress(tool.id);
            // what the result depends on: the scene, less the settings a resumed run may change
            nlohmann::json key = scene.document;
            for (const auto& k : runner.resultIndependent)
              if (key.contains(tool.section) && key[tool.section].is_object()) key[tool.section].erase(k);
            Checkpoint checkpoint(o->checkpoint, tool.command, key.dump());
            if (auto saved = checkpoint.load()) run->restore(saved->state);
            const ToolControl control = interruptibleControl(progress);
            bool finished = false;
            try {
              finished = checkpoint.enabled()
                             ? checkpoint.run([&](const ToolControl& c) { return run->advance(c); },
                                              [&](Snapshot& state) { run->save(state); }, control)
                             : run->advance(control);
            } catch (const InputError& e) {
              rethrowNamingTheFlag(e, given);
            }
            progress.clear(); // what follows may print on the same terminal
            ToolResult r = run->result();
            r.stopped = !finished;
            if (r.failure.empty()) checkToolResult(tool, r);
            if (vti) {
              if (r.grid.dimensions == 0)
                throw ComputationError(tool.id + ": its result is no grid for .vti");
              writeGridVti(o->output, r);
            } else if (vtp) {
              if (r.cloud == 0) throw ComputationError(tool.id + ": its result is no point cloud for .vtp");
              writePolyDataVtp(o->output, r.table, {0, r.cloud > 1 ? 1 : -1, r.cloud > 2 ? 2 : -1}, false);
            } else if (out) {
              writeTableCsv(out->get(), r);
              out->commit();
            }
            if (finished) checkpoint.finish(); // after the output is written: a failed write can resume
            if (o->json) {
              fmt::print("{}\n", toolResultJson(r).dump());
            } else {
              // what it said on the way: beside a table on standard output, on standard error
              FILE* notes = out && o->output.empty() ? stderr : stdout;
              for (const auto& line : r.notes)
                fmt::print(notes, "{}\n", line);
              if (!out && !vti && !vtp) {
                if (runner.describe)
                  fmt::print("{}", runner.describe(r));
                else
                  printFields(tool, r);
              }
            }
            if (!r.failure.empty()) { // the result so far is written; the computation ended early
              fmt::print(stderr, "rollviz: failed: {}\n", r.failure);
              return 1;
            }
            return r.stopped || interrupted() ? 130 : 0;
          }};
}

} // namespace rv
