#include "render/GrowingPolyline.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace rv {

namespace {
// cells of (at most) 1.5 pixels for lines 3 pixels wide, the traces' default: a segment left out passes
// within a cell's diagonal (2.1 px in a plane facing the view) of drawn ones. Inside a scribble that is
// inside their width (ViewTest: mean difference 0.003 of 255, 0.002 % of pixels over 48, against 0.000 and
// 0.0003 % with 1-pixel cells, for 36 % fewer segments: the rattleback's trace frame 1.54 -> 1.29-1.33x the
// bare scene); two passes of a sparse trace closer than that are drawn as one. Thinner lines get smaller
// cells in proportion.
constexpr double kCellPixels = 1.5;
constexpr double kCellLineWidth = 3.0;
// a cell key packs three 21-bit coordinates; a point further out (a million pixels off the line's start) is
// never counted as covered
constexpr std::int64_t kCellRange = 1 << 20;

bool cellKey(const Eigen::Vector3d& p, double cell, std::uint64_t& key) {
  key = 0;
  for (int k = 0; k < 3; ++k) {
    const double c = std::floor(p[k] / cell);
    if (!(std::abs(c) < kCellRange)) return false;
    key |= (static_cast<std::uint64_t>(static_cast<std::int64_t>(c) + kCellRange) & 0x1FFFFF) << (21 * k);
  }
  return true;
}
} // namespace

GrowingPolyline::~GrowingPolyline() {
  if (renderer_) renderer_->RemoveObserver(observer_);
}

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
  if (asPoints_) return;
  if (renderer_) renderer_->RemoveObserver(observer_);
  renderer_ = renderer;
  observer_ = renderer->AddObserver(vtkCommand::StartEvent, this, &GrowingPolyline::beforeFrame);
}

void GrowingPolyline::setLevelOfDetail(bool on) {
  lod_ = on;
  if (!on && cell_ > 0) {
    cell_ = 0;
    settle(true);
  }
}

long GrowingPolyline::segmentsDrawn() const {
  return data_->GetLines()->GetNumberOfCells();
}

void GrowingPolyline::beforeFrame() {
  double cell = 0;
  double b[6];
  actor_->GetBounds(b); // world coordinates, the body's placement included
  auto* camera = renderer_->GetActiveCamera();
  const int height = renderer_->GetSize()[1];
  auto* property = actor_->GetProperty();
  // translucent lines darken where they overlap: leaving a covered segment out would show
  if (lod_ && camera && height > 0 && b[0] <= b[1] && property->GetOpacity() >= 1) {
    double pixel = 0;
    if (camera->GetParallelProjection()) {
      pixel = 2 * camera->GetParallelScale() / height;
    } else { // at the line's nearest corner along the view: no part of it is drawn larger
      const Eigen::Vector3d eye(camera->GetPosition()), view(camera->GetDirectionOfProjection());
      double depth = 1e300;
      for (int corner = 0; corner < 8; ++corner)
        depth = std::min(
            depth,
            (Eigen::Vector3d(b[corner & 1], b[2 + (corner >> 1 & 1)], b[4 + (corner >> 2)]) - eye).dot(view));
      if (depth > 0)
        pixel = 2 * depth * std::tan(0.5 * camera->GetViewAngle() * std::numbers::pi / 180) / height;
    }
    const double target = kCellPixels * pixel * std::min(1.0, property->GetLineWidth() / kCellLineWidth);
    // cells of at most kCellPixels pixels, not under an eighth of the simplification's tolerance (nothing to
    // gain there); a camera that follows the body changes the pixel a little every frame: the cells change
    // only when the pixel has shrunk below them or grown by a third
    if (cell_ > 0 && cell_ <= target && target < 1.33 * cell_) return;
    if (target >= tolerance_ / 8) cell = target;
  }
  if (cell != cell_) {
    cell_ = cell;
    settle(true);
  }
}

void GrowingPolyline::settle(bool all) {
  if (all) {
    cells_.clear();
    kept_.clear();
    settled_ = 0;
  }
  const long segments = data_->GetNumberOfPoints() - 1;
  const long target = std::max(0L, segments - kLodHead);
  std::vector<std::uint64_t> keys;
  for (long i = settled_; i < target; ++i) {
    bool covered = cell_ > 0;
    if (covered) { // the segment's samples every half cell: all in cells already reached?
      const Eigen::Vector3d a = vertex(i), d = vertex(i + 1) - a;
      const long steps = std::max(1L, static_cast<long>(std::ceil(d.norm() / (0.5 * cell_))));
      keys.clear();
      for (long k = 0; k <= steps; ++k) {
        std::uint64_t key;
        if (!cellKey(a + d * (static_cast<double>(k) / steps), cell_, key)) {
          covered = false;
          keys.clear();
          break;
        }
        keys.push_back(key);
        covered = covered && cells_.count(key);
      }
    }
    if (!covered) {
      cells_.insert(keys.begin(), keys.end());
      kept_.push_back(i);
    }
  }
  settled_ = std::max(settled_, target);
  rebuildCells();
}

void GrowingPolyline::rebuildCells() {
  auto* lines = data_->GetLines();
  lines->Reset();
  const long segments = data_->GetNumberOfPoints() - 1;
  for (const long i : kept_) {
    const vtkIdType seg[2] = {i, i + 1};
    lines->InsertNextCell(2, seg);
  }
  for (long i = settled_; i < segments; ++i) { // the head, exact
    const vtkIdType seg[2] = {i, i + 1};
    lines->InsertNextCell(2, seg);
  }
  lines->Modified();
  data_->Modified();
}

void GrowingPolyline::setAppearance(const Rgb& colour, double lineWidth, double opacity, bool visible) {
  auto* p = actor_->GetProperty();
  p->SetColor(colour[0], colour[1], colour[2]);
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
  cells_.clear();
  kept_.clear();
  settled_ = 0;
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
      if (id - settled_ > 2 * kLodHead) settle(false); // the head's older half settles: filtered once
    }
  }
  pts->Modified();
  data_->Modified();
}

} // namespace rv
