// Commands.h -- each subcommand registers its options on the CLI11 app and runs from there.
#pragma once
#include "render/charts/ChartStyle.h"
#include "scenes/SceneLoader.h"
#include "scenes/SceneTools.h"
#include "scenes/Sweep.h"

#include <CLI/CLI.hpp>
#include <complex>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace rv {

/// Options every scene command takes: the scene file and `--set ID=VALUE`.
struct SceneArgs {
  std::string scene;
  std::vector<std::string> sets;
  /// Loads the scene with the overrides (InputError on any problem).
  Scene load() const;
};

/// Adds the SCENE positional and --set to a subcommand.
void addSceneArgs(CLI::App* cmd, SceneArgs& args);

/// A check of an output option: the file's extension (any case) is one of `extensions` (".csv", ".png",
/// ...), else the command line is refused (exit 2) naming the option and listing the supported ones -- an
/// output's format follows its extension, and nothing is written under a name of another format.
CLI::Validator writesOneOf(const std::vector<std::string>& extensions);

/// Parses "WxH"; InputError naming --size otherwise.
std::pair<int, int> parseSize(const std::string& text);

/// A subcommand and what to run when it was chosen (returns the exit status).
struct Command {
  CLI::App* app;
  std::function<int()> run;
};
Command addListCommand(CLI::App& app);
Command addDescribeCommand(CLI::App& app);
Command addDescribeToolCommand(CLI::App& app);
/// `rollviz info`: version, build, libraries and the headless renderer (warns when it is software).
Command addInfoCommand(CLI::App& app);
/// Set by `rollviz` in the environment of the `rollviz-osmesa` it hands a command to: why EGL failed.
inline constexpr const char* kEglUnavailableVariable = "ROLLVIZ_EGL_UNAVAILABLE";
Command addIntegrateCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);
Command addVideoCommand(CLI::App& app);
Command addPageCommand(CLI::App& app);
Command addChartCommand(CLI::App& app);

/// `rollviz sweep`: a tool over a grid of scenes (scenes/Sweep.h), named and described by the registry's
/// entry.
Command addSweepCommand(CLI::App& app);
/// The subcommand of a tool that runs through scenes/ToolRunner.h (a module's tool): SCENE, --set, a flag
/// per setting of its section (--KEY), --json (its fields), -o (its table as CSV).
Command addRegisteredToolCommand(CLI::App* cmd, const ToolEntry& tool);

/// Draws a sweep's chart into a PNG, SVG or PDF by the extension (`rollviz sweep --png`, `rollviz chart
/// --view sweep`); `what` names the option in messages.
void writeChartFigure(const SweepChartData& data, const std::string& path, std::pair<int, int> pixels,
                      const std::string& what, const ChartStyle& style = {});

} // namespace rv
