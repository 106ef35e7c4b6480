#include "render/charts/ToolCharts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vtkChartXY.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>

namespace rv {

double drawUnitCircle(PoincareChart& chart) {
  std::vector<double> cx, cy;
  for (int i = 0; i <= 360; ++i) {
    const double a = 2 * std::numbers::pi * i / 360;
    cx.push_back(std::cos(a)), cy.push_back(std::sin(a));
  }
  chart.addCurve(cx, cy, {0.55, 0.55, 0.55}, 1.5);
  return 1.2;
}

void drawMultipliers(PoincareChart& chart, const std::vector<std::vector<std::complex<double>>>& steps) {
  double r = drawUnitCircle(chart);
  std::size_t count = 0;
  for (const auto& s : steps)
    count = std::max(count, s.size());
  for (std::size_t k = 0; k < count; ++k) {
    std::vector<double> x, y;
    for (const auto& s : steps)
      if (k < s.size() && std::isfinite(std::abs(s[k]))) {
        x.push_back(s[k].real()), y.push_back(s[k].imag());
        r = std::max({r, 1.1 * std::abs(s[k].real()), 1.1 * std::abs(s[k].imag())});
      }
    chart.addSeries(x, y, seriesColour(static_cast<int>(k)));
  }
  chart.select(-1);
  chart.setRanges(-r, r, -r, r);
}

void drawDiagram(PoincareChart& chart, const Diagram& d, const std::vector<DiagramPoint>& states) {
  int colour = 0;
  for (const auto& b : d.branches) {
    if (!(b.step > 0) || !(b.max >= b.min)) continue;
    const long n = std::min<long>(20000, static_cast<long>(std::floor((b.max - b.min) / b.step)) + 1);
    // a branch may have several points per value: each index is its own curve, broken where points are
    // missing
    std::vector<std::vector<double>> xs, ys;
    for (long i = 0; i < n; ++i) {
      const auto pts = b.points(b.min + (b.max - b.min) * (n > 1 ? static_cast<double>(i) / (n - 1) : 0.0));
      if (pts.size() > xs.size()) xs.resize(pts.size()), ys.resize(pts.size());
      for (std::size_t k = 0; k < xs.size(); ++k) {
        const bool has = k < pts.size();
        xs[k].push_back(has ? pts[k][0] : std::numeric_limits<double>::quiet_NaN());
        ys[k].push_back(has ? pts[k][1] : std::numeric_limits<double>::quiet_NaN());
      }
    }
    int first = -1; // the branch's first plot: the one its name goes to in the legend
    for (std::size_t k = 0; k < xs.size(); ++k) {
      const bool single =
          std::count_if(xs[k].begin(), xs[k].end(), [](double v) { return !std::isnan(v); }) == 1;
      if (single) { // a point (T0)
        std::vector<double> x, y;
        for (std::size_t i = 0; i < xs[k].size(); ++i)
          if (!std::isnan(xs[k][i])) x.push_back(xs[k][i]), y.push_back(ys[k][i]);
        const int i = chart.addSeries(x, y, seriesColour(colour));
        if (first < 0) first = i;
      } else if (const int i = chart.addCurve(xs[k], ys[k], seriesColour(colour)); i >= 0 && first < 0) {
        first = i;
      }
    }
    if (first >= 0) {
      chart.setLegend(first, b.id);
      ++colour;
    }
  }
  chart.legendTopLeft(); // the branches rise to the right from near the origin: the top left is free
  std::vector<double> x, y;
  for (const auto& s : states)
    x.push_back(s[0]), y.push_back(s[1]);
  if (!x.empty()) {
    const int i = chart.addSeries(x, y, {0, 0, 0});
    if (auto* p = vtkPlotPoints::SafeDownCast(chart.chart()->GetPlot(i))) p->SetMarkerSize(9);
    chart.setLegend(i, states.size() > 1 ? "the states" : "the state");
  }
}

void drawCurves(PoincareChart& chart, const std::vector<double>& x,
                const std::vector<std::vector<double>>& ys, const std::vector<std::array<double, 2>>& marks,
                const std::vector<std::string>& names) {
  for (std::size_t k = 0; k < ys.size(); ++k) {
    const int first = chart.addCurve(x, ys[k], seriesColour(static_cast<int>(k)));
    if (first >= 0 && k < names.size()) chart.setLegend(first, names[k]);
  }
  if (!marks.empty()) {
    std::vector<double> mx, my;
    for (const auto& m : marks)
      mx.push_back(m[0]), my.push_back(m[1]);
    const int i = chart.addSeries(mx, my, {0.85, 0.1, 0.1});
    if (auto* p = vtkPlotPoints::SafeDownCast(chart.chart()->GetPlot(i))) p->SetMarkerSize(8);
  }
}

Rgb typeColour(FixedPointType type) {
  switch (type) {
  case FixedPointType::Elliptic:
    return {0.12, 0.38, 0.85};
  case FixedPointType::Hyperbolic:
    return {0.85, 0.2, 0.15};
  case FixedPointType::HyperbolicWithReflection:
    return {0.95, 0.55, 0.1};
  default:
    return {0.45, 0.45, 0.45};
  }
}

void drawFamily(PoincareChart& chart, const std::vector<double>& parameter,
                const std::vector<double>& coordinate, const std::vector<FixedPointType>& types) {
  std::vector<FixedPointType> seen;
  for (const auto& t : types)
    if (std::find(seen.begin(), seen.end(), t) == seen.end()) seen.push_back(t);
  for (const auto& t : seen) {
    std::vector<double> x, y;
    for (std::size_t i = 0; i < types.size(); ++i)
      if (types[i] == t) x.push_back(parameter[i]), y.push_back(coordinate[i]);
    const int k = chart.addSeries(x, y, typeColour(t));
    if (auto* p = vtkPlotPoints::SafeDownCast(chart.chart()->GetPlot(k))) p->SetMarkerSize(5);
  }
}

} // namespace rv
