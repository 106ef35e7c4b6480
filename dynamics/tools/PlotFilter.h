// PlotFilter.h -- the 2D / 3D plot filters (manual §2.4.1-§2.4.2): observables of a trajectory sampled
// whenever the output condition (an observable, by default the time) has changed by the period since the
// last point, up to a number of points. Sampling in time uses the dense output (exact times).
#pragma once
#include "dynamics/core/Model.h"
#include "dynamics/integrators/Integrator.h"
#include "dynamics/tools/ToolControl.h"

#include <string>
#include <vector>

namespace rv {

struct PlotSettings {
  std::vector<std::string> axes = {"t", "E"}; ///< observable ids: 2 (2D plot) or 3 (3D plot)
  std::string condition = "t";                ///< the output condition's observable
  double period = 0.05;                       ///< its change between two points
  long maxPoints = 20000;
  double timeLimit = 1000; ///< integration time at most (a condition that stops changing ends the plot)
};

/// points[k] = the axes' values at the k-th output. Throws InputError naming `context` for an unknown
/// observable or a bad period; stops (returning what it has) when the control asks.
std::vector<std::vector<double>> samplePlot(const Model& model, Integrator& integrator, const PlotSettings& s,
                                            const ToolControl& control, const std::string& context = "plot");

} // namespace rv
