#include "render/objects/FrameObjects.h"

#include "render/objects/Actors.h"
#include "render/objects/ApexObject.h"

#include <Eigen/Geometry>
#include <cmath>
#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkCellData.h>
#include <vtkCubeSource.h>
#include <vtkMatrix4x4.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

namespace rv {

namespace {
void place(vtkActor* actor, const Eigen::Matrix3d& r) {
  vtkNew<vtkMatrix4x4> m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      m->SetElement(i, j, r(i, j));
  actor->SetUserMatrix(m);
}
} // namespace

UnitSphereObject::UnitSphereObject(std::string name) : VisualObject(std::move(name)) {
  sphere_ = sphereActor(1.0, 72, 36);
  sphere_->GetProperty()->SetSpecular(0.2);
}

void UnitSphereObject::attach(vtkRenderer* renderer) {
  renderer->AddActor(sphere_);
}

void UnitSphereObject::apply(const ObjectOptions& o) {
  const Rgb c = o.colour.value_or(Rgb{0.85, 0.87, 0.92});
  auto* p = sphere_->GetProperty();
  p->SetColor(c[0], c[1], c[2]);
  p->SetOpacity(o.opacity.value_or(0.3)); // see the apexes' traces on the far side through it
  p->SetRepresentation(o.style == SurfaceStyle::Grid ? VTK_WIREFRAME : VTK_SURFACE);
  p->SetEdgeVisibility(o.style == SurfaceStyle::Both);
  p->SetEdgeColor(0.55, 0.57, 0.62);
  sphere_->SetVisibility(o.enabled);
}

BodyBoxObject::BodyBoxObject(std::string name, LookingIn frame, const std::array<double, 3>& defaultSize)
    : VisualObject(std::move(name)), frame_(frame), defaultSize_(defaultSize) {
  cube_ = vtkSmartPointer<vtkCubeSource>::New();
  cube_->Update();
  // vtkCubeSource's six faces come in the order -x, +x, -y, +y, -z, +z: colour each by its axis
  vtkNew<vtkPolyData> faces;
  faces->DeepCopy(cube_->GetOutput());
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  for (int f = 0; f < 6; ++f) {
    const Rgb c = axisColour(f / 2);
    const double shade = f % 2 ? 1.0 : 0.7; // the negative face darker
    const unsigned char rgb[3] = {static_cast<unsigned char>(255 * c[0] * shade),
                                  static_cast<unsigned char>(255 * c[1] * shade),
                                  static_cast<unsigned char>(255 * c[2] * shade)};
    colours->InsertNextTypedTuple(rgb);
  }
  faces->GetCellData()->SetScalars(colours);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(faces);
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper);
}

void BodyBoxObject::attach(vtkRenderer* renderer) {
  renderer->AddActor(actor_);
}

void BodyBoxObject::apply(const ObjectOptions& o) {
  const auto size = o.size.value_or(defaultSize_);
  actor_->SetScale(size[0], size[1], size[2]);
  actor_->SetVisibility(o.enabled);
  auto* p = actor_->GetProperty();
  p->SetOpacity(o.opacity.value_or(1.0));
  p->SetRepresentation(o.style == SurfaceStyle::Grid ? VTK_WIREFRAME : VTK_SURFACE);
  p->SetEdgeVisibility(o.style == SurfaceStyle::Both);
}

void BodyBoxObject::show(const FrameState& s) {
  if (!s.pose) return;
  place(actor_, frame_ == LookingIn::Absolute ? s.pose->rotation : Eigen::Matrix3d::Identity());
}

VectorObject::VectorObject(std::string name, LookingIn frame) : VisualObject(std::move(name)), frame_(frame) {
  vtkNew<vtkArrowSource> arrow; // along +x, unit length
  arrow->SetTipResolution(24);
  arrow->SetShaftResolution(16);
  actor_ = actorOf(arrow);
}

void VectorObject::attach(vtkRenderer* renderer) {
  renderer->AddActor(actor_);
}

void VectorObject::apply(const ObjectOptions& o) {
  if (o.vector) v0_ = Eigen::Vector3d((*o.vector)[0], (*o.vector)[1], (*o.vector)[2]);
  const Rgb c = o.colour.value_or(Rgb{0.95, 0.6, 0.05});
  actor_->GetProperty()->SetColor(c[0], c[1], c[2]);
  actor_->GetProperty()->SetOpacity(o.opacity.value_or(1.0));
  actor_->SetVisibility(o.enabled && v0_.norm() > 0);
}

void VectorObject::show(const FrameState& s) {
  if (!s.pose) return;
  const Eigen::Matrix3d& r = s.pose->rotation;
  if (!haveStart_) r0_ = r, haveStart_ = true;
  value_ = frame_ == LookingIn::Absolute ? Eigen::Vector3d(r * r0_.transpose() * v0_)
                                         : Eigen::Vector3d(r.transpose() * r0_ * v0_);
  // the arrow's +x onto value_: a rotation taking e1 to its direction, scaled by its length
  const double len = value_.norm();
  if (len == 0) return;
  const Eigen::Vector3d d = value_ / len;
  const Eigen::Vector3d helper = std::abs(d.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e2 = d.cross(helper).normalized();
  Eigen::Matrix3d m;
  m << d, e2, d.cross(e2);
  place(actor_, m * len);
}

} // namespace rv
