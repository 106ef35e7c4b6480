// BuiltinTools.h -- rollviz's own tools, registered the way a module's are (scenes/builtin/BuiltinTool.h:
// each tool's entry, settings table, runner and lanes in its own file, one line each in
// scenes/builtin/BuiltinTools.cpp), before any front end reads the registry: the scene loader's library
// does it when it loads, and findToolRunner, loadModules and sceneFromJson make sure of it.
#pragma once

namespace rv {

/// Registers the built-in tools' entries, settings sections, runners and batch evaluations on lanes;
/// idempotent and thread-safe. Free of VTK (the fuzzers link it).
void registerBuiltinTools();
/// Binds their charts (scenes/builtin/BuiltinCharts.cpp, VTK) after their runners; idempotent and
/// thread-safe.
void registerBuiltinCharts();

} // namespace rv
