// ToolSettings.h -- the parameters of the fixed-point family of tools (manual §2.3.4-§2.3.9), declared once
// as parameter tables: scene sections ("fixedpoint", "continuation", "separatrix", "bifurcation_tree",
// "grid"), `--set SECTION.ID=VALUE` and the GUI's fields all come from these declarations.
#pragma once
#include "dynamics/tools/BifurcationCurve.h"
#include "dynamics/tools/BifurcationTree.h"
#include "dynamics/tools/MapGrid.h"
#include "dynamics/tools/Separatrix.h"
#include "dynamics/tools/ToolRegistry.h"

namespace rv {

/// The tables take their defaults from default-constructed settings structs (one declaration of each).
const ParameterTable& fixedPointTable();
const ParameterTable& continuationTable();
const ParameterTable& separatrixTable();
const ParameterTable& bifurcationTreeTable();
/// "bifurcation_curve": which curve, its steps and box (its second parameter is the section's text key
/// "second_parameter", the first continuation.parameter).
const ParameterTable& bifurcationCurveTable();
const ParameterTable& gridTable();
/// The bifurcation diagram's section has no numbers of its own: its keys (which diagram, branch, range) are
/// text keys (scenes/SceneLoader.cpp).
const ParameterTable& diagramTable();
/// A sweep file's "options" (scenes/Sweep.h): time, statistic, orbit points, the order search... (one
/// declaration, shown by `rollviz describe-tool sweep`).
const ParameterTable& sweepOptionsTable();

FixedPointSettings fixedPointSettings(const ParameterValues& v);
/// The numeric part (parameter id, finite value and step come from the command or the scene's strings).
ContinuationSettings continuationSettings(const ParameterValues& v, const FixedPointSettings& search);
SeparatrixSettings separatrixSettings(const ParameterValues& v, const FixedPointSettings& search);
BifurcationTreeSettings bifurcationTreeSettings(const ParameterValues& v, const ContinuationSettings& c);
/// The numeric part (the two parameters' ids come from the scene's strings).
BifurcationCurveSettings bifurcationCurveSettings(const ParameterValues& v, const FixedPointSettings& search);
/// The grid's threads, steps, section and the chart's ranges x_min ... y_max (a command's flags override
/// them).
GridSettings gridSettings(const ParameterValues& v);

} // namespace rv
