#include "render/objects/PlaneObject.h"

#include "render/Textures.h"

#include <cmath>
#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

namespace rv {

PlaneObject::PlaneObject(std::string name, double cell, double halfSize)
    : VisualObject(std::move(name)), cell_(cell), half_(halfSize) {
  quad_ = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetNumberOfPoints(4);
  quad_->SetPoints(pts);
  vtkNew<vtkFloatArray> tc;
  tc->SetNumberOfComponents(2);
  tc->SetNumberOfTuples(4);
  quad_->GetPointData()->SetTCoords(tc);
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  for (int i = 0; i < 4; ++i)
    normals->InsertNextTuple3(0, 0, 1);
  quad_->GetPointData()->SetNormals(normals);
  vtkNew<vtkCellArray> polys;
  const vtkIdType ids[4] = {0, 1, 2, 3};
  polys->InsertNextCell(4, ids);
  quad_->SetPolys(polys);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(quad_);
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper);
  // unlit: a flat plane under directional lights is one shade anyway, and lighting it costs a third of the
  // frame on software GL (tests/bench)
  actor_->GetProperty()->LightingOff();
  place(0, 0);
}

void PlaneObject::attach(vtkRenderer* renderer) {
  renderer->AddActor(actor_);
}

void PlaneObject::apply(const ObjectOptions& o) {
  const Rgb light = o.color.value_or(Rgb{0.92, 0.92, 0.89});
  const Rgb dark = {light[0] * 0.9, light[1] * 0.9, light[2] * 0.9};
  // "grid" (and "both") draw the plane's grid lines over the floor, on a plain sheet: a wireframe of the one
  // quad would be its four edges, the floor gone
  const bool grid = o.style != SurfaceStyle::Fill;
  actor_->SetTexture(textureFor(o, [&] {
    return makeCheckerTexture(light, grid ? light : dark, {0.45, 0.45, 0.55});
  }));
  const Rgb base = actor_->GetTexture() ? Rgb{1, 1, 1} : light; // a texture carries the colour itself
  actor_->GetProperty()->SetColor(base[0], base[1], base[2]);
  actor_->SetVisibility(o.enabled);
  actor_->GetProperty()->SetOpacity(o.opacity.value_or(1.0));
}

void PlaneObject::show(const FrameState& s) {
  if (!s.pose) return;
  // move only when the body has gone a quarter of the way to the edge
  if (std::abs(s.pose->contact[0] - cx_) > 0.25 * half_ || std::abs(s.pose->contact[1] - cy_) > 0.25 * half_)
    place(s.pose->contact[0], s.pose->contact[1]);
}

void PlaneObject::place(double cx, double cy) {
  const double two = 2 * cell_; // one texture repeat holds 2 x 2 cells
  cx_ = std::round(cx / two) * two, cy_ = std::round(cy / two) * two;
  const double xs[4] = {cx_ - half_, cx_ + half_, cx_ + half_, cx_ - half_};
  const double ys[4] = {cy_ - half_, cy_ - half_, cy_ + half_, cy_ + half_};
  auto* tc = quad_->GetPointData()->GetTCoords();
  for (int i = 0; i < 4; ++i) {
    quad_->GetPoints()->SetPoint(i, xs[i], ys[i], 0);
    tc->SetTuple2(i, xs[i] / two, ys[i] / two);
  }
  quad_->GetPoints()->Modified();
  tc->Modified();
  quad_->Modified();
}

} // namespace rv
