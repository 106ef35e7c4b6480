#include "render/GrowingPolyline.h"

#include <algorithm>
#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace rv {

GrowingPolyline::GrowingPolyline(double tolerance, long maxPoints, bool asPoints)
    : tolerance_(tolerance), maxPoints_(maxPoints), asPoints_(asPoints) {
  data_ = vtkSmartPointer<vtkPolyData>::New();
  clear();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data_);
  actor_ = vtkSmartPointer<vtkActor>::New();
  actor_->SetMapper(mapper);
  // flat wide lines: VTK draws them instanced; lit tubes cost 4x more on software GL (tests/bench)
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
  samples_.clear();
  data_->Modified();
}

long GrowingPolyline::size() const {
  return data_->GetNumberOfPoints();
}

Eigen::Vector3d GrowingPolyline::vertex(long i) const {
  Eigen::Vector3d v;
  data_->GetPoints()->GetPoint(i, v.data());
  return v;
}

vtkActor* GrowingPolyline::actor() const {
  return actor_;
}

bool GrowingPolyline::chordPassesNearDropped(const Eigen::Vector3d& end) const {
  const Eigen::Vector3d d = end - anchor_;
  const double len2 = d.squaredNorm(), tol2 = 0.25 * tolerance_ * tolerance_;
  const auto near = [&](const Eigen::Vector3d& q) {
    const double s = len2 > 0 ? std::clamp((q - anchor_).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (anchor_ + s * d - q).squaredNorm() <= tol2;
  };
  return near(provisional_) && std::all_of(samples_.begin(), samples_.end(), near);
}

void GrowingPolyline::append(double x, double y, double z) {
  vtkPoints* pts = data_->GetPoints();
  const vtkIdType n = pts->GetNumberOfPoints();
  if (asPoints_) {
    if (n >= maxPoints_) return;
    const vtkIdType id = pts->InsertNextPoint(x, y, z);
    data_->GetVerts()->InsertNextCell(1, &id);
    data_->GetVerts()->Modified();
  } else {
    const Eigen::Vector3d p(x, y, z);
    // Dropped points are sampled every tolerance/2 and checked against tolerance/2: a point not sampled is
    // within tolerance/2 of one that is, so within tolerance of the line. The samples are capped to bound
    // the work per point (a long straight stretch then keeps a vertex every kMaxSamples * tolerance / 2).
    constexpr std::size_t kMaxSamples = 256;
    if (n >= 2 && samples_.size() < kMaxSamples && chordPassesNearDropped(p)) {
      if (samples_.empty() || (provisional_ - samples_.back()).norm() >= 0.5 * tolerance_)
        samples_.push_back(provisional_);
      provisional_ = p;
      pts->SetPoint(n - 1, x, y, z); // the provisional vertex moves on
    } else {
      if (n >= maxPoints_) return;         // the cap: the trace stops growing, it is never rebuilt
      anchor_ = n == 0 ? p : provisional_; // the provisional vertex stays
      samples_.clear();
      provisional_ = p;
      const vtkIdType id = pts->InsertNextPoint(x, y, z);
      if (id > 0) {
        const vtkIdType seg[2] = {id - 1, id};
        data_->GetLines()->InsertNextCell(2, seg);
        data_->GetLines()->Modified();
      }
    }
  }
  pts->Modified();
  data_->Modified();
}

} // namespace rv
