// BuiltinTools.h -- rollviz's own tools that run through scenes/ToolRunner.h (as a module's do): their
// runners are bound to their registry entries here, once, before any front end is built (findToolRunner
// and scenes/ModuleLoader.h call it).
#pragma once
#include <nlohmann/json.hpp>

namespace rv {

struct MegnoEstimate;

/// The megno tool's named outputs of an estimate (megno, megno_rate, y, fli, time): its result's fields, and
/// what a sweep batching MEGNO on lanes reads (one definition).
nlohmann::json megnoFields(const MegnoEstimate& e);

/// Binds the runners of the built-in tools that have one (bifurcation_curve, spectrum, lyapunov, megno);
/// idempotent and thread-safe. Free of VTK (the fuzzers link it).
void registerBuiltinTools();
/// Binds the runners of the grid tools, surface and ram (scenes/GridTools.cpp); called by the above.
void registerGridTools();
/// Binds the runners of the fixed-point family: fixedpoint, continuation, separatrix, bifurcation_tree
/// (scenes/MapTools.cpp); called by the above.
void registerMapTools();
/// Binds the runners of poincare, map3d, plot and multipliers (scenes/PoincareTools.cpp); called by the
/// above.
void registerPoincareTools();
/// Binds their charts (scenes/BuiltinCharts.cpp, VTK) after their runners; idempotent and thread-safe.
void registerBuiltinCharts();

} // namespace rv
