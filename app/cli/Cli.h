// Cli.h -- the `rollviz` command line (design.md "Command line"): the commands are registered in Cli.cpp and
// the tools' own in the tool registry (`rollviz --help` lists them all).
// Exit status: 0 done, 1 a computation that did not succeed, 2 bad input; 130 after Ctrl-C (work kept).
#pragma once
#include <functional>
#include <string>

namespace rv {

/// What `rollviz gui` was asked for.
struct GuiOptions {
  std::string scene;      ///< scene file; empty: the last scene, else the default one
  std::string screenshot; ///< when set: save a screenshot of the window there before quitting
  double quitAfter = 0;   ///< when > 0: quit after this many seconds (smoke tests, scripted demos)
  /// When set: the window's state (the summary line printed at a scripted quit) is written there every 0.2 s,
  /// and creating STATUS.quit makes it take the screenshot, print the summary and quit -- so a script waits
  /// on what the window did, not on the clock.
  std::string statusFile;
};

/// Starts the GUI; null where there is no GUI.
using GuiLauncher = std::function<int(int argc, char** argv, const GuiOptions& options)>;

/// Runs the command line; returns the exit status.
int runCli(int argc, char** argv, const GuiLauncher& gui);

} // namespace rv
