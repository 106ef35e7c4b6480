#include "render/GrowingPolyline.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace rv {

GrowingPolyline::GrowingPolyline(double minSpacing, long maxPoints, bool asPoints)
    : minSpacing2_(minSpacing * minSpacing), maxPoints_(maxPoints), asPoints_(asPoints) {
  data_ = vtkSmartPointer<vtkPolyData>::New();
  clear();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data_);
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper);
  actor_->GetProperty()->SetRenderLinesAsTubes(true); // honours the line width on core-profile GL
  actor_->GetProperty()->SetRenderPointsAsSpheres(true);
  actor_->GetProperty()->SetAmbient(0.6);
  actor_->GetProperty()->SetDiffuse(0.5);
}

void GrowingPolyline::attach(vtkRenderer* renderer) {
  renderer->AddActor(actor_);
}

void GrowingPolyline::setAppearance(const Rgb& color, double lineWidth, double opacity, bool visible) {
  auto* p = actor_->GetProperty();
  p->SetColor(color[0], color[1], color[2]);
  p->SetLineWidth(static_cast<float>(lineWidth));
  p->SetPointSize(static_cast<float>(lineWidth));
  p->SetOpacity(opacity);
  actor_->SetVisibility(visible);
}

void GrowingPolyline::clear() {
  data_->SetPoints(vtkSmartPointer<vtkPoints>::New());
  data_->SetLines(vtkSmartPointer<vtkCellArray>::New());
  data_->SetVerts(vtkSmartPointer<vtkCellArray>::New());
  lastIsProvisional_ = false;
  data_->Modified();
}

long GrowingPolyline::size() const {
  return data_->GetNumberOfPoints();
}

vtkActor* GrowingPolyline::actor() const {
  return actor_;
}

void GrowingPolyline::append(double x, double y, double z) {
  vtkPoints* pts = data_->GetPoints();
  if (asPoints_) {
    if (pts->GetNumberOfPoints() >= maxPoints_) return;
    const vtkIdType id = pts->InsertNextPoint(x, y, z);
    data_->GetVerts()->InsertNextCell(1, &id);
    pts->Modified();
    data_->GetVerts()->Modified();
    data_->Modified();
    return;
  }
  const vtkIdType n = pts->GetNumberOfPoints();
  if (n >= 2) {
    // the newest point is provisional until it is far enough from the one before it: move it
    double prev[3];
    pts->GetPoint(n - (lastIsProvisional_ ? 2 : 1), prev);
    const double d2 =
        (x - prev[0]) * (x - prev[0]) + (y - prev[1]) * (y - prev[1]) + (z - prev[2]) * (z - prev[2]);
    if (lastIsProvisional_) {
      pts->SetPoint(n - 1, x, y, z);
      lastIsProvisional_ = d2 < minSpacing2_;
      pts->Modified();
      data_->Modified();
      return;
    }
    if (d2 < minSpacing2_) lastIsProvisional_ = true;
  }
  if (n >= maxPoints_) return; // the cap: the trace stops growing, it is never rebuilt
  const vtkIdType id = pts->InsertNextPoint(x, y, z);
  if (id > 0) {
    const vtkIdType seg[2] = {id - 1, id};
    data_->GetLines()->InsertNextCell(2, seg);
  }
  pts->Modified();
  data_->GetLines()->Modified();
  data_->Modified();
}

} // namespace rv
