#include "render/charts/PoincareChart.h"

#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

namespace rv {

Rgb seriesColor(int i) {
  static const Rgb palette[] = {{0.12, 0.38, 0.85}, {0.85, 0.25, 0.15}, {0.15, 0.6, 0.25},  {0.6, 0.25, 0.7},
                                {0.9, 0.55, 0.1},   {0.1, 0.6, 0.65},   {0.45, 0.45, 0.45}, {0.7, 0.55, 0.2}};
  return palette[i % 8];
}

PoincareChart::PoincareChart(std::string xTitle, std::string yTitle) {
  view_ = vtkSmartPointer<vtkContextView>::New();
  view_->GetRenderer()->SetBackground(1, 1, 1);
  chart_ = vtkSmartPointer<vtkChartXY>::New();
  view_->GetScene()->AddItem(chart_);
  chart_->GetAxis(vtkAxis::BOTTOM)->SetTitle(xTitle);
  chart_->GetAxis(vtkAxis::LEFT)->SetTitle(yTitle);
  for (int a : {vtkAxis::BOTTOM, vtkAxis::LEFT}) {
    chart_->GetAxis(a)->GetTitleProperties()->SetFontSize(16);
    chart_->GetAxis(a)->GetLabelProperties()->SetFontSize(13);
  }
}

PoincareChart::~PoincareChart() = default;

vtkChartXY* PoincareChart::chart() const {
  return chart_;
}

int PoincareChart::addSeries(const std::vector<double>& x, const std::vector<double>& y, const Rgb& c) {
  vtkNew<vtkTable> table;
  vtkNew<vtkDoubleArray> xs, ys;
  xs->SetName("x");
  ys->SetName(("y" + std::to_string(chart_->GetNumberOfPlots())).c_str());
  table->AddColumn(xs);
  table->AddColumn(ys);
  table->SetNumberOfRows(static_cast<vtkIdType>(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i) {
    table->SetValue(static_cast<vtkIdType>(i), 0, x[i]);
    table->SetValue(static_cast<vtkIdType>(i), 1, y[i]);
  }
  vtkPlot* plot = chart_->AddPlot(vtkChart::POINTS);
  plot->SetInputData(table, 0, 1);
  plot->SetColor(static_cast<unsigned char>(255 * c[0]), static_cast<unsigned char>(255 * c[1]),
                 static_cast<unsigned char>(255 * c[2]), 255);
  if (auto* points = vtkPlotPoints::SafeDownCast(plot)) {
    points->SetMarkerStyle(vtkPlotPoints::CIRCLE);
    points->SetMarkerSize(3);
  }
  return static_cast<int>(chart_->GetNumberOfPlots()) - 1;
}

void PoincareChart::select(int index) {
  for (vtkIdType i = 0; i < chart_->GetNumberOfPlots(); ++i)
    if (auto* points = vtkPlotPoints::SafeDownCast(chart_->GetPlot(i)))
      points->SetMarkerSize(i == index ? 6 : 3);
  selected_ = index;
}

void PoincareChart::attach(vtkRenderWindow* window) {
  view_->SetRenderWindow(window);
}

} // namespace rv
