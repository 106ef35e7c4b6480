#include "render/charts/ToolCharts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vtkChartXY.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>

namespace rv {

void drawMultipliers(PoincareChart& chart, const std::vector<std::vector<std::complex<double>>>& steps) {
  std::vector<double> cx, cy;
  for (int i = 0; i <= 360; ++i) {
    const double a = 2 * std::numbers::pi * i / 360;
    cx.push_back(std::cos(a)), cy.push_back(std::sin(a));
  }
  chart.addCurve(cx, cy, {0.55, 0.55, 0.55}, 1.5);
  double r = 1.2;
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
    chart.addSeries(x, y, seriesColor(static_cast<int>(k)));
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
    bool any = false;
    for (std::size_t k = 0; k < xs.size(); ++k) {
      const bool single =
          std::count_if(xs[k].begin(), xs[k].end(), [](double v) { return !std::isnan(v); }) == 1;
      if (single) { // a point (T0)
        std::vector<double> x, y;
        for (std::size_t i = 0; i < xs[k].size(); ++i)
          if (!std::isnan(xs[k][i])) x.push_back(xs[k][i]), y.push_back(ys[k][i]);
        chart.addSeries(x, y, seriesColor(colour));
        any = true;
      } else if (chart.addCurve(xs[k], ys[k], seriesColor(colour)) >= 0) {
        any = true;
      }
    }
    if (any) ++colour;
  }
  std::vector<double> x, y;
  for (const auto& s : states)
    x.push_back(s[0]), y.push_back(s[1]);
  if (!x.empty()) {
    const int i = chart.addSeries(x, y, {0, 0, 0});
    if (auto* p = vtkPlotPoints::SafeDownCast(chart.chart()->GetPlot(i))) p->SetMarkerSize(9);
  }
}

} // namespace rv
