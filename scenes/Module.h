// Module.h -- the one entry point of a rollviz module (docs/modules.md): a shared library, built against the
// installed SDK with rollviz_add_module() (find_package(rollviz)), that registers models, tools and
// integrators. Write
//
//   #include "scenes/Module.h"
//   ROLLVIZ_MODULE(registrar) {
//     registrar.addModel({&Rossler::staticInfo(), [](const rv::ParameterValues& p) { ... }});
//     registrar.addIntegrator(Dopri5::entry());
//     registrar.addTool(returnTimesEntry(), returnTimesRunner(), &returnTimesTable());
//   }
//
// rollviz loads it at start (scenes/ModuleLoader.h) and every front end picks up what it added. What a module
// registers is checked as a whole before any of it is added: an id that is taken refuses the module.
#pragma once
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Integrator.h"
#include "dynamics/tools/ToolRegistry.h"
#include "rollviz/Version.h"
#include "scenes/ToolRunner.h"

#include <string>
#include <vector>

namespace rv {

/// What a module registers, collected by its entry point and added by the loader once all of it checks out.
class ModuleRegistrar {
public:
  /// A model (dynamics/core/ModelRegistry.h): its constant description and a factory.
  void addModel(ModelEntry entry) { models.push_back(std::move(entry)); }
  /// An integration method (dynamics/integrators/Integrator.h).
  void addIntegrator(IntegratorEntry entry) { integrators.push_back(std::move(entry)); }
  /// A tool: its entry (id, title, parent, description, outputs with the sweep quantities marked, the CLI
  /// command, the chart view), how it runs (scenes/ToolRunner.h), and the parameter table of its settings,
  /// which become the scene section `entry.section` (or the tool's id when that is empty): `--set
  /// SECTION.KEY=V`, the CLI flags `--KEY`, Python keywords, GUI fields.
  void addTool(ToolEntry entry, ToolRunner runner, const ParameterTable* settings = nullptr) {
    if (settings && entry.section.empty()) entry.section = entry.id;
    tools.push_back({std::move(entry), std::move(runner), settings});
  }

  struct Tool {
    ToolEntry entry;
    ToolRunner runner;
    const ParameterTable* settings;
  };
  std::vector<ModelEntry> models;
  std::vector<IntegratorEntry> integrators;
  std::vector<Tool> tools;
};

} // namespace rv

/// The symbols the loader looks for: the stamp of the rollviz and compiler the module was built with, and
/// the function that registers its parts.
#define ROLLVIZ_MODULE_STAMP_SYMBOL "rollviz_module_stamp"
#define ROLLVIZ_MODULE_REGISTER_SYMBOL "rollviz_module_register"

/// Defines a module's entry point; the body fills `registrar` (an rv::ModuleRegistrar&).
// the argument names a parameter, so it cannot be parenthesised
// NOLINTBEGIN(bugprone-macro-parentheses)
#define ROLLVIZ_MODULE(registrar)                                                                            \
  extern "C" __attribute__((visibility("default"))) const char* rollviz_module_stamp() {                     \
    return ROLLVIZ_ABI_STAMP;                                                                                \
  }                                                                                                          \
  extern "C" __attribute__((visibility("default"))) void rollviz_module_register(                            \
      ::rv::ModuleRegistrar& registrar)
// NOLINTEND(bugprone-macro-parentheses)
