// BuiltinTool.h -- one of rollviz's own tools as one registration, the shape a module's tool has
// (scenes/Module.h, ModuleRegistrar::addTool): its entry (dynamics/tools/ToolRegistry.h), the settings
// section it declares, how it runs on a scene (scenes/ToolRunner.h) and its batch evaluation on SIMD lanes
// (scenes/Sweep.h). Each tool's file gives its own; scenes/builtin/BuiltinTools.cpp lists them, a line each.
// A chart, which needs VTK, is bound by the tool's id in scenes/builtin/BuiltinCharts.cpp.
#pragma once
#include "dynamics/tools/ToolRegistry.h"
#include "scenes/Sweep.h"
#include "scenes/ToolRunner.h"

#include <optional>

namespace rv {

struct BuiltinTool {
  ToolEntry entry;
  /// The settings section it declares (its key: entry.section; its table the parameters, scene keys, --set,
  /// GUI fields). None for a tool without settings, or one that reads a section another declares (ram reads
  /// surface's "grid").
  std::optional<ToolSection> settings = {};
  /// How it runs; none for a tool whose front ends are written by hand (sweep).
  std::optional<ToolRunner> runner = {};
  /// Its batch evaluation on lanes, which every sweep of its outputs then uses; empty: one point at a time.
  LanesEvaluator lanes = {};
  /// The sweep quantities it computes otherwise than by reading a number its runner gives (a count of
  /// exponents, a type's code, an orbit diagram); its outputs marked `quantity` are sweep quantities anyway.
  std::vector<SweepQuantity> quantities = {};
};

// each in its tool's file (the fixed-point family's in MapTools.cpp, the grid's in GridTools.cpp, the map's
// points in PoincareTools.cpp)
BuiltinTool poincareTool();
BuiltinTool spectrumTool();
BuiltinTool lyapunovTool();
BuiltinTool megnoTool();
BuiltinTool map3dTool();
BuiltinTool plotTool();
BuiltinTool fixedPointTool();
BuiltinTool continuationTool();
BuiltinTool multipliersTool();
BuiltinTool separatrixTool();
BuiltinTool bifurcationTreeTool();
BuiltinTool bifurcationCurveTool();
BuiltinTool surfaceTool();
BuiltinTool ramTool();
BuiltinTool diagramTool();
BuiltinTool sweepTool();

} // namespace rv
