// ToolCommands.cpp -- `rollviz poincare` and the command of every tool with a runner (scenes/ToolRunner.h:
// spectrum, lyapunov, megno, bifurcation-curve, a module's): the tools of dynamics/tools
// run in the foreground, with progress on a terminal and Ctrl-C keeping what was computed (exit 130).
#include "app/cli/Checkpoint.h"
#include "app/cli/Commands.h"
#include "app/cli/Output.h"
#include "app/cli/Progress.h"
#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "render/export/VtkXmlFiles.h"
#include "scenes/SectionTextKeys.h"
#include "scenes/ToolRunner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fmt/core.h>
#include <memory>
#include <nlohmann/json.hpp>

namespace rv {

namespace {

struct PoincareOptions {
  SceneArgs scene;
  long points = 0;
  std::string output, checkpoint;
};

} // namespace

Command addPoincareCommand(CLI::App* cmd) {
  auto o = std::make_shared<PoincareOptions>();
  addSceneArgs(cmd, o->scene);
  cmd->add_option("--points", o->points, "how many points (default: the scene's poincare.points)");
  cmd->add_option(
         "-o,--output", o->output,
         "CSV file: the map coordinates, t, sheet (default: standard output); a .vtp file is a point "
         "cloud for ParaView with the same columns as point data")
      ->check(writesOneOf({".csv", ".vtp"}));
  addCheckpointOption(cmd, o->checkpoint);
  return {cmd, [o] {
            if (o->points < 0) throw InputError("--points: must be positive");
            const Scene scene = o->scene.load();
            const auto map = scenePoincareMap(scene, o->points);
            if (hasExtension(o->output, ".vtp")) {
              if (!o->checkpoint.empty()) throw InputError("--checkpoint: only with CSV output");
              checkWritable(o->output, "-o");
              NamedColumns table;
              table.names = map->coordinateNames();
              table.names.insert(table.names.end(), {"t", "sheet"});
              const int dims = static_cast<int>(map->coordinateNames().size());
              Progress progress("poincare");
              const ToolControl control = interruptibleControl(progress);
              while (auto p = map->next(control)) {
                std::vector<double> row = p->coordinates;
                row.insert(row.end(), {p->time, static_cast<double>(p->sheet)});
                table.addRow(row);
              }
              writePolyDataVtp(o->output, table, {0, dims > 1 ? 1 : -1, dims > 2 ? 2 : -1}, false);
              return interrupted() ? 130 : 0;
            }
            Checkpoint checkpoint(o->checkpoint, "poincare",
                                  scene.document.dump() + " --points " + std::to_string(o->points));
            Output out(o->output);
            std::string text; // what is written, kept for the checkpoint
            if (auto saved = checkpoint.load()) {
              map->restore(saved->state);
              text = std::move(saved->text);
            } else {
              for (const auto& n : map->coordinateNames())
                text += n + ",";
              text += "t,sheet\n";
            }
            std::fputs(text.c_str(), out.get());
            Progress progress("poincare");
            const ToolControl control = checkpoint.stoppingWhenDue(interruptibleControl(progress));
            for (;;) {
              if (auto p = map->next(control)) {
                const auto start = text.size();
                for (double c : p->coordinates)
                  text += fmt::format("{:.17g},", c);
                text += fmt::format("{:.17g},{}\n", p->time, p->sheet);
                std::fputs(text.c_str() + start, out.get());
                if (!checkpoint.enabled()) text.clear();
                continue;
              }
              // stopped between steps: a due save goes on, Ctrl-C saves and ends, the end of the map ends
              if (interrupted() || checkpoint.due()) {
                Snapshot state;
                map->save(state);
                checkpoint.save(state, text);
                if (!interrupted()) continue;
              }
              break;
            }
            out.commit(); // a failed integration throws before this: no file is left behind
            if (interrupted()) return 130;
            checkpoint.finish();
            return 0;
          }};
}

Command addRegisteredToolCommand(CLI::App* cmd, const ToolEntry& tool) {
  struct Options {
    SceneArgs scene;
    std::string output;
    bool json = false;
    std::string checkpoint;
    std::map<std::string, std::string> settings; // --KEY of the settings table, by key
  };
  auto o = std::make_shared<Options>();
  addSceneArgs(cmd, o->scene);
  const ToolSection* section = findToolSection(tool.section);
  if (section) {
    for (const auto& p : section->table->specs())
      cmd->add_option("--" + p.id, o->settings[p.id],
                      p.description + " (default: the scene's " + tool.section + "." + p.id + ")");
    for (const auto& t : sectionTextKeys(section->key))
      cmd->add_option("--" + t.key, o->settings[t.key],
                      t.description + " (default: the scene's " + tool.section + "." + t.key + ")");
  }
  std::string fields;
  for (const auto& out : tool.outputs)
    fields += (fields.empty() ? "" : ", ") + out.name;
  cmd->add_flag("--json", o->json, "print one JSON object: " + fields);
  cmd->add_option("-o,--output", o->output, "CSV file: the tool's table (.csv)")
      ->check(writesOneOf({".csv"}));
  if (resumable(tool)) addCheckpointOption(cmd, o->checkpoint);
  return {cmd, [o, &tool, section] {
            std::vector<std::string> sets = o->scene.sets;
            for (const auto& [key, value] : o->settings)
              if (!value.empty()) sets.push_back(section->key + "." + key + "=" + value);
            SceneArgs args{o->scene.scene, sets};
            if (!o->output.empty() && !hasExtension(o->output, ".csv"))
              throw InputError("-o " + o->output + ": unsupported format (supported: .csv)");
            const Scene scene = args.load();
            std::unique_ptr<Output> out;
            if (!o->output.empty()) out = std::make_unique<Output>(o->output);
            Progress progress(tool.id);
            const auto run = startTool(tool, scene);
            Checkpoint checkpoint(o->checkpoint, tool.command, scene.document.dump());
            if (auto saved = checkpoint.load()) run->restore(saved->state);
            const ToolControl control = interruptibleControl(progress);
            const bool finished = checkpoint.enabled()
                                      ? checkpoint.run([&](const ToolControl& c) { return run->advance(c); },
                                                       [&](Snapshot& state) { run->save(state); }, control)
                                      : run->advance(control);
            if (finished) checkpoint.finish();
            ToolResult r = run->result();
            r.stopped = !finished;
            checkToolResult(tool, r);
            if (out) {
              const auto& t = r.table;
              for (std::size_t c = 0; c < t.names.size(); ++c)
                std::fprintf(out->get(), "%s%s", c ? "," : "", t.names[c].c_str());
              std::fprintf(out->get(), "\n");
              for (long k = 0; k < t.rows(); ++k)
                for (std::size_t c = 0; c < t.names.size(); ++c)
                  std::fprintf(out->get(), "%.17g%s", t.values[c][static_cast<std::size_t>(k)],
                               c + 1 < t.names.size() ? "," : "\n");
              out->commit();
            }
            if (o->json)
              fmt::print("{}\n", toolResultJson(r).dump());
            else if (!out) { // the declared outputs in their order, then any other field
              std::vector<std::string> names;
              for (const auto& output : tool.outputs)
                if (r.fields.contains(output.name)) names.push_back(output.name);
              for (const auto& [name, value] : r.fields.items())
                if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
              for (const auto& name : names) {
                const auto& value = r.fields[name];
                fmt::print("{} = {}\n", name,
                           value.is_number_float() ? fmt::format("{:.10g}", value.get<double>())
                                                   : value.dump());
              }
            }
            return r.stopped || interrupted() ? 130 : 0;
          }};
}

} // namespace rv
