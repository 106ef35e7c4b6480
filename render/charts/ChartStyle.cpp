#include "render/charts/ChartStyle.h"

#include "dynamics/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vtkActor2D.h>
#include <vtkActor2DCollection.h>
#include <vtkActorCollection.h>
#include <vtkAxis.h>
#include <vtkAxisActor.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkCoordinate.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkPropCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkStringArray.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

namespace rv {

namespace {

// A 3.5-inch column at 300 dpi: 8-9 pt type is 33-38 px, a 0.6 pt line 2.5 px.
constexpr int kPaperWidth = 1050, kPaperHeight = 788;
constexpr double kPaperPens = 2.5;
constexpr double kPaperMarkers = 1.5; // a map's thousands of points stay points

// The print dress: black text, axes and ticks at a column's type sizes, a faint grid, pens and layout
// distances grown for 300 dpi.
void dressForPaper(vtkChartXY* chart) {
  const auto text = [](vtkTextProperty* t, int size) {
    if (t) t->SetFontSize(size), t->SetColor(0, 0, 0);
  };
  text(chart->GetTitleProperties(), 38);
  chart->SetHiddenAxisBorder(static_cast<int>(std::lround(chart->GetHiddenAxisBorder() * kPaperPens)));
  for (int a = 0; a < 4; ++a) {
    vtkAxis* axis = chart->GetAxis(a);
    text(axis->GetTitleProperties(), 35);
    text(axis->GetLabelProperties(), 33);
    axis->GetPen()->SetColor(0, 0, 0);
    axis->GetPen()->SetWidth(static_cast<float>(std::max(1.0, axis->GetPen()->GetWidth() * kPaperPens)));
    axis->GetGridPen()->SetColor(225, 225, 225);
    axis->SetTickLength(static_cast<float>(axis->GetTickLength() * 2));
    axis->SetLabelOffset(static_cast<float>(axis->GetLabelOffset() * 2));
    int margins[2];
    axis->GetMargins(margins);
    axis->SetMargins(2 * margins[0], 2 * margins[1]);
  }
  if (vtkChartLegend* legend = chart->GetLegend()) {
    text(legend->GetLabelProperties(), 31);
    legend->SetSymbolWidth(static_cast<int>(std::lround(legend->GetSymbolWidth() * kPaperPens)));
    legend->SetPadding(static_cast<int>(std::lround(legend->GetPadding() * kPaperPens)));
  }
  for (vtkIdType i = 0; i < chart->GetNumberOfPlots(); ++i) {
    vtkPlot* plot = chart->GetPlot(i);
    if (vtkPen* pen = plot->GetPen()) pen->SetWidth(static_cast<float>(pen->GetWidth() * kPaperPens));
    if (auto* points = vtkPlotPoints::SafeDownCast(plot))
      points->SetMarkerSize(static_cast<float>(points->GetMarkerSize() * kPaperMarkers));
  }
}

// Every pixel distance x factor (or / factor, `back`: exactly undoing it): type, pens, markers, ticks,
// offsets, margins, borders.
void scaleChart(vtkChartXY* chart, int factor, bool back = false) {
  const auto by = [factor, back](auto v) { return static_cast<decltype(v)>(back ? v / factor : v * factor); };
  const auto text = [&by](vtkTextProperty* t) {
    if (t) t->SetFontSize(by(t->GetFontSize()));
  };
  text(chart->GetTitleProperties());
  chart->SetHiddenAxisBorder(by(chart->GetHiddenAxisBorder()));
  for (int a = 0; a < 4; ++a) {
    vtkAxis* axis = chart->GetAxis(a);
    text(axis->GetTitleProperties());
    text(axis->GetLabelProperties());
    axis->GetPen()->SetWidth(by(axis->GetPen()->GetWidth()));
    axis->GetGridPen()->SetWidth(by(axis->GetGridPen()->GetWidth()));
    axis->SetTickLength(by(axis->GetTickLength()));
    axis->SetLabelOffset(by(axis->GetLabelOffset()));
    int margins[2];
    axis->GetMargins(margins);
    axis->SetMargins(by(margins[0]), by(margins[1]));
  }
  if (vtkChartLegend* legend = chart->GetLegend()) {
    text(legend->GetLabelProperties());
    legend->SetSymbolWidth(by(legend->GetSymbolWidth()));
    legend->SetPadding(by(legend->GetPadding()));
  }
  for (vtkIdType i = 0; i < chart->GetNumberOfPlots(); ++i) {
    vtkPlot* plot = chart->GetPlot(i);
    if (vtkPen* pen = plot->GetPen()) pen->SetWidth(by(pen->GetWidth()));
    if (auto* points = vtkPlotPoints::SafeDownCast(plot)) points->SetMarkerSize(by(points->GetMarkerSize()));
  }
}

// The ticks the chart chose at its size, kept: a scaled picture has the same ticks and labels. The axes
// frozen go to `frozen` when given.
void freezeTicks(vtkChartXY* chart, std::vector<vtkAxis*>* frozen = nullptr) {
  for (int a = 0; a < 4; ++a) {
    vtkAxis* axis = chart->GetAxis(a);
    if (!axis->GetVisible() || !axis->GetTickPositions()) continue;
    vtkNew<vtkDoubleArray> positions;
    positions->DeepCopy(axis->GetTickPositions());
    vtkNew<vtkStringArray> labels;
    labels->DeepCopy(axis->GetTickLabels());
    axis->SetCustomTickPositions(positions, labels);
    if (frozen) frozen->push_back(axis);
  }
}

void forEachRenderer(vtkRenderWindow* window, const std::function<void(vtkRenderer*)>& f) {
  vtkRendererCollection* renderers = window->GetRenderers();
  renderers->InitTraversal();
  while (vtkRenderer* renderer = renderers->GetNextItem())
    f(renderer);
}

void forEachChart(vtkRenderWindow* window, const std::function<void(vtkChartXY*)>& f) {
  forEachRenderer(window, [&f](vtkRenderer* renderer) {
    vtkPropCollection* props = renderer->GetViewProps();
    props->InitTraversal();
    while (vtkProp* prop = props->GetNextProp()) {
      auto* actor = vtkContextActor::SafeDownCast(prop);
      if (!actor || !actor->GetScene()) continue;
      vtkContextScene* scene = actor->GetScene();
      for (unsigned i = 0; i < scene->GetNumberOfItems(); ++i)
        if (auto* chart = vtkChartXY::SafeDownCast(scene->GetItem(i))) f(chart);
    }
  });
}

} // namespace

ChartStyle chartStyle(const std::string& name, int scale, const std::string& what) {
  ChartStyle s;
  if (name == "paper")
    s.paper = true;
  else if (name != "screen")
    throw InputError(what + " " + name + ": expected screen or paper");
  if (scale < 1 || scale > 8) throw InputError("scale " + std::to_string(scale) + ": must be 1..8");
  s.scale = scale;
  return s;
}

std::pair<int, int> figureSize(const ChartStyle& style, std::pair<int, int> size, bool sizeGiven) {
  if (style.paper && !sizeGiven) size = {kPaperWidth, kPaperHeight};
  return {size.first * style.scale, size.second * style.scale};
}

void styleCharts(vtkRenderWindow* window, const ChartStyle& style) {
  if (!style.paper && style.scale == 1) return;
  // the ticks are laid out as on a screen figure of the same proportions (VTK picks them by pixel length,
  // not by the type's size), then kept while the type, pens and pixels grow
  const double layout = (style.paper ? kPaperPens : 1.0) * style.scale;
  const int width = window->GetSize()[0], height = window->GetSize()[1];
  window->SetSize(std::max(16, static_cast<int>(width / layout)),
                  std::max(16, static_cast<int>(height / layout)));
  window->Render();
  forEachChart(window, [](vtkChartXY* chart) { freezeTicks(chart); });
  window->SetSize(width, height);
  if (style.paper) {
    forEachRenderer(window, [](vtkRenderer* r) { r->SetBackground(1, 1, 1), r->GradientBackgroundOff(); });
    forEachChart(window, dressForPaper);
  }
  if (style.scale > 1) forEachChart(window, [&](vtkChartXY* chart) { scaleChart(chart, style.scale); });
}

ScaledPicture::ScaledPicture(vtkRenderWindow* window, int scale) : window_(window), scale_(scale) {
  if (scale_ <= 1) return;
  // the ticks of the last (screen) layout kept: VTK would pick them again by pixel length, finer
  forEachChart(window_, [this](vtkChartXY* chart) {
    freezeTicks(chart, &frozen_);
    scaleChart(chart, scale_);
  });
  // a 3D view's text in display pixels (the time and energy line, the apex view's key): larger and as far
  // from the corner, as the CLI's tiled large pictures have it
  forEachRenderer(window_, [this](vtkRenderer* renderer) {
    vtkActor2DCollection* actors = renderer->GetActors2D();
    actors->InitTraversal();
    while (vtkActor2D* actor = actors->GetNextActor2D()) {
      auto* text = vtkTextActor::SafeDownCast(actor);
      if (!text || text->GetPositionCoordinate()->GetCoordinateSystem() != VTK_DISPLAY) continue;
      const double* at = text->GetPosition();
      texts_.push_back({text, text->GetTextProperty()->GetFontSize(), at[0], at[1]});
      text->GetTextProperty()->SetFontSize(texts_.back().fontSize * scale_);
      text->SetPosition(at[0] * scale_, at[1] * scale_);
    }
    // the scene axes' numbers and titles, screen text too (vtkAxisActor's 2D mode): tiny in a large picture
    vtkActorCollection* props = renderer->GetActors();
    props->InitTraversal();
    while (vtkActor* actor = props->GetNextActor()) {
      auto* axis = vtkAxisActor::SafeDownCast(actor);
      if (!axis || !axis->GetUse2DMode()) continue;
      for (vtkTextProperty* p : {axis->GetLabelTextProperty(), axis->GetTitleTextProperty()}) {
        axisTexts_.push_back({p, p->GetFontSize()});
        p->SetFontSize(p->GetFontSize() * scale_);
      }
      axis->Modified();
    }
  });
}

ScaledPicture::~ScaledPicture() {
  if (scale_ <= 1) return;
  forEachChart(window_, [this](vtkChartXY* chart) { scaleChart(chart, scale_, true); });
  for (vtkAxis* axis : frozen_)
    axis->SetCustomTickPositions(nullptr); // VTK picks them again (no window's chart has ticks of its own)
  for (const auto& t : texts_) {
    t.actor->GetTextProperty()->SetFontSize(t.fontSize);
    t.actor->SetPosition(t.x, t.y);
  }
  for (const auto& [property, size] : axisTexts_)
    property->SetFontSize(size);
}

} // namespace rv
