#include "render/charts/RasterPointsPlot.h"

#include <cmath>
#include <vector>
#include <vtkContext2D.h>
#include <vtkContextScene.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLGL2PSHelper.h>
#include <vtkPen.h>
#include <vtkPointData.h>
#include <vtkPoints2D.h>
#include <vtkRect.h>
#include <vtkTransform2D.h>
#include <vtkUnsignedCharArray.h>

namespace rv {

vtkStandardNewMacro(RasterPointsPlot);

bool RasterPointsPlot::Paint(vtkContext2D* painter) {
  const vtkIdType n = this->Points ? this->Points->GetNumberOfPoints() : 0;
  const bool coloured = this->ScalarVisibility && this->Colors;
  const bool bad = this->BadPoints && this->BadPoints->GetNumberOfTuples() > 0;
  auto* scene = this->GetScene();
  if (!this->Visible || n == 0 || coloured || bad || !scene ||
      (this->MarkerStyle != vtkPlotPoints::CIRCLE && this->MarkerStyle != vtkPlotPoints::SQUARE))
    return vtkPlotPoints::Paint(painter);
  // a vector figure (GL2PS): its SVG cannot hold the raster picture, and a marker drawn as a point is a small
  // circle there (a wedge path is seven times the bytes): 10^5 points stay a few MB
  if (auto* gl2ps = vtkOpenGLGL2PSHelper::GetInstance();
      gl2ps && gl2ps->GetActiveState() != vtkOpenGLGL2PSHelper::Inactive) {
    painter->GetPen()->SetColor(this->Pen->GetColor());
    painter->GetPen()->SetWidth(std::max(1.0f, this->MarkerSize));
    painter->DrawPoints(static_cast<float*>(this->Points->GetVoidPointer(0)), static_cast<int>(n));
    return true;
  }
  const int w = scene->GetViewWidth(), h = scene->GetViewHeight();
  if (w <= 0 || h <= 0) return vtkPlotPoints::Paint(painter);

  // the pixels a marker covers around the pixel its centre falls in: a square of its size, or a disk
  const double size = std::max(1.0f, this->MarkerSize), r = 0.5 * size;
  const int half = static_cast<int>(std::floor(r));
  std::vector<std::pair<int, int>> stencil;
  for (int dy = -half; dy <= half; ++dy)
    for (int dx = -half; dx <= half; ++dx)
      if (this->MarkerStyle == vtkPlotPoints::SQUARE || dx * dx + dy * dy <= r * r + 0.25)
        stencil.emplace_back(dx, dy);

  unsigned char rgba[4];
  this->Pen->GetColor(rgba); // the plot's colour (vtkPlot::SetColor), as vtkPlotPoints' markers take it
  const unsigned char alpha = this->Pen->GetOpacity();
  int dims[3];
  image_->GetDimensions(dims);
  if (dims[0] != w || dims[1] != h || !image_->GetPointData()->GetScalars()) {
    image_->SetDimensions(w, h, 1);
    image_->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  }
  auto* px = static_cast<unsigned char*>(image_->GetScalarPointer());
  for (std::size_t k = 0; k < std::size_t(w) * h; ++k) // the colour everywhere, the markers in alpha
    px[4 * k] = rgba[0], px[4 * k + 1] = rgba[1], px[4 * k + 2] = rgba[2], px[4 * k + 3] = 0;
  // data -> scene pixels, as the painter would place the markers
  const double* m = painter->GetTransform()->GetMatrix()->GetData();
  const auto* xy = static_cast<const float*>(this->Points->GetVoidPointer(0));
  for (vtkIdType k = 0; k < n; ++k) {
    const double x = xy[2 * k], y = xy[2 * k + 1];
    const int cx = static_cast<int>(std::floor(m[0] * x + m[1] * y + m[2]));
    const int cy = static_cast<int>(std::floor(m[3] * x + m[4] * y + m[5]));
    for (const auto& [dx, dy] : stencil) {
      const int ix = cx + dx, iy = cy + dy;
      if (ix >= 0 && iy >= 0 && ix < w && iy < h) px[(std::size_t(iy) * w + ix) * 4 + 3] = alpha;
    }
  }
  // the picture in scene pixels: the painter's data transform set aside for the one quad (the chart's clip
  // rectangle still applies)
  painter->PushMatrix();
  vtkNew<vtkTransform2D> identity;
  painter->SetTransform(identity);
  image_->Modified(); // its pixels were rewritten in place
  painter->DrawImage(vtkRectf(0, 0, static_cast<float>(w), static_cast<float>(h)), image_);
  painter->PopMatrix();
  return true;
}

} // namespace rv
