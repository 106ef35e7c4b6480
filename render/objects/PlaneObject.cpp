#include "render/objects/PlaneObject.h"

#include "render/Textures.h"

#include <array>
#include <cmath>
#include <utility>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
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

PlaneObject::~PlaneObject() {
  if (renderer_) renderer_->RemoveObserver(startObserver_), renderer_->RemoveObserver(endObserver_);
}

void PlaneObject::attach(vtkRenderer* renderer) {
  renderer->AddActor(actor_);
  if (renderer_) renderer_->RemoveObserver(startObserver_), renderer_->RemoveObserver(endObserver_);
  renderer_ = renderer;
  startObserver_ = renderer->AddObserver(vtkCommand::StartEvent, this, &PlaneObject::beforeFrame);
  endObserver_ = renderer->AddObserver(vtkCommand::EndEvent, this, &PlaneObject::afterFrame);
}

bool PlaneObject::fillsTheView() const {
  if (!renderer_ || !actor_->GetVisibility() || actor_->HasTranslucentPolygonalGeometry()) return false;
  auto* window = renderer_->GetRenderWindow();
  if (!window) return false;
  int tiles[2];
  window->GetTileScale(tiles);
  if (tiles[0] != 1 || tiles[1] != 1) return false; // a tile of a large picture: keep it simple
  // the segment of each corner's ray between the near and the far clipping planes, in world coordinates
  vtkNew<vtkMatrix4x4> toWorld;
  toWorld->DeepCopy(renderer_->GetActiveCamera()->GetCompositeProjectionTransformMatrix(
      renderer_->GetTiledAspectRatio(), -1, 1));
  toWorld->Invert();
  const auto unproject = [&](double x, double y, double z) {
    double p[4] = {x, y, z, 1};
    toWorld->MultiplyPoint(p, p);
    return std::array<double, 3>{p[0] / p[3], p[1] / p[3], p[2] / p[3]};
  };
  const double* b = actor_->GetBounds(); // the quad, flat at z = b[4]
  int side = 0;
  for (const auto& [x, y] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}) {
    const auto a = unproject(x, y, -1), c = unproject(x, y, 1);
    const double za = a[2] - b[4], zc = c[2] - b[4];
    // the segment crosses the floor's plane, from the same side at every corner
    const int s = za > 0 && zc < 0 ? 1 : za < 0 && zc > 0 ? -1 : 0;
    if (s == 0 || (side != 0 && s != side)) return false;
    side = s;
    const double t = za / (za - zc), hx = a[0] + t * (c[0] - a[0]), hy = a[1] + t * (c[1] - a[1]);
    if (!(hx > b[0] && hx < b[1] && hy > b[2] && hy < b[3])) return false;
  }
  // a screen point's segment crosses the plane on a convex part of the screen, and the crossings form the
  // projective image of the view's rectangle: the corners inside the (convex) quad put all of it inside
  return true;
}

void PlaneObject::beforeFrame() {
  if (!renderer_->GetGradientBackground() || !fillsTheView()) return;
  renderer_->GradientBackgroundOff();
  backgroundHidden_ = true;
}

void PlaneObject::afterFrame() {
  if (!backgroundHidden_) return;
  renderer_->GradientBackgroundOn();
  backgroundHidden_ = false;
}

void PlaneObject::apply(const ObjectOptions& o) {
  const Rgb light = o.colour.value_or(Rgb{0.92, 0.92, 0.89});
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
