#include "render/charts/PoincareChart.h"

#include "render/charts/RasterPointsPlot.h"
#include "render/charts/VectorPictures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vtkAxis.h>
#include <vtkCallbackCommand.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkColorLegend.h>
#include <vtkColorTransferFunction.h>
#include <vtkCommand.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkObjectFactory.h>
#include <vtkPlot.h>
#include <vtkPlotHistogram2D.h>
#include <vtkPlotPoints.h>
#include <vtkPointData.h>
#include <vtkRect.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkTooltipItem.h>

namespace rv {

namespace {
// A heat map's colour bar: the chart's colour legend kept just right of the plot area (the chart lays out
// the plot area at each paint; vtkChartHistogram2D does the same for its own legend).
class ColourBar final : public VectorColourLegend {
public:
  static ColourBar* New();
  vtkTypeMacro(ColourBar, VectorColourLegend);
  vtkChartXY* owner = nullptr; ///< the chart it stands beside (which owns it)
  ColourBar() { Axis->GetLabelProperties()->SetFontSize(12); }
  bool Paint(vtkContext2D* painter) override {
    if (owner) {
      const int* p1 = owner->GetPoint1();
      const int* p2 = owner->GetPoint2();
      SetPosition(vtkRectf(static_cast<float>(p2[0] + 12), static_cast<float>(p1[1]), 16.0f,
                           static_cast<float>(p2[1] - p1[1])));
    }
    Update(); // the bar's picture of the colours (nothing calls it for an item added to a chart)
    return VectorColourLegend::Paint(painter);
  }
};
vtkStandardNewMacro(ColourBar);
} // namespace

Rgb seriesColour(int i) {
  static const Rgb palette[] = {{0.12, 0.38, 0.85}, {0.85, 0.25, 0.15}, {0.15, 0.6, 0.25},  {0.6, 0.25, 0.7},
                                {0.9, 0.55, 0.1},   {0.1, 0.6, 0.65},   {0.45, 0.45, 0.45}, {0.7, 0.55, 0.2}};
  return palette[i % 8];
}

PoincareChart::PoincareChart(const std::string& xTitle, const std::string& yTitle) {
  view_ = vtkSmartPointer<vtkContextView>::New();
  view_->GetRenderer()->SetBackground(1, 1, 1);
  chart_ = vtkSmartPointer<vtkChartXY>::New();
  view_->GetScene()->AddItem(chart_);
  // before every frame: thin the large series for the ranges about to be drawn
  vtkNew<vtkCallbackCommand> beforeRender;
  beforeRender->SetClientData(this);
  beforeRender->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    static_cast<PoincareChart*>(self)->thinLargeSeries();
    static_cast<PoincareChart*>(self)->fitTickDigits();
  });
  view_->GetRenderer()->AddObserver(vtkCommand::StartEvent, beforeRender);
  chart_->GetAxis(vtkAxis::BOTTOM)->SetTitle(xTitle);
  chart_->GetAxis(vtkAxis::LEFT)->SetTitle(yTitle);
  for (int a : {vtkAxis::BOTTOM, vtkAxis::LEFT}) {
    chart_->GetAxis(a)->GetTitleProperties()->SetFontSize(16);
    chart_->GetAxis(a)->GetLabelProperties()->SetFontSize(13);
  }
}

void PoincareChart::fitTickDigits() {
  for (int a : {vtkAxis::BOTTOM, vtkAxis::LEFT}) {
    vtkAxis* axis = chart_->GetAxis(a);
    // VTK's labels have six digits: zoomed into 3.14159 +- 1e-6 they all read "3.14159"; give them the digits
    // of the tick step (about a fifth of the range) beyond the numbers' magnitude
    const double lo = axis->GetMinimum(), hi = axis->GetMaximum();
    const double step = std::abs(hi - lo) / 5, big = std::max(std::abs(lo), std::abs(hi));
    int digits = 6;
    if (step > 0 && big > 0 && std::isfinite(big / step))
      digits = std::clamp(static_cast<int>(std::ceil(std::log10(big / step))) + 2, 6, 17);
    if (digits == 6) { // VTK's own labels, as always
      if (axis->GetNotation() != vtkAxis::STANDARD_NOTATION) axis->SetNotation(vtkAxis::STANDARD_NOTATION);
    } else if (const std::string format = "%." + std::to_string(digits) + "g";
               axis->GetNotation() != vtkAxis::PRINTF_NOTATION || axis->GetLabelFormat() != format) {
      axis->SetNotation(vtkAxis::PRINTF_NOTATION);
      axis->SetLabelFormat(format);
    }
  }
}

PoincareChart::~PoincareChart() = default; // (no GL work here: the window's context may be gone already)

void PoincareChart::setTitle(const std::string& title) {
  chart_->SetTitle(title);
  chart_->GetTitleProperties()->SetFontSize(16);
  chart_->GetTitleProperties()->SetBold(true);
}

void PoincareChart::setLegend(int index, const std::string& name) {
  vtkPlot* plot = chart_->GetPlot(index);
  if (!plot) return;
  if (!chart_->GetShowLegend()) { // the first name: every series so far unnamed, left out of the legend
    for (vtkIdType i = 0; i < chart_->GetNumberOfPlots(); ++i)
      chart_->GetPlot(i)->SetLegendVisibility(false);
    chart_->SetShowLegend(true);
    chart_->GetLegend()->GetLabelProperties()->SetFontSize(13);
  }
  plot->SetLabel(name);
  plot->SetLegendVisibility(true);
}

void PoincareChart::legendTopLeft() {
  chart_->GetLegend()->SetHorizontalAlignment(vtkChartLegend::LEFT);
  chart_->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
}

void PoincareChart::setTitles(const std::string& x, const std::string& y) {
  chart_->GetAxis(vtkAxis::BOTTOM)->SetTitle(x);
  chart_->GetAxis(vtkAxis::LEFT)->SetTitle(y);
}

vtkChartXY* PoincareChart::chart() const {
  return chart_;
}

namespace {
vtkSmartPointer<vtkTable> tableOf(const std::vector<double>& x, const std::vector<double>& y,
                                  vtkIdType series) {
  auto table = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkDoubleArray> xs, ys;
  xs->SetName("x");
  ys->SetName(("y" + std::to_string(series)).c_str());
  xs->SetNumberOfValues(static_cast<vtkIdType>(x.size()));
  ys->SetNumberOfValues(static_cast<vtkIdType>(y.size()));
  for (std::size_t i = 0; i < x.size(); ++i) {
    xs->SetValue(static_cast<vtkIdType>(i), x[i]);
    ys->SetValue(static_cast<vtkIdType>(i), y[i]);
  }
  table->AddColumn(xs);
  table->AddColumn(ys);
  return table;
}
} // namespace

namespace {
// the indices of the smallest and largest x and y: kept by the thinning, so that the data's bounds (and the
// automatic ranges) do not change with the view
// (from index `from` on, starting from the extremes `e` of the points before it)
std::array<std::size_t, 4> extremes(const std::vector<double>& x, const std::vector<double>& y,
                                    std::size_t from = 0, std::array<std::size_t, 4> e = {0, 0, 0, 0}) {
  for (std::size_t k = from; k < x.size(); ++k) {
    if (x[k] < x[e[0]]) e[0] = k;
    if (x[k] > x[e[1]]) e[1] = k;
    if (y[k] < y[e[2]]) e[2] = k;
    if (y[k] > y[e[3]]) e[3] = k;
  }
  return e;
}
} // namespace

void PoincareChart::setPoints(vtkPlot* plot, int index, const std::vector<double>& x,
                              const std::vector<double>& y) {
  // a map filling: the same series with points added at its end takes only the new points (10^6 points copied
  // on every frame would cost the GUI a turn of its event loop)
  auto grown = std::find_if(large_.begin(), large_.end(), [&](const LargeSeries& s) {
    const std::size_t n = s.x.size();
    return s.index == index && s.plot == plot && n <= x.size() && x.size() == y.size() && n > 0 &&
           s.x[n - 1] == x[n - 1] && s.y[n - 1] == y[n - 1] && s.x[0] == x[0] && s.y[0] == y[0] &&
           s.x[n / 2] == x[n / 2] && s.y[n / 2] == y[n / 2];
  });
  if (grown == large_.end()) {
    std::erase_if(large_, [&](const LargeSeries& s) { return s.index == index; });
    if (x.size() <= kThinAbove) return plot->SetInputData(tableOf(x, y, index), 0, 1);
    // a large series: only its extremes until the thinning before the next frame (a table of every point
    // would cost more than drawing the thinned ones)
    large_.push_back({plot, index, x, y, extremes(x, y)});
    grown = large_.end() - 1;
  } else {
    const std::size_t old = grown->x.size();
    grown->x.insert(grown->x.end(), x.begin() + static_cast<std::ptrdiff_t>(old), x.end());
    grown->y.insert(grown->y.end(), y.begin() + static_cast<std::ptrdiff_t>(old), y.end());
    grown->extremes = extremes(grown->x, grown->y, old, grown->extremes);
    return; // the thinning before the next frame adds the new points to those it kept
  }
  std::vector<double> ex, ey;
  for (std::size_t k : grown->extremes)
    ex.push_back(grown->x[k]), ey.push_back(grown->y[k]);
  plot->SetInputData(tableOf(ex, ey, index), 0, 1);
}

int PoincareChart::addSeries(const std::vector<double>& x, const std::vector<double>& y, const Rgb& c) {
  vtkNew<RasterPointsPlot> raster; // one splatted picture instead of a point sprite each
  vtkPlot* plot = raster;
  chart_->AddPlot(plot);
  plot->SetLegendVisibility(!chart_->GetShowLegend()); // (setLegend names it)
  const int index = static_cast<int>(chart_->GetNumberOfPlots()) - 1;
  setPoints(plot, index, x, y);
  plot->SetColor(static_cast<unsigned char>(255 * c[0]), static_cast<unsigned char>(255 * c[1]),
                 static_cast<unsigned char>(255 * c[2]), 255);
  if (auto* points = vtkPlotPoints::SafeDownCast(plot)) {
    points->SetMarkerStyle(vtkPlotPoints::CIRCLE);
    points->SetMarkerSize(markerSize_); // the chart's size, also for series added later
  }
  return static_cast<int>(chart_->GetNumberOfPlots()) - 1;
}

int PoincareChart::addMarkers(const std::vector<double>& x, const std::vector<double>& y, const Rgb& c) {
  vtkNew<vtkPlotPoints> points;
  chart_->AddPlot(points);
  points->SetLegendVisibility(!chart_->GetShowLegend()); // (setLegend names it)
  const int index = static_cast<int>(chart_->GetNumberOfPlots()) - 1;
  setPoints(points, index, x, y);
  points->SetColor(static_cast<unsigned char>(255 * c[0]), static_cast<unsigned char>(255 * c[1]),
                   static_cast<unsigned char>(255 * c[2]), 255);
  points->SetMarkerStyle(vtkPlotPoints::CROSS);
  points->SetMarkerSize(5 * markerSize_);
  markers_.push_back(index);
  return index;
}

int PoincareChart::addCurve(const std::vector<double>& x, const std::vector<double>& y, const Rgb& c,
                            float width) {
  int first = -1;
  std::vector<double> px, py;
  const auto flush = [&] {
    if (px.size() >= 2) {
      vtkPlot* plot = chart_->AddPlot(vtkChart::LINE);
      plot->SetLegendVisibility(!chart_->GetShowLegend()); // (setLegend names it)
      plot->SetInputData(tableOf(px, py, chart_->GetNumberOfPlots()), 0, 1);
      plot->SetColor(static_cast<unsigned char>(255 * c[0]), static_cast<unsigned char>(255 * c[1]),
                     static_cast<unsigned char>(255 * c[2]), 255);
      plot->SetWidth(width);
      if (first < 0) first = static_cast<int>(chart_->GetNumberOfPlots()) - 1;
    }
    px.clear(), py.clear();
  };
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    if (std::isnan(x[i]) || std::isnan(y[i])) {
      flush();
      continue;
    }
    px.push_back(x[i]), py.push_back(y[i]);
  }
  flush();
  return first;
}

void PoincareChart::addImage(int nx, int ny, double x0, double dx, double y0, double dy,
                             const std::vector<double>& values, const Rgb& low, const Rgb& high) {
  vtkNew<vtkImageData> image;
  image->SetDimensions(nx, ny, 1);
  image->SetOrigin(x0 - dx / 2, y0 - dy / 2, 0); // the plot's cells start at their points
  image->SetSpacing(dx, dy, 1);
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetNumberOfValues(static_cast<vtkIdType>(nx) * ny);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < values.size() && i < static_cast<std::size_t>(scalars->GetNumberOfValues());
       ++i) {
    scalars->SetValue(static_cast<vtkIdType>(i), values[i]);
    if (std::isfinite(values[i])) lo = std::min(lo, values[i]), hi = std::max(hi, values[i]);
  }
  image->GetPointData()->SetScalars(scalars);
  if (!(hi > lo)) hi = lo + 1;
  vtkNew<vtkColorTransferFunction> colours;
  colours->AddRGBPoint(lo, low[0], low[1], low[2]);
  colours->AddRGBPoint(hi, high[0], high[1], high[2]);
  colours->SetNanColor(1, 1, 1);
  colours->SetNanOpacity(0);
  vtkNew<CellsPlot> plot; // its cells reach vector figures
  plot->SetInputData(image);
  plot->SetTransferFunction(colours);
  plot->SetLegendVisibility(false);
  chart_->AddPlot(plot);
  chart_->RecalculateBounds();
  vtkNew<ColourBar> bar;
  bar->owner = chart_;
  bar->SetTransferFunction(colours);
  bar->DrawBorderOn();
  chart_->AddItem(bar);
  chart_->SetHiddenAxisBorder(std::max(chart_->GetHiddenAxisBorder(), 72)); // room for the bar's numbers
}

void PoincareChart::setRanges(double x0, double x1, double y0, double y1) {
  vtkAxis* ax = chart_->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* ay = chart_->GetAxis(vtkAxis::LEFT);
  ax->SetRange(x0, x1), ay->SetRange(y0, y1);
  ax->SetBehavior(vtkAxis::FIXED), ay->SetBehavior(vtkAxis::FIXED);
}

void PoincareChart::setPointLabel(bool on) {
  if (on == (chart_->GetTooltip() != nullptr)) return;
  chart_->SetTooltip(on ? vtkSmartPointer<vtkTooltipItem>::New().GetPointer() : nullptr);
}

std::array<double, 4> PoincareChart::ranges() const {
  vtkAxis* ax = chart_->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* ay = chart_->GetAxis(vtkAxis::LEFT);
  return {ax->GetMinimum(), ax->GetMaximum(), ay->GetMinimum(), ay->GetMaximum()};
}

bool PoincareChart::rangesHeld() const {
  return chart_->GetAxis(vtkAxis::BOTTOM)->GetBehavior() == vtkAxis::FIXED;
}

void PoincareChart::holdRanges() {
  for (int a : {vtkAxis::BOTTOM, vtkAxis::LEFT})
    chart_->GetAxis(a)->SetBehavior(vtkAxis::FIXED);
}

void PoincareChart::fitToData() {
  // the bounds of the points drawn (a thinned series keeps its extremes), read from the plots' tables: the
  // axes' own automatic bounds are only recomputed in the next frame
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (vtkIdType i = 0; i < chart_->GetNumberOfPlots(); ++i) {
    vtkTable* t = chart_->GetPlot(i)->GetInput();
    auto* xs = t ? vtkDoubleArray::SafeDownCast(t->GetColumn(0)) : nullptr;
    auto* ys = t ? vtkDoubleArray::SafeDownCast(t->GetColumn(1)) : nullptr;
    if (!xs || !ys) continue;
    for (vtkIdType r = 0; r < std::min(xs->GetNumberOfValues(), ys->GetNumberOfValues()); ++r) {
      const double x = xs->GetValue(r), y = ys->GetValue(r);
      if (!std::isfinite(x) || !std::isfinite(y)) continue;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  }
  if (!(x0 <= x1 && y0 <= y1)) { // nothing drawn: the axes follow the data to come
    for (int a : {vtkAxis::BOTTOM, vtkAxis::LEFT})
      chart_->GetAxis(a)->SetBehavior(vtkAxis::AUTO);
    return;
  }
  // a margin of 3 % (a point on the edge stays visible); a single value gets a unit range
  const auto pad = [](double& lo, double& hi) {
    const double m = hi > lo ? 0.03 * (hi - lo) : 0.5 * std::max(1.0, std::abs(lo));
    lo -= m, hi += m;
  };
  pad(x0, x1), pad(y0, y1);
  setRanges(x0, x1, y0, y1);
}

void PoincareChart::setSeries(int index, const std::vector<double>& x, const std::vector<double>& y) {
  if (vtkPlot* plot = chart_->GetPlot(index)) {
    setPoints(plot, index, x, y);
    chart_->RecalculateBounds();
  }
}

void PoincareChart::setColour(int index, const Rgb& c) {
  if (vtkPlot* plot = chart_->GetPlot(index))
    plot->SetColor(static_cast<unsigned char>(255 * c[0]), static_cast<unsigned char>(255 * c[1]),
                   static_cast<unsigned char>(255 * c[2]), 255);
}

void PoincareChart::clear() {
  chart_->ClearPlots();
  large_.clear();
  markers_.clear();
  for (int a : {vtkAxis::BOTTOM, vtkAxis::LEFT}) // ranges follow the next data again
    chart_->GetAxis(a)->SetBehavior(vtkAxis::AUTO);
  selected_ = -1;
}

bool PoincareChart::changedSincePainted() const {
  return view_->GetScene()->GetDirty();
}

void PoincareChart::thinLargeSeries() {
  if (large_.empty()) return;
  vtkAxis* ax = chart_->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* ay = chart_->GetAxis(vtkAxis::LEFT);
  // the ranges this frame draws: fixed ones are the axes'; automatic ones follow the data, and the axes are
  // only rescaled later in the frame (the first frame, all a headless picture has, would see the ranges of
  // before the data and drop every point outside them)
  std::array<double, 4> range{ax->GetMinimum(), ax->GetMaximum(), ay->GetMinimum(), ay->GetMaximum()};
  const auto follow = [&](int axis, bool fixed) {
    if (fixed) return;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& s : large_)
      for (std::size_t k : s.extremes) {
        const double v = axis == 0 ? s.x[k] : s.y[k];
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
      }
    if (hi > lo) range[2 * axis] = lo, range[2 * axis + 1] = hi;
  };
  follow(0, ax->GetBehavior() == vtkAxis::FIXED);
  follow(1, ay->GetBehavior() == vtkAxis::FIXED);
  const int* p1 = chart_->GetPoint1();
  const int* p2 = chart_->GetPoint2();
  int w = p2[0] - p1[0], h = p2[1] - p1[1];
  if (w <= 0 || h <= 0) { // not laid out yet: the window's size
    const int* size = view_->GetRenderWindow()->GetSize();
    w = size[0], h = size[1];
  }
  const std::array<double, 7> key = {range[0],  range[1],  range[2],   range[3],
                                     double(w), double(h), markerSize_};
  const double cell = std::max(1.0f, markerSize_ / 2); // pixels per cell: half a marker keeps the coverage
  const int nx = std::max(1, static_cast<int>(w / cell)), ny = std::max(1, static_cast<int>(h / cell));
  const double x0 = key[0], sx = nx / (key[1] - key[0]), y0 = key[2], sy = ny / (key[3] - key[2]);
  for (auto& s : large_) {
    if (s.grid != key) { // other ranges or another size: thinned again from the first point
      s.grid = key;
      s.taken.assign(std::size_t(nx) * ny, 0);
      s.kx.clear(), s.ky.clear();
      s.thinned = 0;
    } else if (s.thinned == s.x.size()) {
      continue; // nothing new
    }
    // only the points added since the last frame (a map filling), against the cells already taken
    for (std::size_t k = s.thinned; k < s.x.size(); ++k) {
      const double i = (s.x[k] - x0) * sx, j = (s.y[k] - y0) * sy;
      if (!(i >= 0 && i < nx && j >= 0 && j < ny)) continue;
      auto& t = s.taken[std::size_t(j) * nx + std::size_t(i)];
      if (!t) t = 1, s.kx.push_back(s.x[k]), s.ky.push_back(s.y[k]);
    }
    s.thinned = s.x.size();
    std::vector<double> kx = s.kx, ky = s.ky;
    for (std::size_t k : s.extremes) // the data's bounds stay those of every point
      kx.push_back(s.x[k]), ky.push_back(s.y[k]);
    s.plot->SetInputData(tableOf(kx, ky, s.index), 0, 1);
  }
}

bool PoincareChart::toChart(double px, double py, double& x, double& y) const {
  const int* p1 = chart_->GetPoint1(); // the plot area's corners in scene pixels
  const int* p2 = chart_->GetPoint2();
  const double ax0 = p1[0], ay0 = p1[1], ax1 = p2[0], ay1 = p2[1];
  if (px < ax0 || px > ax1 || py < ay0 || py > ay1 || ax1 == ax0 || ay1 == ay0) return false;
  vtkAxis* ax = chart_->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* ay = chart_->GetAxis(vtkAxis::LEFT);
  x = ax->GetMinimum() + (px - ax0) / (ax1 - ax0) * (ax->GetMaximum() - ax->GetMinimum());
  y = ay->GetMinimum() + (py - ay0) / (ay1 - ay0) * (ay->GetMaximum() - ay->GetMinimum());
  return true;
}

bool PoincareChart::toPixels(double x, double y, double& px, double& py) const {
  const int* p1 = chart_->GetPoint1();
  const int* p2 = chart_->GetPoint2();
  vtkAxis* ax = chart_->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* ay = chart_->GetAxis(vtkAxis::LEFT);
  const double wx = ax->GetMaximum() - ax->GetMinimum(), wy = ay->GetMaximum() - ay->GetMinimum();
  if (wx == 0 || wy == 0) return false;
  px = p1[0] + (x - ax->GetMinimum()) / wx * (p2[0] - p1[0]);
  py = p1[1] + (y - ay->GetMinimum()) / wy * (p2[1] - p1[1]);
  return px >= p1[0] && px <= p2[0] && py >= p1[1] && py <= p2[1];
}

void PoincareChart::select(int index) {
  for (vtkIdType i = 0; i < chart_->GetNumberOfPlots(); ++i)
    if (auto* points = vtkPlotPoints::SafeDownCast(chart_->GetPlot(i)))
      points->SetMarkerSize(std::find(markers_.begin(), markers_.end(), i) != markers_.end() ? 5 * markerSize_
                            : i == index                                                     ? 2 * markerSize_
                                                                                             : markerSize_);
  selected_ = index;
}

void PoincareChart::setMarkerSize(float size) {
  markerSize_ = size; // (the thinning's cells follow it: part of each series' grid key)
  select(selected_);
}

void PoincareChart::attach(vtkRenderWindow* window) {
  view_->SetRenderWindow(window);
  if (!equalAspect_) return;
  // equal units per pixel: widen the range that is short for its side of the window (the margins are
  // about the same on both axes, so the window's aspect stands for the plot area's)
  chart_->RecalculateBounds();
  vtkAxis* ax = chart_->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* ay = chart_->GetAxis(vtkAxis::LEFT);
  const int* size = window->GetSize();
  const double w = std::max(1, size[0] - 90), h = std::max(1, size[1] - 70);
  double x0 = ax->GetMinimum(), x1 = ax->GetMaximum(), y0 = ay->GetMinimum(), y1 = ay->GetMaximum();
  const double perX = (x1 - x0) / w, perY = (y1 - y0) / h;
  if (perX > perY) {
    const double c = (y0 + y1) / 2, half = perX * h / 2;
    y0 = c - half, y1 = c + half;
  } else {
    const double c = (x0 + x1) / 2, half = perY * w / 2;
    x0 = c - half, x1 = c + half;
  }
  setRanges(x0, x1, y0, y1);
}

void PoincareChart::writeCsv(std::ostream& out) const {
  out << "series," << chart_->GetAxis(vtkAxis::BOTTOM)->GetTitle() << ","
      << chart_->GetAxis(vtkAxis::LEFT)->GetTitle() << "\n";
  char row[96];
  for (vtkIdType i = 0; i < chart_->GetNumberOfPlots(); ++i) {
    const auto large =
        std::find_if(large_.begin(), large_.end(), [&](const LargeSeries& s) { return s.index == i; });
    if (large != large_.end()) { // every point, not the ones drawn
      for (std::size_t k = 0; k < large->x.size(); ++k) {
        std::snprintf(row, sizeof row, "%lld,%.17g,%.17g\n", static_cast<long long>(i), large->x[k],
                      large->y[k]);
        out << row;
      }
      continue;
    }
    vtkTable* t = chart_->GetPlot(i)->GetInput();
    if (!t || t->GetNumberOfColumns() < 2) continue; // a heat map has no rows
    for (vtkIdType r = 0; r < t->GetNumberOfRows(); ++r) {
      std::snprintf(row, sizeof row, "%lld,%.17g,%.17g\n", static_cast<long long>(i),
                    t->GetValue(r, 0).ToDouble(), t->GetValue(r, 1).ToDouble());
      out << row;
    }
  }
}

} // namespace rv
