// ToolCharts.h -- the charts of the fixed-point family on a PoincareChart: the multipliers of a continued
// fixed point on the complex plane with the unit circle (manual §2.4.3, Fixed point multiplicators plot), and
// a bifurcation diagram on the plane of first integrals with the points of trajectories (§2.4.4, Bifurcation
// plot).
#pragma once
#include "dynamics/core/Diagram.h"
#include "dynamics/tools/FixedPoint.h"
#include "render/charts/PoincareChart.h"

#include <array>
#include <complex>
#include <string>
#include <vector>

namespace rv {

/// The unit circle (grey), the plane of multipliers; returns the half-width of the square to show (1.2).
double drawUnitCircle(PoincareChart& chart);

/// The unit circle and the multipliers of each step of a family (one colour per multiplier index, so a
/// multiplier's path can be followed); the plane is square around the circle and the points.
void drawMultipliers(PoincareChart& chart, const std::vector<std::vector<std::complex<double>>>& steps);

/// Every branch of `diagram` sampled over its default range, one colour per branch, and `states` (points of
/// trajectories) as large black points; the legend names each branch by its id (sigma, tau, T0, ...).
void drawDiagram(PoincareChart& chart, const Diagram& diagram, const std::vector<DiagramPoint>& states);

/// One curve per series against a common abscissa (Lyapunov exponents against time, the spectrum), with
/// optional marked points (peaks); `names` (one per curve, or none) label the curves in a legend.
void drawCurves(PoincareChart& chart, const std::vector<double>& x,
                const std::vector<std::vector<double>>& ys,
                const std::vector<std::array<double, 2>>& marks = {},
                const std::vector<std::string>& names = {});

/// A family of fixed points: parameter against a coordinate, one colour per type (elliptic blue, hyperbolic
/// red, with reflection orange, others grey).
void drawFamily(PoincareChart& chart, const std::vector<double>& parameter,
                const std::vector<double>& coordinate, const std::vector<FixedPointType>& types);

/// The colour of a fixed point's type.
Rgb typeColour(FixedPointType type);

} // namespace rv
