#include "render/objects/SurfaceObject.h"

#include "render/BodyMeshes.h"
#include "render/Textures.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

namespace rv {

SurfaceObject::SurfaceObject(std::string name, const SupportSurface& surface)
    : VisualObject(std::move(name)) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(makeSurfaceMesh(surface));
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper);
  actor_->GetProperty()->BackfaceCullingOff();
  actor_->GetProperty()->SetSpecular(0.2);
}

void SurfaceObject::attach(vtkRenderer* renderer) {
  renderer->AddActor(actor_);
}

void SurfaceObject::apply(const ObjectOptions& o) {
  const Rgb light = o.color.value_or(Rgb{0.93, 0.9, 0.84});
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
