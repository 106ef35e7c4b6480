// ToolCommands.cpp -- `rollviz poincare`, `rollviz lyapunov`, `rollviz megno`, `rollviz spectrum`: the tools
// of dynamics/tools run in the foreground, with progress on a terminal and Ctrl-C keeping what was computed
// (exit 130).
#include "app/cli/Checkpoint.h"
#include "app/cli/Commands.h"
#include "app/cli/Output.h"
#include "app/cli/Progress.h"
#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "dynamics/tools/Megno.h"
#include "render/export/VtkXmlFiles.h"
#include "scenes/SectionTextKeys.h"
#include "scenes/ToolRunner.h"

#include <cmath>
#include <cstdio>
#include <fmt/core.h>
#include <memory>
#include <nlohmann/json.hpp>

namespace rv {

namespace {

void printPeaks(const std::string& function, const SpectrumResult& r) {
  nlohmann::json peaks = nlohmann::json::array();
  for (const auto& p : r.peaks)
    peaks.push_back({{"frequency", p.frequency}, {"amplitude", p.amplitude}});
  fmt::print(
      "{}\n",
      nlohmann::json{{"function", function}, {"peaks", peaks}, {"step", r.step}, {"samples", r.samples}}
          .dump());
}

struct PoincareOptions {
  SceneArgs scene;
  long points = 0;
  std::string output, checkpoint;
};
struct LyapunovOptions {
  SceneArgs scene;
  double time = 0;
  bool json = false;
  std::string checkpoint;
};

struct MegnoOptions {
  SceneArgs scene;
  double time = 0;
  bool json = false;
  std::string checkpoint;
};

struct SpectrumOptions {
  SceneArgs scene;
  std::string function, output;
  long samples = 0;
  bool json = false;
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

Command addLyapunovCommand(CLI::App* cmd) {
  auto o = std::make_shared<LyapunovOptions>();
  addSceneArgs(cmd, o->scene);
  cmd->add_option("--time", o->time, "integration time (default: the scene's lyapunov.time)");
  cmd->add_flag("--json", o->json, "print one JSON object: exponents, sum, time, converged");
  addCheckpointOption(cmd, o->checkpoint);
  return {cmd, [o] {
            const Scene scene = o->scene.load();
            LyapunovSettings s = scene.lyapunov;
            if (o->time < 0 || !std::isfinite(o->time)) throw InputError("--time: must be positive");
            if (o->time > 0) s.maxTime = o->time;
            const RunSpec spec = scene.runSpec();
            const Model& model = *scene.model;
            Checkpoint checkpoint(o->checkpoint, "lyapunov",
                                  scene.document.dump() + fmt::format(" --time {}", s.maxTime));
            LyapunovRun run(
                model, [&] { return spec.makeIntegrator(model); }, scene.initialState, s);
            if (auto saved = checkpoint.load()) run.restore(saved->state);
            Progress progress("lyapunov");
            checkpoint.run([&](const ToolControl& c) { return run.run({}, c); },
                           [&](Snapshot& state) { run.save(state); }, interruptibleControl(progress));
            const LyapunovResult r = run.result();
            if (!r.stopped) checkpoint.finish();
            if (o->json) {
              nlohmann::json j{{"exponents", r.last.exponents},
                               {"sum", r.last.sum()},
                               {"time", r.last.time},
                               {"converged", r.converged},
                               {"stopped", r.stopped}};
              fmt::print("{}\n", j.dump());
            } else {
              for (std::size_t i = 0; i < r.last.exponents.size(); ++i)
                fmt::print("lambda{} = {:.10g}\n", i + 1, r.last.exponents[i]);
              fmt::print("sum = {:.10g}\ntime = {:.10g}\nconverged = {}\n", r.last.sum(), r.last.time,
                         r.converged);
            }
            return r.stopped ? 130 : 0;
          }};
}

Command addMegnoCommand(CLI::App* cmd) {
  auto o = std::make_shared<MegnoOptions>();
  addSceneArgs(cmd, o->scene);
  cmd->add_option("--time", o->time, "integration time (default: the scene's megno.time)");
  cmd->add_flag("--json", o->json, "print one JSON object: megno, megno_rate, y, fli, time");
  addCheckpointOption(cmd, o->checkpoint);
  return {cmd, [o] {
            const Scene scene = o->scene.load();
            MegnoSettings s = scene.megno;
            if (o->time < 0 || !std::isfinite(o->time)) throw InputError("--time: must be positive");
            if (o->time > 0) s.maxTime = o->time;
            const RunSpec spec = scene.runSpec();
            const Model& model = *scene.model;
            Checkpoint checkpoint(o->checkpoint, "megno",
                                  scene.document.dump() + fmt::format(" --time {}", s.maxTime));
            MegnoRun run(
                model, [&] { return spec.makeIntegrator(model); }, scene.initialState, s);
            if (auto saved = checkpoint.load()) run.restore(saved->state);
            Progress progress("megno");
            checkpoint.run([&](const ToolControl& c) { return run.run({}, c); },
                           [&](Snapshot& state) { run.save(state); }, interruptibleControl(progress));
            const MegnoResult& r = run.result();
            if (!r.stopped) checkpoint.finish();
            const MegnoEstimate& e = r.last;
            if (o->json)
              fmt::print("{}\n", nlohmann::json{{"megno", e.megno},
                                                {"megno_rate", e.megnoRate},
                                                {"y", e.y},
                                                {"fli", e.fli},
                                                {"time", e.time},
                                                {"stopped", r.stopped}}
                                     .dump());
            else
              fmt::print(
                  "megno = {:.10g}\nmegno_rate = {:.10g}\ny = {:.10g}\nfli = {:.10g}\ntime = {:.10g}\n",
                  e.megno, e.megnoRate, e.y, e.fli, e.time);
            return r.stopped ? 130 : 0;
          }};
}

Command addSpectrumCommand(CLI::App* cmd) {
  auto o = std::make_shared<SpectrumOptions>();
  addSceneArgs(cmd, o->scene);
  cmd->add_option("--function", o->function, "observable to expand (default: the scene's spectrum.function)");
  cmd->add_option("--samples", o->samples, "number of iterations (integration steps) sampled");
  cmd->add_option("-o,--output", o->output, "CSV file: frequency, amplitude")->check(writesOneOf({".csv"}));
  cmd->add_flag("--json", o->json, "print the peaks as one JSON object");
  return {cmd, [o] {
            const Scene scene = o->scene.load();
            SpectrumSettings s = scene.spectrum;
            if (!o->function.empty()) s.function = o->function;
            if (s.function.empty()) throw InputError("--function: give the observable to expand");
            if (o->samples < 0) throw InputError("--samples: must be positive");
            if (o->samples > 0) s.samples = o->samples;
            Output out(o->output.empty() && o->json ? "/dev/null" : o->output);
            auto integ = scene.startIntegrator();
            Progress progress("spectrum");
            const SpectrumResult r = fourierSpectrum(*scene.model, *integ, s, interruptibleControl(progress));
            if (o->output.empty() && o->json) {
              printPeaks(s.function, r);
              return interrupted() ? 130 : 0;
            }
            std::fprintf(out.get(), "frequency,amplitude\n");
            for (std::size_t k = 0; k < r.frequency.size(); ++k)
              std::fprintf(out.get(), "%.17g,%.17g\n", r.frequency[k], r.amplitude[k]);
            out.commit();
            if (o->json) {
              printPeaks(s.function, r);
            }
            return interrupted() ? 130 : 0;
          }};
}

Command addRegisteredToolCommand(CLI::App* cmd, const ToolEntry& tool) {
  struct Options {
    SceneArgs scene;
    std::string output;
    bool json = false;
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
            const ToolResult r = runTool(tool, scene, interruptibleControl(progress));
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
            else if (!out)
              for (const auto& [name, value] : r.fields.items())
                fmt::print("{} = {}\n", name,
                           value.is_number_float() ? fmt::format("{:.10g}", value.get<double>())
                                                   : value.dump());
            return r.stopped || interrupted() ? 130 : 0;
          }};
}

} // namespace rv
