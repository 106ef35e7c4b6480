#include "render/objects/ApexObject.h"

#include "render/objects/Actors.h"

#include <vtkActor.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

namespace rv {

Rgb axisColour(int axis) {
  static const Rgb colours[3] = {{0.86, 0.16, 0.12}, {0.12, 0.63, 0.24}, {0.16, 0.31, 0.86}};
  return colours[axis];
}

ApexObject::ApexObject(std::string name, int axis, LookingIn frame, long maxPoints)
    : VisualObject(std::move(name)), axis_(axis), frame_(frame), trace_(1e-3, maxPoints) {
  dot_ = sphereActor(0.035, 20, 12);
}

void ApexObject::attach(vtkRenderer* renderer) {
  renderer->AddActor(dot_);
  trace_.attach(renderer);
}

void ApexObject::apply(const ObjectOptions& o) {
  const Rgb c = o.colour.value_or(axisColour(axis_));
  dot_->GetProperty()->SetColor(c[0], c[1], c[2]);
  dot_->SetVisibility(o.enabled);
  trace_.setAppearance(o.traceColour.value_or(c), o.lineWidth, o.opacity.value_or(1.0), o.enabled && o.trace);
}

Eigen::Vector3d ApexObject::apexOf(const BodyPose& pose) const {
  return frame_ == LookingIn::Absolute ? Eigen::Vector3d(pose.rotation.col(axis_))
                                       : Eigen::Vector3d(pose.rotation.row(axis_).transpose());
}

void ApexObject::advance(const FrameState& s) {
  if (!s.pose) return;
  tip_ = apexOf(*s.pose);
  // drawn a hair outside the unit sphere so that the sphere does not hide it
  const Eigen::Vector3d p = 1.004 * tip_;
  trace_.append(p[0], p[1], p[2]);
}

void ApexObject::show(const FrameState& s) {
  advance(s);
  dot_->SetPosition(tip_[0], tip_[1], tip_[2]);
}

} // namespace rv
