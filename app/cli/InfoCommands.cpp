// InfoCommands.cpp -- `rollviz list ...`, `rollviz describe PROBLEM`, `rollviz describe-tool ID`, `rollviz
// info`.
#include "app/cli/BuildInfo.h"
#include "app/cli/Commands.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Integrator.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/Gallery.h"
#include "scenes/ModelFile.h"
#include "scenes/ToolRunner.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fmt/core.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <unistd.h>

namespace rv {

namespace {
// "observable.NAME" for the quantities that take a name
std::string quantityName(const SweepQuantity& q) {
  return q.id.back() == '.' ? q.id + "NAME" : q.id;
}
std::string toolOf(const SweepQuantity& q) {
  return q.tool.empty() ? "integrate" : q.tool;
}

void printParameters(const ParameterTable& table) {
  for (const auto& s : table.specs()) {
    std::string range, value = fmt::format("{}", s.defaultValue);
    if (!s.choices.empty()) {
      value = s.choices[static_cast<std::size_t>(s.defaultValue)];
      for (const auto& c : s.choices)
        range += (range.empty() ? "" : "|") + c;
    } else if (s.min > -1e299 || s.max < 1e299)
      range = fmt::format("[{}, {}]", s.min > -1e299 ? fmt::format("{}", s.min) : "-inf",
                          s.max < 1e299 ? fmt::format("{}", s.max) : "inf");
    fmt::print("  {:<20} {:<12} {:<14} {}{}\n", s.id, value, range, s.description,
               s.unit.empty() ? "" : " (" + s.unit + ")");
  }
}
// the sweep quantities a tool yields (all of them for the sweep itself: the tool with the sweep's options)
void printQuantities(const ToolEntry& tool) {
  const bool sweep = tool.options == &sweepOptionsTable();
  bool any = false;
  for (const auto& q : sweepQuantities()) {
    if (!sweep && q.tool != tool.id) continue;
    if (!any) fmt::print("\nsweep quantities (rollviz sweep, \"quantity\"):\n");
    any = true;
    fmt::print("  {:<22} {}{}\n", quantityName(q), q.description, sweep ? " [" + toolOf(q) + "]" : "");
  }
}
} // namespace

Command addListCommand(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("list", "list problems, integrators, tools, quantities, scenes or the gallery");
  auto whatPtr = std::make_shared<std::string>();
  cmd->add_option("what", *whatPtr, "problems | integrators | tools | quantities | scenes | gallery")
      ->required()
      ->check(CLI::IsMember({"problems", "integrators", "tools", "quantities", "scenes", "gallery"}));
  return {cmd, [whatPtr] {
            const std::string& what = *whatPtr;
            if (what == "problems")
              for (const auto& e : ModelRegistry::global().entries()) // scripts read a bare id a line
                fmt::print("{}\n", isatty(STDOUT_FILENO) == 1
                                       ? fmt::format("{:<22} {}", e.info->id, e.info->title)
                                       : e.info->id);
            else if (what == "integrators")
              for (const auto& e : IntegratorRegistry::global().entries())
                fmt::print("{:<10} {}\n", e.id, e.title);
            else if (what == "quantities")
              for (const auto& q : sweepQuantities())
                fmt::print("{:<20} {}: {}\n", quantityName(q), toolOf(q), q.description);
            else if (what == "gallery") // the scene file, its title, then what to watch
              for (const auto& g : galleryScenes())
                fmt::print("{}\n  {}\n  {}\n  picture at t = {:g}\n", g.path, g.title, g.description, g.time);
            else if (what == "tools") {
              // the manual's tree: a child indented under its parent
              const auto& tools = ToolRegistry::global().entries();
              const auto depth = [&](const ToolEntry& e) {
                int d = 0;
                for (const ToolEntry* p = &e; !p->parent.empty(); p = &ToolRegistry::global().get(p->parent))
                  ++d;
                return d;
              };
              for (const auto& e : tools)
                fmt::print("{:<{}}{:<{}} {}: {}\n", "", 2 * depth(e), e.id, 20 - 2 * depth(e), e.title,
                           e.description);
              fmt::print(
                  "\nrollviz describe-tool ID: a tool's settings (scene section, --set SECTION.ID=VALUE) "
                  "and outputs\n");
            } else {
              std::vector<std::string> files;
              for (const auto& f : std::filesystem::directory_iterator(scenesDirectory()))
                if (f.path().extension() == ".json") files.push_back(f.path().string());
              std::sort(files.begin(), files.end());
              for (const auto& f : files)
                fmt::print("{}\n", f);
            }
            return 0;
          }};
}

Command addDescribeToolCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("describe-tool", "a tool's settings, outputs, command, chart and parent");
  auto idPtr = std::make_shared<std::string>();
  cmd->add_option("tool", *idPtr, "tool id (rollviz list tools)")->required();
  return {
      cmd, [idPtr] {
        const ToolEntry& e = ToolRegistry::global().get(*idPtr);
        fmt::print("{}\n  {}\n  {}\n", e.id, e.title, e.description);
        if (!e.reference.empty()) fmt::print("  reference: {}\n", e.reference);
        fmt::print("  in the tool tree under: {}\n", e.parent.empty() ? "(the top)" : e.parent);
        fmt::print("  computation: {}\n", e.computation);
        fmt::print("  command: {}\n", e.command.empty() ? "(none: a chart view)" : "rollviz " + e.command);
        fmt::print("  chart: {}\n", e.chartView.empty() ? "(none)" : "rollviz chart --view " + e.chartView);
        if (const ToolSection* s = findToolSection(e.section)) {
          fmt::print("\nsettings (scene section \"{}\", --set {}.ID=VALUE; id, default, range, meaning):\n",
                     s->key, s->key);
          printParameters(*s->table);
        } else if (!e.section.empty()) {
          fmt::print("\nsettings: the scene section \"{}\" (README: scene files)\n", e.section);
        }
        if (!e.alsoSections.empty()) {
          std::string also;
          for (const auto& a : e.alsoSections)
            also += (also.empty() ? "" : ", ") + a;
          fmt::print("\nalso reads the sections: {} (rollviz describe-tool of their tools)\n", also);
        }
        if (e.options) {
          fmt::print("\noptions (a sweep file's \"options\"; id, default, range, meaning):\n");
          printParameters(*e.options);
        }
        if (const ToolRunner* runner = findToolRunner(e.id); runner && !runner->arguments.empty()) {
          fmt::print("\narguments (the command's --NAME, Python's NAME=; they stand for scene settings):\n");
          for (const auto& a : runner->arguments)
            fmt::print("  {:<22} {}\n", "--" + a.name + (a.flag ? "" : " " + a.valueName), a.description);
        }
        fmt::print("\noutputs:\n");
        for (const auto& out : e.outputs)
          fmt::print("  {:<22} {}\n", out.name, out.description);
        printQuantities(e);
        return 0;
      }};
}

Command addDescribeCommand(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("describe", "parameters, state variables, observables, integrals of a problem");
  auto idPtr = std::make_shared<std::string>();
  cmd->add_option("problem", *idPtr, "problem id (rollviz list problems) or a model file (docs/models.md)")
      ->required();
  return {cmd, [idPtr] {
            const std::string& id = *idPtr;
            const ModelEntry& entry = modelEntryByName(id);
            const ModelInfo& info = *entry.info;
            // a model file is described interpreted: nothing is compiled just to list its contents
            const auto system = equationSystemOf(entry);
            const auto model = system ? system->create(ParameterValues(info.parameters))
                                      : entry.create(ParameterValues(info.parameters));
            fmt::print("{}\n  {}\n", info.id, info.title);
            if (!info.reference.empty()) fmt::print("  reference: {}\n", info.reference);
            fmt::print("\nparameters (id, default, range, meaning):\n");
            printParameters(info.parameters);
            fmt::print("\nstate ({} components; the first {} evolve on their own):\n ",
                       info.stateNames.size(), info.coreDimension);
            for (const auto& n : info.stateNames)
              fmt::print(" {}", n);
            fmt::print("\n\nfirst integrals:");
            if (info.integralNames.empty()) fmt::print(" none");
            for (const auto& n : info.integralNames)
              fmt::print(" {}", n);
            fmt::print("\ninvariant measure: {}\n",
                       model->hasInvariantMeasure() ? "yes (at the default parameters)" : "none known");
            fmt::print("map coordinates for \"initial\": {{\"map\": [...]}}:");
            if (info.mapCoordinates.empty()) fmt::print(" none (give \"state\")");
            for (const auto& n : info.mapCoordinates)
              fmt::print(" {}", n);
            fmt::print("\n\nobservables (for --columns):\n");
            for (const auto& o : model->observables())
              fmt::print("  {:<10} {}\n", o.id, o.description);
            fmt::print("\nintegrators (scene \"integrator\" section, or --set integrator.ID=VALUE):\n");
            for (const auto& e : IntegratorRegistry::global().entries()) {
              fmt::print(" {}: {}\n", e.id, e.title);
              printParameters(*e.parameters);
            }
            return 0;
          }};
}

Command addInfoCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "version, build, libraries and the renderer headless pictures use");
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json, "print one JSON object");
  return {cmd, [json] {
            // a tiny context tells the renderer; HeadlessUnavailable goes up to runCli, which hands over to
            // rollviz-osmesa, and a bad ROLLVIZ_EGL_DEVICE is an InputError (status 2)
            const auto ctx = createHeadlessContext(16, 16);
            const RendererInfo& r = ctx->info();
            const char* eglFailure = std::getenv(kEglUnavailableVariable);
            if (*json) {
              nlohmann::ordered_json j;
              j["modules"] = nlohmann::ordered_json::array();
              for (const auto& f : buildFacts())
                if (f.name == "module")
                  j["modules"].push_back(f.value);
                else if (f.name != "modules")
                  j[f.name] = f.value;
              j["renderer"] = {{"backend", r.backend},  {"context", r.context},   {"devices", r.devices},
                               {"vendor", r.vendor},    {"renderer", r.renderer}, {"version", r.version},
                               {"software", r.software}};
              if (eglFailure) j["renderer"]["egl_unavailable"] = eglFailure;
              fmt::print("{}\n", j.dump());
            } else {
              for (const auto& f : buildFacts())
                fmt::print("{:<13}{}\n", f.name, f.value);
              fmt::print("\nheadless renderer\n");
              for (const auto& f : rendererFacts(r))
                fmt::print("  {:<13}{}\n", f.name, f.value);
              if (eglFailure) fmt::print("  {:<13}unavailable: {}\n", "EGL", eglFailure);
            }
            if (const auto warning = softwareRendererWarning(r); !warning.empty())
              fmt::print(stderr, "rollviz: warning: {}\n", warning);
            return 0;
          }};
}

} // namespace rv
