#include "render/objects/BallObject.h"

#include "render/Textures.h"

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRegularPolygonSource.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>
#include <vtkTexturedSphereSource.h>

namespace rv {

BallObject::BallObject(std::string name, double radius) : VisualObject(std::move(name)), radius_(radius) {
  vtkNew<vtkTexturedSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(96);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  ball_ = vtkSmartPointer<vtkActor>::New();
  ball_->SetMapper(mapper);
  ball_->GetProperty()->SetSpecular(0.35);
  ball_->GetProperty()->SetSpecularPower(30);

  vtkNew<vtkRegularPolygonSource> disc;
  disc->SetNumberOfSides(64);
  disc->GeneratePolylineOff();
  disc->SetRadius(0.7 * radius);
  vtkNew<vtkPolyDataMapper> discMapper;
  discMapper->SetInputConnection(disc->GetOutputPort());
  shadow_ = vtkSmartPointer<vtkActor>::New();
  shadow_->SetMapper(discMapper);
  // opaque: translucent geometry is not drawn the same on every headless backend
  shadow_->GetProperty()->SetColor(0.62, 0.62, 0.64);
  shadow_->GetProperty()->LightingOff();
  shadow_->PickableOff();
}

void BallObject::attach(vtkRenderer* renderer) {
  renderer->AddActor(shadow_);
  renderer->AddActor(ball_);
}

void BallObject::apply(const ObjectOptions& o) {
  const Rgb color = o.color.value_or(Rgb{0.19, 0.44, 1.0});
  ball_->SetTexture(makeBallTexture(color));
  ball_->SetVisibility(o.enabled);
  shadow_->SetVisibility(o.enabled);
  auto* p = ball_->GetProperty();
  p->SetOpacity(o.opacity);
  p->SetRepresentation(o.style == SurfaceStyle::Grid ? VTK_WIREFRAME : VTK_SURFACE);
  p->SetEdgeVisibility(o.style == SurfaceStyle::Both);
  p->SetEdgeColor(0.1, 0.1, 0.1);
}

void BallObject::show(const FrameState& s) {
  if (!s.pose) return;
  vtkNew<vtkMatrix4x4> m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m->SetElement(i, j, s.pose->rotation(i, j));
    m->SetElement(i, 3, s.pose->center[i]);
  }
  ball_->SetUserMatrix(m);
  shadow_->SetPosition(s.pose->contact[0], s.pose->contact[1], s.pose->contact[2] + 3e-3 * radius_);
}

} // namespace rv
