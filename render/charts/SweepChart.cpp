#include "render/charts/SweepChart.h"

#include "render/charts/PoincareChart.h"
#include "render/charts/VectorPictures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vtkAxis.h>
#include <vtkChartHistogram2D.h>
#include <vtkColorLegend.h>
#include <vtkColorTransferFunction.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkPlot.h>
#include <vtkPointData.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

namespace rv {

namespace {

// perceptually uniform, readable in grey and by colour-blind readers (matplotlib's viridis, 5 stops)
constexpr double kViridis[5][3] = {{0.267, 0.005, 0.329},
                                   {0.230, 0.322, 0.546},
                                   {0.128, 0.567, 0.551},
                                   {0.369, 0.789, 0.383},
                                   {0.993, 0.906, 0.144}};

class HeatMapChart final : public Chart {
public:
  explicit HeatMapChart(const SweepChartData& d) : data_(d) {
    view_ = vtkSmartPointer<vtkContextView>::New();
    view_->GetRenderer()->SetBackground(1, 1, 1);
    chart_ = vtkSmartPointer<CellsChart>::New(); // its cells and colour bar reach vector figures
    view_->GetScene()->AddItem(chart_);
    const int nx = d.counts[0], ny = d.counts[1];
    const std::size_t stride = std::max<std::size_t>(1, d.columns.size());
    vtkNew<vtkImageData> image;
    image->SetDimensions(nx, ny, 1);
    // cells centred on the grid values (a one-point axis gets a unit-wide cell)
    const double dx = nx > 1 ? (d.maxs[0] - d.mins[0]) / (nx - 1) : 1,
                 dy = ny > 1 ? (d.maxs[1] - d.mins[1]) / (ny - 1) : 1;
    image->SetOrigin(d.mins[0] - dx / 2, d.mins[1] - dy / 2, 0);
    image->SetSpacing(dx, dy, 1);
    vtkNew<vtkDoubleArray> scalars;
    scalars->SetNumberOfValues(static_cast<vtkIdType>(nx) * ny);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (vtkIdType i = 0; i < scalars->GetNumberOfValues(); ++i) {
      const std::size_t at = static_cast<std::size_t>(i) * stride;
      const double v = at < d.values.size() ? d.values[at] : std::numeric_limits<double>::quiet_NaN();
      scalars->SetValue(i, v);
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    image->GetPointData()->SetScalars(scalars);
    if (!std::isfinite(lo)) lo = 0, hi = 1;
    if (!(hi > lo)) hi = lo + 1;
    vtkNew<vtkColorTransferFunction> colours;
    for (int k = 0; k < 5; ++k)
      colours->AddRGBPoint(lo + (hi - lo) * k / 4, kViridis[k][0], kViridis[k][1], kViridis[k][2]);
    colours->SetNanColor(0.85, 0.85, 0.85); // failed points: light grey
    colours->Build();
    chart_->SetInputData(image);
    chart_->SetTransferFunction(colours);
    chart_->GetAxis(vtkAxis::BOTTOM)->SetTitle(d.axes[0]);
    chart_->GetAxis(vtkAxis::LEFT)->SetTitle(d.axes[1]);
    for (int a : {vtkAxis::BOTTOM, vtkAxis::LEFT}) {
      chart_->GetAxis(a)->GetTitleProperties()->SetFontSize(16);
      chart_->GetAxis(a)->GetLabelProperties()->SetFontSize(13);
    }
    if (auto* legend = vtkColorLegend::SafeDownCast(chart_->GetLegend()))
      legend->SetTitle(d.columns.empty() ? std::string() : d.columns[0]);
    chart_->SetTitle(d.title);
    chart_->GetTitleProperties()->SetFontSize(16);
    // the curves over it, white under black so they show on every colour of the map
    for (const auto& o : d.overlays) {
      vtkNew<vtkTable> table;
      vtkNew<vtkDoubleArray> xs, ys;
      xs->SetName("x"), ys->SetName(o.name.empty() ? "curve" : o.name.c_str());
      for (std::size_t i = 0; i < std::min(o.x.size(), o.y.size()); ++i)
        xs->InsertNextValue(o.x[i]), ys->InsertNextValue(o.y[i]);
      table->AddColumn(xs), table->AddColumn(ys);
      for (const auto& [width, grey] : {std::pair{5.0f, 255}, std::pair{2.5f, 0}}) {
        vtkPlot* line = chart_->AddPlot(vtkChart::LINE);
        line->SetInputData(table, 0, 1);
        line->SetColor(static_cast<unsigned char>(grey), static_cast<unsigned char>(grey),
                       static_cast<unsigned char>(grey), 255);
        line->SetWidth(width);
      }
    }
  }
  void attach(vtkRenderWindow* window) override { view_->SetRenderWindow(window); }
  bool toChart(double px, double py, double& x, double& y) const override {
    const int* p1 = chart_->GetPoint1(); // the plot area's corners in scene pixels
    const int* p2 = chart_->GetPoint2();
    if (px < p1[0] || px > p2[0] || py < p1[1] || py > p2[1] || p1[0] == p2[0] || p1[1] == p2[1])
      return false;
    vtkAxis* ax = chart_->GetAxis(vtkAxis::BOTTOM);
    vtkAxis* ay = chart_->GetAxis(vtkAxis::LEFT);
    x = ax->GetMinimum() + (px - p1[0]) / (p2[0] - p1[0]) * (ax->GetMaximum() - ax->GetMinimum());
    y = ay->GetMinimum() + (py - p1[1]) / (p2[1] - p1[1]) * (ay->GetMaximum() - ay->GetMinimum());
    return true;
  }
  void writeCsv(std::ostream& out) const override {
    out << data_.axes[0] << "," << data_.axes[1] << ","
        << (data_.columns.empty() ? "value" : data_.columns[0]) << "\n";
    const std::size_t stride = std::max<std::size_t>(1, data_.columns.size());
    char row[128];
    for (int j = 0; j < data_.counts[1]; ++j)
      for (int i = 0; i < data_.counts[0]; ++i) {
        const std::size_t at = (static_cast<std::size_t>(j) * data_.counts[0] + i) * stride;
        const auto axis = [&](int a, int k) {
          return data_.counts[a] > 1
                     ? data_.mins[a] + (data_.maxs[a] - data_.mins[a]) * k / (data_.counts[a] - 1)
                     : data_.mins[a];
        };
        std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g\n", axis(0, i), axis(1, j),
                      at < data_.values.size() ? data_.values[at] : std::nan(""));
        out << row;
      }
  }

private:
  SweepChartData data_;
  vtkSmartPointer<vtkContextView> view_;
  vtkSmartPointer<vtkChartHistogram2D> chart_;
};

} // namespace

std::unique_ptr<Chart> makeSweepChart(const SweepChartData& d) {
  if (d.axes.size() == 2 && !d.orbit) return std::make_unique<HeatMapChart>(d);
  // one axis (or an orbit diagram): over the first axis, the other axes' points side by side
  const std::size_t stride = std::max<std::size_t>(1, d.columns.size());
  const long points = static_cast<long>(d.values.size() / stride);
  const int nx = d.counts[0];
  const auto xAt = [&](long p) {
    const int i = static_cast<int>(p % nx);
    return nx > 1 ? d.mins[0] + (d.maxs[0] - d.mins[0]) * i / (nx - 1) : d.mins[0];
  };
  std::string yTitle = d.columns.empty() ? "" : d.columns[0];
  if (d.orbit) yTitle = yTitle.substr(0, yTitle.rfind('.')); // "x.1" ... "x.N": the coordinate x
  auto chart = std::make_unique<PoincareChart>(d.axes[0], yTitle);
  if (d.orbit) {
    std::vector<double> x, y;
    for (long p = 0; p < points; ++p)
      for (std::size_t c = 0; c < stride; ++c)
        if (const double v = d.values[static_cast<std::size_t>(p) * stride + c]; std::isfinite(v))
          x.push_back(xAt(p)), y.push_back(v);
    chart->setMarkerSize(2);
    chart->addSeries(x, y, {0.1, 0.1, 0.35});
    return chart;
  }
  // a line per value of the second axis (if any)
  const int lines = points / std::max(1, nx) > 0 ? static_cast<int>(points / nx) : 1;
  for (int l = 0; l < lines; ++l) {
    std::vector<double> x, y;
    for (int i = 0; i < nx; ++i) {
      const long p = static_cast<long>(l) * nx + i;
      x.push_back(xAt(p));
      y.push_back(d.values[static_cast<std::size_t>(p) * stride]);
    }
    chart->addCurve(x, y, seriesColour(l));
    chart->addSeries(x, y, seriesColour(l));
  }
  return chart;
}

} // namespace rv
