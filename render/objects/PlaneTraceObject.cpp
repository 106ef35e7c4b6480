#include "render/objects/PlaneTraceObject.h"

namespace rv {

PlaneTraceObject::PlaneTraceObject(std::string name, double scale, long maxPoints)
    : VisualObject(std::move(name)), lift_(6e-3 * scale), line_(2e-3 * scale, maxPoints) {}

void PlaneTraceObject::apply(const ObjectOptions& o) {
  line_.setAppearance(o.traceColor.value_or(o.color.value_or(Rgb{0.82, 0.13, 0.1})), o.lineWidth, o.opacity, o.enabled);
}

void PlaneTraceObject::advance(const FrameState& s) {
  if (s.pose) line_.append(s.pose->contact[0], s.pose->contact[1], s.pose->contact[2] + lift_);
}

} // namespace rv
