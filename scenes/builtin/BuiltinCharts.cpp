// BuiltinCharts.cpp -- how the results of rollviz's own runnable tools (BuiltinTool.h) are drawn, bound to
// their runners by id once, before the first chart is drawn (scenes/SceneCharts.cpp). Apart from the tools'
// files because it needs VTK (the fuzzers link the tools without it).
#include "dynamics/core/Diagram.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"
#include "dynamics/tools/FixedPoint.h"
#include "render/charts/Chart3D.h"
#include "render/charts/PlotChart.h"
#include "render/charts/ToolCharts.h"
#include "scenes/BuiltinTools.h"
#include "scenes/ToolRunner.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <utility>

namespace rv {

namespace {

// the curve in its parameter plane, its meeting points marked
std::unique_ptr<Chart> bifurcationCurveChart(const Scene&, const ToolResult& r) {
  const auto& t = r.table;
  if (t.names.size() < 2) throw ComputationError("bifurcation_curve: no curve to draw");
  auto chart = std::make_unique<PoincareChart>(t.names[0], t.names[1]);
  std::vector<std::array<double, 2>> marks;
  for (const auto& e : r.fields.value("events", nlohmann::json::array()))
    marks.push_back({e[t.names[0]].get<double>(), e[t.names[1]].get<double>()});
  drawCurves(*chart, t.values[0], {t.values[1]}, marks);
  chart->setTitle(format("%s curve in (%s, %s)", r.fields.value("kind", std::string()).c_str(),
                         t.names[0].c_str(), t.names[1].c_str()));
  return chart;
}

// the map's points: its first two coordinates (a 1D map's against the time)
std::unique_ptr<Chart> poincareChart(const Scene&, const ToolResult& r) {
  const auto& t = r.table;
  // the columns are the coordinates, t, sheet: a 1D map's second column is the time
  auto chart = std::make_unique<PoincareChart>(t.names.at(0), t.names.at(1));
  chart->addSeries(t.values.at(0), t.values.at(1), seriesColour(0));
  chart->select(0);
  chart->setTitle("Poincaré map");
  return chart;
}

// the map in three dimensions
std::unique_ptr<Chart> map3dChart(const Scene&, const ToolResult& r) {
  const auto& t = r.table;
  auto chart =
      std::make_unique<Chart3D>(std::array<std::string, 3>{t.names.at(0), t.names.at(1), t.names.at(2)});
  chart->addSeries(t.values[0], t.values[1], t.values[2], seriesColour(0), 3);
  return chart;
}

// the plot section's observables, in the plot window's ranges and point type
std::unique_ptr<Chart> plotChart(const Scene& scene, const ToolResult& r) {
  std::array<std::vector<double>, 3> c;
  for (std::size_t i = 0; i < r.table.values.size() && i < 3; ++i)
    c[i] = r.table.values[i];
  auto plot = std::make_unique<PlotChart>(scene.plot.settings.axes, scene.plot.chart);
  plot->setSeries(plot->addSeries(seriesColour(0)), c);
  return plot;
}

// the multipliers on the complex plane, step after step of the continuation
std::unique_ptr<Chart> multipliersChart(const Scene&, const ToolResult& r) {
  std::vector<std::vector<std::complex<double>>> steps;
  for (const auto& row : r.fields.at("multipliers")) {
    steps.emplace_back();
    for (const auto& z : row)
      steps.back().emplace_back(z[0].get<double>(), z[1].get<double>());
  }
  auto chart = std::make_unique<PoincareChart>("Re", "Im");
  drawMultipliers(*chart, steps);
  chart->setTitle("Multipliers");
  return chart;
}

// a type as the result's text column spells it (toString)
FixedPointType fixedPointTypeOf(const std::string& name) {
  for (int k = 0; k <= static_cast<int>(FixedPointType::Unstable); ++k)
    if (name == toString(static_cast<FixedPointType>(k))) return static_cast<FixedPointType>(k);
  throw ComputationError("continuation: unknown type of fixed point '" + name + "'");
}

// a continued family: its parameter against the coordinate that moves most along it, coloured by type
std::unique_ptr<Chart> continuationChart(const Scene&, const ToolResult& r) {
  const auto& t = r.table;
  if (t.rows() == 0) throw ComputationError("continuation: no point of the family to draw");
  // the coordinates are the columns between the parameter and the multipliers (re1, im1, ...)
  const auto multipliers = std::find(t.names.begin(), t.names.end(), "re1");
  const auto coordinates = static_cast<std::size_t>(multipliers - t.names.begin());
  std::size_t best = 1;
  double spread = -1;
  for (std::size_t k = 1; k < coordinates; ++k) {
    const auto [lo, hi] = std::minmax_element(t.values[k].begin(), t.values[k].end());
    if (*hi - *lo > spread) spread = *hi - *lo, best = k;
  }
  std::vector<FixedPointType> types;
  for (const auto& name : r.text.at(0).values)
    types.push_back(fixedPointTypeOf(name));
  auto chart = std::make_unique<PoincareChart>(t.names[0], t.names[best]);
  drawFamily(*chart, t.values[0], t.values[best], types);
  chart->setTitle("Continuation");
  return chart;
}

// the amplitudes against frequency, the peaks marked, up to a little past the highest peak (the rest of a
// smooth signal's spectrum is flat)
std::unique_ptr<Chart> spectrumChart(const Scene&, const ToolResult& r) {
  const auto& frequency = r.table.values.at(0);
  const auto& amplitude = r.table.values.at(1);
  std::vector<std::array<double, 2>> peaks;
  double top = 0, amax = 0;
  for (const auto& p : r.fields.at("peaks")) {
    peaks.push_back({p["frequency"].get<double>(), p["amplitude"].get<double>()});
    top = std::max(top, peaks.back()[0]), amax = std::max(amax, peaks.back()[1]);
  }
  auto chart = std::make_unique<PoincareChart>("frequency",
                                               "amplitude of " + r.fields.at("function").get<std::string>());
  drawCurves(*chart, frequency, {amplitude}, peaks);
  if (top > 0 && !frequency.empty() && 2 * top < frequency.back())
    chart->setRanges(0, 2 * top, 0, 1.05 * amax);
  chart->setTitle("Fourier spectrum");
  return chart;
}

// the history's curves against t, each with its last value in the legend (the number the chart is read for);
// `curves` picks columns and names them in the legend (empty: every column, by its own name)
using LegendNames = std::vector<std::pair<std::string, std::string>>; // column, its name in the legend
/// How a history chart orders its curves in the legend.
enum class CurveOrder { AsComputed, LargestFirst };
std::unique_ptr<Chart> historyChart(const ToolResult& r, const std::string& title, const std::string& yTitle,
                                    const LegendNames& curves, CurveOrder order = CurveOrder::AsComputed) {
  const auto& t = r.table;
  auto chart = std::make_unique<PoincareChart>("t", yTitle);
  struct Curve {
    const std::vector<double>* y;
    std::string name;
    double last;
  };
  std::vector<Curve> drawn;
  for (std::size_t c = 1; c < t.names.size(); ++c) {
    const auto picked = std::find_if(curves.begin(), curves.end(),
                                     [&](const auto& curve) { return curve.first == t.names[c]; });
    if (!curves.empty() && picked == curves.end()) continue;
    const std::string& label = curves.empty() ? t.names[c] : picked->second;
    const double last = t.values[c].empty() ? 0.0 : t.values[c].back();
    drawn.push_back({&t.values[c], format("%s = %.6g", label.c_str(), last), last});
  }
  // a spectrum: its values at the end, largest first (a finite time's estimates need not come in order; NaN
  // last)
  if (order == CurveOrder::LargestFirst) {
    const auto key = [](const Curve& c) { return std::isnan(c.last) ? -HUGE_VAL : c.last; };
    std::stable_sort(drawn.begin(), drawn.end(),
                     [&](const Curve& a, const Curve& b) { return key(a) > key(b); });
    chart->setLegendOrder("largest first");
  }
  std::vector<std::vector<double>> ys;
  std::vector<std::string> names;
  for (const Curve& c : drawn)
    ys.push_back(*c.y), names.push_back(c.name);
  if (!t.names.empty()) drawCurves(*chart, t.values[0], ys, {}, names);
  chart->setTitle(title);
  return chart;
}

// a grid tool's result (GridTools.cpp) as an image over its plane -- the surface as log10 of the
// distance (the zeros, fixed points, are the darkest spots) with the search path from fixedpoint.guess, the
// region of allowed motion as two shades; of a 3D grid the layer nearest grid.z
std::unique_ptr<Chart> gridChart(const Scene& scene, const ToolResult& r) {
  const ToolGrid& g = r.grid;
  const auto& t = r.table;
  if (g.dimensions < 2 || static_cast<int>(t.names.size()) <= g.coordinates)
    throw ComputationError("the grid tool gave no grid to draw");
  const bool surface = t.names[g.coordinates] == "distance";
  const int nx = g.size[0], ny = g.size[1];
  int layer = 0;
  if (g.dimensions == 3) {
    const double z = scene.tool("grid")["z"];
    layer = std::clamp(static_cast<int>(std::lround((z - g.origin[2]) / g.spacing[2])), 0, g.size[2] - 1);
  }
  const auto& values = t.values[g.coordinates];
  std::vector<double> z(static_cast<std::size_t>(nx) * ny);
  for (std::size_t i = 0; i < z.size(); ++i) {
    const double v = values.at(static_cast<std::size_t>(layer) * z.size() + i);
    z[i] = surface ? std::log10(std::max(v, 1e-16)) : v;
  }
  auto chart = std::make_unique<PoincareChart>(t.names[0], t.names[1]);
  if (surface)
    chart->addImage(nx, ny, g.origin[0], g.spacing[0], g.origin[1], g.spacing[1], z, {0.05, 0.05, 0.35},
                    {1.0, 0.95, 0.6});
  else
    chart->addImage(nx, ny, g.origin[0], g.spacing[0], g.origin[1], g.spacing[1], z, {0.85, 0.85, 0.85},
                    {0.2, 0.55, 0.3});
  std::vector<double> px, py;
  for (const auto& p : r.fields.value("search_path", nlohmann::json::array()))
    px.push_back(p.at(0).get<double>()), py.push_back(p.at(1).get<double>());
  if (!px.empty()) {
    chart->addCurve(px, py, {0.9, 0.1, 0.1}, 1.5);
    chart->select(chart->addSeries(px, py, {0.9, 0.1, 0.1}));
  }
  // the cells are centred on the nodes: the outer ones reach half a step beyond the grid's range
  chart->setRanges(g.origin[0] - g.spacing[0] / 2, g.origin[0] + (nx - 0.5) * g.spacing[0],
                   g.origin[1] - g.spacing[1] / 2, g.origin[1] + (ny - 0.5) * g.spacing[1]);
  std::string title = surface ? "Surface |Map(x) - x| (log10)" : "Region of allowed motion";
  if (g.dimensions == 3)
    title += format(" at %s = %.6g", t.names[2].c_str(), g.origin[2] + layer * g.spacing[2]);
  chart->setTitle(title);
  return chart;
}

// the diagram's branches drawn from the model (the chart samples them finer than a table may), the scene's
// point marked; named by its id when the scene picks one
std::unique_ptr<Chart> diagramChart(const Scene& scene, const ToolResult& r) {
  const auto diagrams = scene.model->diagrams();
  const Diagram& d = findDiagram(diagrams, r.fields.at("diagram").get<std::string>(), "diagram.diagram",
                                 scene.model->info().id);
  auto chart = std::make_unique<PoincareChart>(d.axes[0], d.axes[1]);
  drawDiagram(*chart, d, {r.fields.at("state").get<DiagramPoint>()});
  const bool named = scene.document.contains("diagram") && scene.document["diagram"].contains("diagram");
  chart->setTitle("Topological analysis" + (named ? " " + d.id : std::string()));
  return chart;
}

} // namespace

void registerBuiltinCharts() {
  static std::once_flag once;
  std::call_once(once, [] {
    registerBuiltinTools();
    addToolChart("bifurcation_curve", bifurcationCurveChart);
    addToolChart("spectrum", spectrumChart);
    addToolChart("diagram", diagramChart);
    addToolChart("continuation", continuationChart);
    addToolChart("poincare", poincareChart);
    addToolChart("map3d", map3dChart);
    addToolChart("plot", plotChart);
    addToolChart("multipliers", multipliersChart);
    addToolChart("surface", gridChart);
    addToolChart("ram", gridChart);
    addToolChart("lyapunov", [](const Scene&, const ToolResult& r) {
      return historyChart(r, "Lyapunov exponents", "Lyapunov exponents", {}, CurveOrder::LargestFirst);
    });
    addToolChart("megno", [](const Scene&, const ToolResult& r) {
      return historyChart(r, "MEGNO and FLI", "MEGNO <Y>", {{"megno", "<Y>"}});
    });
  });
}

} // namespace rv
