#include "render/objects/ContactTraceObject.h"

namespace rv {

ContactTraceObject::ContactTraceObject(std::string name, double scale, long maxPoints)
    : VisualObject(std::move(name)), lift_(6e-3 * scale), line_(2e-3 * scale, maxPoints) {}

void ContactTraceObject::apply(const ObjectOptions& o) {
  line_.setAppearance(o.traceColor.value_or(o.color.value_or(Rgb{0.82, 0.13, 0.1})), o.lineWidth, o.opacity,
                      o.enabled);
}

void ContactTraceObject::advance(const FrameState& s) {
  if (!s.pose) return;
  const Eigen::Vector3d p = s.pose->contact + lift_ * s.pose->supportNormal;
  line_.append(p[0], p[1], p[2]);
}

} // namespace rv
