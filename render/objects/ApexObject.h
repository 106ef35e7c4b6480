// ApexObject.h -- the apex view (manual §2.4.5): the tip of one axis on the unit sphere as the body turns.
// Looking in the absolute frame it is the body's axis e_i seen from space, R e_i; looking in the body's frame
// it is the fixed axis seen from the body, R^T e_i (for z this is the Poisson vector gamma). With or without
// its trace, in the manual's X, Y, Z axis colours.
#pragma once
#include "render/GrowingPolyline.h"
#include "render/objects/VisualObject.h"

#include <vtkSmartPointer.h>

class vtkActor;

namespace rv {

/// The manual's X, Y, Z axis colours (red, green, blue), shared by apexes, the body's box and its axes.
Rgb axisColour(int axis);

class ApexObject final : public VisualObject {
public:
  ApexObject(std::string name, int axis, LookingIn frame, long maxPoints);
  void attach(vtkRenderer* renderer) override;
  void apply(const ObjectOptions& options) override;
  void advance(const FrameState& s) override;
  void show(const FrameState& s) override;
  void clear() override { trace_.clear(); }
  /// Where the apex was in the last state seen (a unit vector).
  const Eigen::Vector3d& tip() const { return tip_; }
  long tracePoints() const { return trace_.size(); }

private:
  Eigen::Vector3d apexOf(const BodyPose& pose) const;
  int axis_;
  LookingIn frame_;
  Eigen::Vector3d tip_ = Eigen::Vector3d::Zero();
  GrowingPolyline trace_;
  vtkSmartPointer<vtkActor> dot_;
};

} // namespace rv
