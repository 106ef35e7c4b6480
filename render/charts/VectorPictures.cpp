#include "render/charts/VectorPictures.h"

#include <algorithm>
#include <cstring>
#include <vtkAxis.h>
#include <vtkBrush.h>
#include <vtkContext2D.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLGL2PSHelper.h>
#include <vtkPen.h>
#include <vtkPointData.h>
#include <vtkTooltipItem.h>

namespace rv {

bool capturingVectorFigure() {
  auto* gl2ps = vtkOpenGLGL2PSHelper::GetInstance();
  return gl2ps && gl2ps->GetActiveState() == vtkOpenGLGL2PSHelper::Capture;
}

long drawPictureAsRectangles(vtkContext2D* painter, const vtkRectf& rect, vtkImageData* picture) {
  if (!picture || !picture->GetPointData()->GetScalars() || picture->GetScalarType() != VTK_UNSIGNED_CHAR)
    return 0;
  int dims[3];
  picture->GetDimensions(dims);
  const int components = picture->GetNumberOfScalarComponents();
  if (dims[0] <= 0 || dims[1] <= 0 || (components != 3 && components != 4)) return 0;
  const auto* px = static_cast<const unsigned char*>(picture->GetScalarPointer());
  const float w = rect.GetWidth() / static_cast<float>(dims[0]),
              h = rect.GetHeight() / static_cast<float>(dims[1]);
  painter->GetPen()->SetLineType(vtkPen::NO_PEN);
  long drawn = 0;
  for (int j = 0; j < dims[1]; ++j)
    for (int i = 0; i < dims[0];) {
      const unsigned char* c = px + (static_cast<std::size_t>(j) * dims[0] + i) * components;
      int run = 1; // the pixels after it of the same colour
      while (i + run < dims[0] &&
             std::memcmp(c, c + static_cast<std::size_t>(run) * components, components) == 0)
        ++run;
      const unsigned char alpha = components == 4 ? c[3] : 255;
      if (alpha > 0) {
        painter->GetBrush()->SetColor(c[0], c[1], c[2], alpha);
        painter->DrawRect(rect.GetX() + w * static_cast<float>(i), rect.GetY() + h * static_cast<float>(j),
                          w * static_cast<float>(run), h);
        ++drawn;
      }
      i += run;
    }
  painter->GetPen()->SetLineType(vtkPen::SOLID_LINE);
  return drawn;
}

vtkStandardNewMacro(CellsPlot);

bool CellsPlot::Paint(vtkContext2D* painter) {
  if (!capturingVectorFigure() || !this->Output) return vtkPlotHistogram2D::Paint(painter);
  if (this->Input) { // placed as vtkPlotHistogram2D::Paint places its picture
    double bounds[4];
    this->GetBounds(bounds);
    this->Position =
        vtkRectf(static_cast<float>(bounds[0]), static_cast<float>(bounds[2]),
                 static_cast<float>(bounds[1] - bounds[0]), static_cast<float>(bounds[3] - bounds[2]));
  }
  drawPictureAsRectangles(painter, this->Position, this->Output);
  return true;
}

vtkStandardNewMacro(VectorColourLegend);

bool VectorColourLegend::Paint(vtkContext2D* painter) {
  if (!capturingVectorFigure()) return vtkColorLegend::Paint(painter);
  if (!this->TransferFunction) return true;
  // as vtkColorLegend::Paint, with the bar as rectangles
  this->GetBoundingRect(painter);
  if (this->DrawBorder) {
    painter->ApplyPen(this->Pen);
    painter->ApplyBrush(this->Brush);
    painter->DrawRect(this->Rect.GetX(), this->Rect.GetY(), this->Rect.GetWidth(), this->Rect.GetHeight());
  }
  drawPictureAsRectangles(painter, this->Position, this->ImageData);
  this->Axis->Paint(painter);
  return true;
}

vtkStandardNewMacro(CellsChart);

CellsChart::CellsChart() {
  // vtkChartHistogram2D's own plot and legend, replaced by the ones that reach vector figures
  this->RemovePlotInstance(this->Histogram);
  this->Histogram = vtkSmartPointer<CellsPlot>::New();
  this->AddPlot(this->Histogram);
  this->RemoveItem(this->Legend);
  this->Legend = vtkSmartPointer<VectorColourLegend>::New();
  this->AddItem(this->Legend);
  this->RemoveItem(this->Tooltip); // painted last, as the base class has it
  this->AddItem(this->Tooltip);
}

} // namespace rv
