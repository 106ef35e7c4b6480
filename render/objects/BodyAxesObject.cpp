#include "render/objects/BodyAxesObject.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

namespace rv {

BodyAxesObject::BodyAxesObject(std::string name, const BodyGeometry& g, double scale)
    : VisualObject(std::move(name)) {
  for (int i = 0; i < 3; ++i) {
    // beyond the surface along each axis: the semi-axis for balls and ellipsoids, the body's size otherwise
    const double reach = g.shape == BodyShape::Paraboloid ? scale : g.semiAxes[i] + g.centre.norm();
    lengths_[i] = 1.3 * reach;
    tips_[i].setZero();
  }
  points_ = vtkSmartPointer<vtkPoints>::New();
  points_->SetNumberOfPoints(6);
  for (int k = 0; k < 6; ++k)
    points_->SetPoint(k, 0, 0, 0);
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  const unsigned char rgb[3][3] = {{220, 40, 30}, {30, 160, 60}, {40, 80, 220}};
  for (int i = 0; i < 3; ++i) {
    const vtkIdType ids[2] = {2 * i, 2 * i + 1};
    lines->InsertNextCell(2, ids);
    colours->InsertNextTypedTuple(rgb[i]);
  }
  data_ = vtkSmartPointer<vtkPolyData>::New();
  data_->SetPoints(points_);
  data_->SetLines(lines);
  data_->GetCellData()->SetScalars(colours);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data_);
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper);
  actor_->GetProperty()->SetLineWidth(3);
  actor_->GetProperty()->SetLighting(false);
}

void BodyAxesObject::attach(vtkRenderer* renderer) {
  renderer->AddActor(actor_);
}

void BodyAxesObject::apply(const ObjectOptions& o) {
  actor_->SetVisibility(o.enabled);
  actor_->GetProperty()->SetOpacity(o.opacity.value_or(1.0));
  actor_->GetProperty()->SetLineWidth(static_cast<float>(o.lineWidth));
}

void BodyAxesObject::show(const FrameState& s) {
  if (!s.pose) return;
  for (int i = 0; i < 3; ++i) {
    tips_[i] = s.pose->centre + lengths_[i] * s.pose->rotation.col(i);
    points_->SetPoint(2 * i, s.pose->centre.data());
    points_->SetPoint(2 * i + 1, tips_[i].data());
  }
  points_->Modified();
}

} // namespace rv
