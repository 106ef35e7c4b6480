#include "render/objects/SurfaceObject.h"

#include "render/BodyMeshes.h"
#include "render/Textures.h"

#include <Eigen/Geometry>
#include <limits>
#include <vtkActor.h>
#include <vtkIdList.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

namespace rv {

SurfaceObject::SurfaceObject(std::string name, const SupportSurface& surface)
    : SurfaceObject(std::move(name), makeSurfaceMesh(surface)) {}

SurfaceObject::SurfaceObject(std::string name, vtkSmartPointer<vtkPolyData> mesh)
    : VisualObject(std::move(name)), mesh_(std::move(mesh)) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh_);
  mapper->ScalarVisibilityOff(); // a sampled surface carries F's values: the colour is the options
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper);
  actor_->GetProperty()->BackfaceCullingOff();
  actor_->GetProperty()->SetSpecular(0.2);
}

void SurfaceObject::hideTheFarSide(const Eigen::Vector3d& contact, const Eigen::Vector3d& centre) {
  double b[6];
  mesh_->GetBounds(b);
  const Eigen::Vector3d middle((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2);
  if ((middle - contact).dot(centre - contact) <= 0) return; // a body outside it: all of it stays drawn
  // the triangle nearest the contact: which way its winding faces, towards the body or away
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector3d facing = Eigen::Vector3d::Zero();
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh_->GetNumberOfCells(); ++c) {
    mesh_->GetCellPoints(c, ids);
    if (ids->GetNumberOfIds() < 3) continue;
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k)
      mesh_->GetPoint(ids->GetId(k), p[k].data());
    const Eigen::Vector3d normal = (p[1] - p[0]).cross(p[2] - p[0]);
    const double d = ((p[0] + p[1] + p[2]) / 3 - contact).squaredNorm();
    if (normal.squaredNorm() > 0 && d < best) best = d, facing = normal;
  }
  if (facing.dot(centre - contact) > 0)
    actor_->GetProperty()->BackfaceCullingOn();
  else
    actor_->GetProperty()->FrontfaceCullingOn();
}

void SurfaceObject::attach(vtkRenderer* renderer) {
  renderer->AddActor(actor_);
}

void SurfaceObject::apply(const ObjectOptions& o) {
  const Rgb light = o.colour.value_or(Rgb{0.93, 0.9, 0.84});
  const Rgb dark = {light[0] * 0.88, light[1] * 0.88, light[2] * 0.88};
  actor_->SetTexture(textureFor(o, [&] { return makeCheckerTexture(light, dark, {0.55, 0.55, 0.6}); }));
  const Rgb base = actor_->GetTexture() ? Rgb{1, 1, 1} : light; // a texture carries the colour itself
  actor_->GetProperty()->SetColor(base[0], base[1], base[2]);
  actor_->SetVisibility(o.enabled);
  actor_->GetProperty()->SetOpacity(o.opacity.value_or(1.0));
  actor_->GetProperty()->SetRepresentation(o.style == SurfaceStyle::Grid ? VTK_WIREFRAME : VTK_SURFACE);
  actor_->GetProperty()->SetEdgeVisibility(o.style == SurfaceStyle::Both);
}

} // namespace rv
