// GuiMain.h -- starts the Qt application and the main window (`rollviz` or `rollviz gui [SCENE]`).
#pragma once
#include "app/cli/Cli.h"

namespace rv {

/// Runs the GUI until its window closes; returns the exit status.
int runGui(int argc, char** argv, const GuiOptions& options);

} // namespace rv
