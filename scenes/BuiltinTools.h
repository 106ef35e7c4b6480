// BuiltinTools.h -- rollviz's own tools that run through scenes/ToolRunner.h (as a module's do): their
// runners are bound to their registry entries here, once, before any front end is built (findToolRunner
// and scenes/ModuleLoader.h call it).
#pragma once

namespace rv {

/// Binds the runners of the built-in tools that have one (bifurcation_curve, megno); idempotent and
/// thread-safe.
void registerBuiltinTools();

} // namespace rv
