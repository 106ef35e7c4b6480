// ToolSettings.h -- the parameters of the fixed-point family of tools (manual §2.3.4-§2.3.9), declared once
// as parameter tables: scene sections ("fixedpoint", "continuation", "separatrix", "bifurcation_tree",
// "grid"), `--set SECTION.ID=VALUE` and the GUI's fields all come from these declarations.
#pragma once
#include "dynamics/core/SettingsTable.h"
#include "dynamics/tools/BifurcationCurve.h"
#include "dynamics/tools/BifurcationTree.h"
#include "dynamics/tools/MapGrid.h"
#include "dynamics/tools/Separatrix.h"
#include "dynamics/tools/ToolRegistry.h"

namespace rv {

/// Each table declares its parameters beside the members they set (SettingsTable.h); the parts of the
/// settings that are no parameters of the section (a continuation's parameter id, the fixed-point search a
/// continuation uses) are set by whoever composes them, before or after read().
const SettingsTable<FixedPointSettings>& fixedPointSettingsTable();
const SettingsTable<ContinuationSettings>& continuationSettingsTable();
const SettingsTable<SeparatrixSettings>& separatrixSettingsTable();
const SettingsTable<BifurcationTreeSettings>& bifurcationTreeSettingsTable();
/// "bifurcation_curve": which curve, its steps and box (its second parameter is the section's text key
/// "second_parameter", the first continuation.parameter).
const SettingsTable<BifurcationCurveSettings>& bifurcationCurveSettingsTable();
/// The grid's threads, steps, section and the chart's ranges x_min ... y_max (a command's flags override
/// them).
const SettingsTable<GridSettings>& gridSettingsTable();
/// The bifurcation diagram's section has no numbers of its own: its keys (which diagram, branch, range) are
/// text keys (scenes/SceneLoader.cpp).
const ParameterTable& diagramTable();
/// A sweep file's "options" (scenes/Sweep.h): time, statistic, orbit points, the order search... (one
/// declaration, shown by `rollviz describe-tool sweep`).
const ParameterTable& sweepOptionsTable();

} // namespace rv
