#include "render/objects/BodyObject.h"

#include "render/BodyMeshes.h"
#include "render/Textures.h"

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRegularPolygonSource.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

namespace rv {

BodyObject::BodyObject(std::string name, const BodyGeometry& geometry,
                       const vtkSmartPointer<vtkPolyData>& mesh)
    : VisualObject(std::move(name)), size_(bodySize(geometry)) {
  vtkNew<vtkPolyDataMapper> mapper;
  const vtkSmartPointer<vtkPolyData> surface = mesh ? mesh : makeBodyMesh(geometry);
  textured_ = surface->GetPointData()->GetTCoords() != nullptr; // a mesh file may have none
  mapper->SetInputData(surface);
  body_ = vtkSmartPointer<vtkActor>::New();
  body_->SetMapper(mapper);
  body_->GetProperty()->SetSpecular(0.35);
  body_->GetProperty()->SetSpecularPower(30);
  body_->GetProperty()->BackfaceCullingOff(); // an open paraboloid shows its inside

  vtkNew<vtkPolyDataMapper> gridMapper;
  gridMapper->SetInputData(mesh ? mesh : makeBodyGridLines(geometry));
  grid_ = vtkSmartPointer<vtkActor>::New();
  grid_->SetMapper(gridMapper);
  if (mesh) grid_->GetProperty()->SetRepresentationToWireframe();
  grid_->GetProperty()->SetLineWidth(1.5);
  grid_->GetProperty()->LightingOff();

  vtkNew<vtkRegularPolygonSource> disc;
  disc->SetNumberOfSides(64);
  disc->GeneratePolylineOff();
  disc->SetRadius(0.35 * size_);
  vtkNew<vtkPolyDataMapper> discMapper;
  discMapper->SetInputConnection(disc->GetOutputPort());
  shadow_ = vtkSmartPointer<vtkActor>::New();
  shadow_->SetMapper(discMapper);
  // opaque: translucent geometry is not drawn the same on every headless backend
  shadow_->GetProperty()->SetColor(0.62, 0.62, 0.64);
  shadow_->GetProperty()->LightingOff();
  shadow_->PickableOff();
}

void BodyObject::attach(vtkRenderer* renderer) {
  renderer->AddActor(shadow_);
  renderer->AddActor(body_);
  renderer->AddActor(grid_);
}

void BodyObject::apply(const ObjectOptions& o) {
  const Rgb colour = o.colour.value_or(Rgb{0.19, 0.44, 1.0});
  body_->SetTexture(textured_ ? textureFor(o, [&] { return makeBallTexture(colour); }) : nullptr);
  const Rgb base = body_->GetTexture() ? Rgb{1, 1, 1} : colour; // a texture carries the colour itself
  body_->GetProperty()->SetColor(base[0], base[1], base[2]);
  shadow_->SetVisibility(o.enabled);
  auto* p = body_->GetProperty();
  p->SetOpacity(o.opacity.value_or(1.0));
  body_->SetVisibility(o.enabled && o.style != SurfaceStyle::Grid);
  grid_->SetVisibility(o.enabled && o.style != SurfaceStyle::Fill);
  // alone, the grid has the body's colour; over the surface, dark lines
  const Rgb line = o.style == SurfaceStyle::Grid ? colour : Rgb{0.1, 0.1, 0.1};
  grid_->GetProperty()->SetColor(line[0], line[1], line[2]);
  grid_->GetProperty()->SetOpacity(o.opacity.value_or(1.0));
}

void BodyObject::show(const FrameState& s) {
  if (!s.pose) return;
  vtkNew<vtkMatrix4x4> m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      m->SetElement(i, j, s.pose->rotation(i, j));
    m->SetElement(i, 3, s.pose->centre[i]);
  }
  body_->SetUserMatrix(m);
  grid_->SetUserMatrix(m);
  shadow_->SetPosition(s.pose->contact[0], s.pose->contact[1], s.pose->contact[2] + 3e-3 * size_);
}

} // namespace rv
