// ToolRegistry.h -- every tool of nonlinear dynamics rollviz offers (manual §2.3-§2.4), registered by id as
// the integrators are: its title and place in the manual's tool tree, the scene section whose parameter table
// holds its settings (one declaration: default, range, description, scene key, `--set SECTION.ID=VALUE`, GUI
// field and `rollviz describe-tool` line), the CLI command and chart view that run it, and what it outputs.
// The CLI's `list tools` / `describe-tool`, the GUI's tool tree and settings tabs and the scene loader's
// sections iterate it. It holds what is registered: rollviz's own tools register from the scenes layer, each
// with its runner (scenes/BuiltinTools.h), as a module's do (scenes/Module.h).
#pragma once
#include "dynamics/core/ParameterTable.h"

#include <string>
#include <vector>

namespace rv {

/// A settings section of a scene: its key, title and parameter table.
struct ToolSection {
  std::string key;   ///< scene section, e.g. "fixedpoint"
  std::string title; ///< as in the manual's menu
  const ParameterTable* table;
  /// The section's text setting that names one of the model's observables ("section" of the Poincare map,
  /// "function" of the spectrum), chosen in the GUI beside the table; "" when it has none.
  std::string observableKey = {};
  /// Where it comes from: "" for rollviz's own, else the module file that registered it.
  std::string origin = {};
};

/// One field of a tool's output (a CSV column or a JSON field).
struct ToolOutput {
  std::string name;
  std::string description;
  /// A number a sweep can chart as the quantity "TOOL.NAME" (a tool that runs through scenes/ToolRunner.h).
  bool quantity = false;
  /// The quantity's name when it is not "TOOL.NAME" (the short names sweep files used before: "megno").
  std::string quantityName = {};
};

/// A registered tool.
struct ToolEntry {
  std::string id;          ///< e.g. "megno"; the GUI's tree key
  std::string title;       ///< as the manual names it
  std::string parent;      ///< the tool it hangs under in the manual's tree ("" at the top)
  std::string description; ///< one line: what it computes and where it shows
  std::string section;     ///< the scene section of its settings ("" when it has none of its own)
  std::string command;     ///< the `rollviz` subcommand that runs it headless ("" when none)
  std::string commandHelp; ///< what that subcommand writes (its `--help` line)
  std::string chartView;   ///< the `rollviz chart --view` that draws it ("" when none)
  std::vector<ToolOutput> outputs;
  std::string reference;   ///< the paper behind it
  std::string computation; ///< where the computation is defined: "dynamics/tools/Megno.h (MegnoRun)"
  /// Other scene sections whose settings it reads besides its own and its parents' (the bifurcation tree
  /// reads the continuation's); a Python keyword may name their keys plainly.
  std::vector<std::string> alsoSections = {};
  /// Settings kept outside scenes (a sweep file's "options"), or nullptr.
  const ParameterTable* options = nullptr;
  /// Where it comes from: "" for rollviz's own, else the module file that registered it.
  std::string origin = {};
};

/// All tools, in the order of the manual's tree (a parent before its children).
class ToolRegistry {
public:
  /// Every tool: rollviz's own and those the loaded modules added (scenes/ModuleLoader.h).
  static const ToolRegistry& global();
  /// The same registry, for the built-in tools (scenes/BuiltinTools.h) and the module loader to add to.
  static ToolRegistry& mutableGlobal();
  /// Adds an entry (its parent, when it names one, must be registered); throws InputError naming both origins
  /// when the id or the command is taken.
  void add(ToolEntry entry);
  const std::vector<ToolEntry>& entries() const { return entries_; }
  /// The entry with this id, or nullptr.
  const ToolEntry* find(const std::string& id) const;
  /// The entry with this id; throws InputError listing the known ids when there is none.
  const ToolEntry& get(const std::string& id) const;

private:
  std::vector<ToolEntry> entries_;
};

/// Every settings section with a parameter table, in the order of the GUI's tabs.
const std::vector<ToolSection>& toolSections();
/// The section with this scene key, or nullptr.
const ToolSection* findToolSection(const std::string& key);
/// Adds a module's settings section (before any scene is loaded); InputError when the key is taken.
void addToolSection(ToolSection section);

} // namespace rv
