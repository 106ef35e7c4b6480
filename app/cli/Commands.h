// Commands.h -- each subcommand registers its options on the CLI11 app and runs from there.
#pragma once
#include "scenes/SceneLoader.h"
#include "scenes/SceneTools.h"
#include "scenes/Sweep.h"

#include <CLI/CLI.hpp>
#include <complex>
#include <functional>
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

/// Parses "WxH"; InputError naming --size otherwise.
std::pair<int, int> parseSize(const std::string& text);

/// A subcommand and what to run when it was chosen (returns the exit status).
struct Command {
  CLI::App* app;
  std::function<int()> run;
};
Command addListCommand(CLI::App& app);
Command addDescribeCommand(CLI::App& app);
Command addIntegrateCommand(CLI::App& app);
Command addRenderCommand(CLI::App& app);
Command addVideoCommand(CLI::App& app);
Command addChartCommand(CLI::App& app);
Command addPoincareCommand(CLI::App& app);
Command addLyapunovCommand(CLI::App& app);
Command addMegnoCommand(CLI::App& app);
Command addSpectrumCommand(CLI::App& app);
Command addDescribeToolCommand(CLI::App& app);
Command addFixedPointCommand(CLI::App& app);
Command addContinueCommand(CLI::App& app);
Command addSeparatrixCommand(CLI::App& app);
Command addBifurcationTreeCommand(CLI::App& app);
Command addSurfaceCommand(CLI::App& app);
Command addRamCommand(CLI::App& app);
Command addDiagramCommand(CLI::App& app);
Command addSweepCommand(CLI::App& app);

/// Draws a sweep's chart into a PNG (`rollviz sweep --png`, `rollviz chart --view sweep`).
void writePngChart(const SweepChartData& data, const std::string& path, const std::string& size);

} // namespace rv
