#include "render/objects/ContactTraceObject.h"

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>

namespace rv {

ContactTraceObject::ContactTraceObject(std::string name, On on, double scale, long maxPoints)
    : VisualObject(std::move(name)), on_(on), lift_((on == On::Support ? 6e-3 : 4e-3) * scale),
      line_(2e-3 * scale, maxPoints) {}

void ContactTraceObject::apply(const ObjectOptions& o) {
  const Rgb fallback = on_ == On::Support ? Rgb{0.82, 0.13, 0.1} : Rgb{0.95, 0.75, 0.1};
  line_.setAppearance(o.traceColour.value_or(o.colour.value_or(fallback)), o.lineWidth,
                      o.opacity.value_or(1.0), o.enabled);
}

void ContactTraceObject::advance(const FrameState& s) {
  if (!s.pose) return;
  if (on_ == On::Support)
    last_ = s.pose->contact + lift_ * s.pose->supportNormal;
  else // in the body's frame, a little outside it: the body's outward normal at the contact is -supportNormal
    last_ = s.pose->rotation.transpose() * (s.pose->contact - lift_ * s.pose->supportNormal - s.pose->centre);
  line_.append(last_[0], last_[1], last_[2]);
}

void ContactTraceObject::show(const FrameState& s) {
  advance(s);
  if (on_ != On::Body || !s.pose) return;
  vtkNew<vtkMatrix4x4> m; // body -> world, as the body itself is placed
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      m->SetElement(i, j, s.pose->rotation(i, j));
    m->SetElement(i, 3, s.pose->centre[i]);
  }
  line_.actor()->SetUserMatrix(m);
}

} // namespace rv
