#include "render/objects/PhaseCurveObject.h"

#include "render/objects/Actors.h"

#include <algorithm>
#include <vtkActor.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

namespace rv {

namespace {
double component(const FrameState& s, int i) {
  return i < s.model.dimension() ? s.x[i] : 0.0;
}
} // namespace

PhaseCurveObject::PhaseCurveObject(std::string name, double scale, long maxPoints, bool asPoints)
    : VisualObject(std::move(name)), scale_(scale), line_(1e-3 * scale, maxPoints, asPoints) {
  marker_ = sphereActor(0.012 * scale, 24, 12);
}

void PhaseCurveObject::attach(vtkRenderer* renderer) {
  line_.attach(renderer);
  renderer->AddActor(marker_);
}

void PhaseCurveObject::apply(const ObjectOptions& o) {
  const Rgb c = o.traceColour.value_or(o.colour.value_or(Rgb{0.1, 0.3, 0.75}));
  line_.setAppearance(c, std::max(1.0, o.lineWidth - 1), o.opacity.value_or(1.0), o.enabled);
  marker_->GetProperty()->SetColor(0.85, 0.15, 0.1);
  marker_->SetVisibility(o.enabled);
}

void PhaseCurveObject::advance(const FrameState& s) {
  line_.append(component(s, 0), component(s, 1), component(s, 2));
}

void PhaseCurveObject::show(const FrameState& s) {
  advance(s);
  marker_->SetPosition(component(s, 0), component(s, 1), component(s, 2));
  // keep the marker about 1% of the curve's extent
  double b[6];
  line_.actor()->GetBounds(b);
  const double extent = std::max({b[1] - b[0], b[3] - b[2], b[5] - b[4], 1e-9});
  marker_->SetScale(extent / (0.012 * scale_) * 0.01);
}

} // namespace rv
