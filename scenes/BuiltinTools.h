// BuiltinTools.h -- rollviz's own tools that run through scenes/ToolRunner.h (as a module's do): their
// runners are bound to their registry entries here, once, before any front end is built
// (scenes/ModuleLoader.h calls it at start, as it loads the modules).
#pragma once

namespace rv {

/// Binds the runners of the built-in tools that have one (bifurcation_curve); idempotent and thread-safe.
void registerBuiltinTools();

} // namespace rv
