#include "render/charts/Chart3D.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

namespace rv {

Chart3D::Chart3D(std::array<std::string, 3> titles) : titles_(std::move(titles)) {
  renderer_ = vtkSmartPointer<vtkRenderer>::New();
  renderer_->SetBackground(1, 1, 1);
  // a live window changes many series between two frames: the actors are rebuilt once, before the frame
  vtkNew<vtkCallbackCommand> beforeRender;
  beforeRender->SetClientData(this);
  beforeRender->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    auto* chart = static_cast<Chart3D*>(self);
    if (chart->dirty_) chart->rebuild();
  });
  renderer_->AddObserver(vtkCommand::StartEvent, beforeRender);
}

Chart3D::~Chart3D() = default; // (no GL work here: the window's context may be gone already)

int Chart3D::addSeries(const std::vector<double>& x, const std::vector<double>& y,
                       const std::vector<double>& z, const Rgb& colour, float pointSize) {
  series_.push_back({x, y, z, colour, pointSize});
  return static_cast<int>(series_.size()) - 1;
}

void Chart3D::setRanges(const std::array<std::optional<double>, 6>& range) {
  range_ = range;
}

void Chart3D::setSeries(int index, const std::vector<double>& x, const std::vector<double>& y,
                        const std::vector<double>& z) {
  if (index < 0 || index >= static_cast<int>(series_.size())) return;
  series_[index].x = x, series_[index].y = y, series_[index].z = z;
  dirty_ = true;
}

void Chart3D::setColour(int index, const Rgb& colour) {
  if (index < 0 || index >= static_cast<int>(series_.size())) return;
  series_[index].colour = colour;
  dirty_ = true;
}

void Chart3D::select(int index) {
  selected_ = index;
  dirty_ = true;
}

void Chart3D::attach(vtkRenderWindow* window) {
  rebuild();
  const auto& a = boxSize_;
  vtkCamera* cam = renderer_->GetActiveCamera();
  cam->SetFocalPoint(0.5 * a[0], 0.5 * a[1], 0.5 * a[2]);
  cam->SetPosition(0.5 * a[0] + 2.2, 0.5 * a[1] - 2.6, 0.5 * a[2] + 1.6);
  cam->SetViewUp(0, 0, 1);
  renderer_->ResetCamera();
  cam->Zoom(0.9); // room for the labels
  window->AddRenderer(renderer_);
}

void Chart3D::rebuild() {
  dirty_ = false;
  // the box: the data's bounds where no range is given
  std::array<double, 6> b = {1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  for (const auto& s : series_)
    for (int i = 0; i < 3; ++i) {
      const auto& v = i == 0 ? s.x : i == 1 ? s.y : s.z;
      for (double c : v)
        if (std::isfinite(c)) b[2 * i] = std::min(b[2 * i], c), b[2 * i + 1] = std::max(b[2 * i + 1], c);
    }
  for (int i = 0; i < 6; ++i) {
    if (range_[i]) b[i] = *range_[i];
    if (std::abs(b[i]) > 1e299) b[i] = i % 2 ? 1 : -1; // no data
  }
  for (int i = 0; i < 3; ++i) {
    // a constant (an integral along its trajectories) would spread its rounding errors over the whole box
    const double size = std::max(std::abs(b[2 * i]), std::abs(b[2 * i + 1]));
    const bool given = range_[2 * i] && range_[2 * i + 1];
    if (!(b[2 * i + 1] > b[2 * i]) || (!given && !(b[2 * i + 1] - b[2 * i] > 1e-9 * size))) {
      const double mid = 0.5 * (b[2 * i] + b[2 * i + 1]), half = size > 0 ? 0.05 * size : 0.5;
      b[2 * i] = mid - half, b[2 * i + 1] = mid + half;
    }
  }
  bounds_ = b;
  // drawn in a unit-ish box: each axis scaled to length 1 unless the scales are equal
  double scale[3];
  const double longest = std::max({b[1] - b[0], b[3] - b[2], b[5] - b[4]});
  for (int i = 0; i < 3; ++i)
    scale[i] = 1.0 / (equal_ ? longest : b[2 * i + 1] - b[2 * i]);
  renderer_->RemoveAllViewProps();
  for (std::size_t i = 0; i < series_.size(); ++i) {
    const Series& s = series_[i];
    vtkNew<vtkPoints> pts;
    vtkNew<vtkCellArray> verts;
    for (std::size_t k = 0; k < s.x.size(); ++k) {
      const vtkIdType id = pts->InsertNextPoint((s.x[k] - b[0]) * scale[0], (s.y[k] - b[2]) * scale[1],
                                                (s.z[k] - b[4]) * scale[2]);
      verts->InsertNextCell(1, &id);
    }
    vtkNew<vtkPolyData> data;
    data->SetPoints(pts);
    data->SetVerts(verts);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(data);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(s.colour[0], s.colour[1], s.colour[2]);
    actor->GetProperty()->SetPointSize(static_cast<int>(i) == selected_ ? 2 * s.size : s.size);
    actor->GetProperty()->LightingOff();
    renderer_->AddActor(actor);
  }
  // the axes carry data units over the scaled box
  AxesOptions a;
  a.style = AxesOptions::Style::Box;
  a.min = std::array<double, 3>{0, 0, 0};
  a.max = std::array<double, 3>{(b[1] - b[0]) * scale[0], (b[3] - b[2]) * scale[1], (b[5] - b[4]) * scale[2]};
  axes_ = std::make_unique<SceneAxesObject>("axes", a, *a.min, *a.max);
  axes_->setLabelling({b[0], b[2], b[4]}, {b[1], b[3], b[5]}, titles_);
  axes_->attach(renderer_);
  boxSize_ = *a.max;
}

void Chart3D::writeCsv(std::ostream& out) const {
  out << "series," << titles_[0] << "," << titles_[1] << "," << titles_[2] << "\n";
  char row[128];
  for (std::size_t i = 0; i < series_.size(); ++i)
    for (std::size_t k = 0; k < series_[i].x.size(); ++k) {
      std::snprintf(row, sizeof row, "%zu,%.17g,%.17g,%.17g\n", i, series_[i].x[k], series_[i].y[k],
                    series_[i].z[k]);
      out << row;
    }
}

} // namespace rv
