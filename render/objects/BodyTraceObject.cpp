#include "render/objects/BodyTraceObject.h"

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>

namespace rv {

BodyTraceObject::BodyTraceObject(std::string name, double scale, long maxPoints)
    : VisualObject(std::move(name)), lift_(4e-3 * scale), line_(2e-3 * scale, maxPoints) {}

void BodyTraceObject::apply(const ObjectOptions& o) {
  line_.setAppearance(o.traceColor.value_or(o.color.value_or(Rgb{0.95, 0.75, 0.1})), o.lineWidth, o.opacity,
                      o.enabled);
}

void BodyTraceObject::advance(const FrameState& s) {
  if (!s.pose) return;
  // in the body's frame, a little outside it: the body's outward normal at the contact is -supportNormal
  const Eigen::Vector3d p =
      s.pose->rotation.transpose() * (s.pose->contact - lift_ * s.pose->supportNormal - s.pose->center);
  line_.append(p[0], p[1], p[2]);
  last_ = p;
}

void BodyTraceObject::show(const FrameState& s) {
  advance(s);
  if (!s.pose) return;
  vtkNew<vtkMatrix4x4> m; // body -> world, as the body itself is placed
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      m->SetElement(i, j, s.pose->rotation(i, j));
    m->SetElement(i, 3, s.pose->center[i]);
  }
  line_.actor()->SetUserMatrix(m);
}

} // namespace rv
