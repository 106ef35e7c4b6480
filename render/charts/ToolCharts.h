// ToolCharts.h -- the charts of the fixed-point family on a PoincareChart: the multipliers of a continued
// fixed point on the complex plane with the unit circle (manual §2.4.3, Fixed point multiplicators plot), and
// a bifurcation diagram on the plane of first integrals with the points of trajectories (§2.4.4, Bifurcation
// plot).
#pragma once
#include "dynamics/core/Diagram.h"
#include "render/charts/PoincareChart.h"

#include <complex>
#include <vector>

namespace rv {

/// The unit circle and the multipliers of each step of a family (one colour per multiplier index, so a
/// multiplier's path can be followed); the plane is square around the circle and the points.
void drawMultipliers(PoincareChart& chart, const std::vector<std::vector<std::complex<double>>>& steps);

/// Every branch of `diagram` sampled over its default range, one colour per branch, and `states` (points of
/// trajectories) as large black points.
void drawDiagram(PoincareChart& chart, const Diagram& diagram, const std::vector<DiagramPoint>& states);

} // namespace rv
