// FrameObjects.h -- what the apex view shows besides the apexes (manual §2.4.5): the unit sphere, the body
// as a box with faces in the axis colours ("Draw body", X/Y/Z body size), and an arbitrary vector given at
// t = 0 in the frame looked in and carried by the rotation.
#pragma once
#include "render/objects/VisualObject.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkArrowSource;
class vtkCubeSource;

namespace rv {

/// The unit sphere, translucent, with a few meridians and parallels.
class UnitSphereObject final : public VisualObject {
public:
  explicit UnitSphereObject(std::string name);
  void attach(vtkRenderer* renderer) override;
  void apply(const ObjectOptions& options) override;

private:
  vtkSmartPointer<vtkActor> sphere_;
};

/// The body as a box of the given edge lengths along its principal axes, turning with it (fixed when
/// looking in the body's frame).
class BodyBoxObject final : public VisualObject {
public:
  BodyBoxObject(std::string name, LookingIn frame, const std::array<double, 3>& defaultSize);
  void attach(vtkRenderer* renderer) override;
  void apply(const ObjectOptions& options) override;
  void show(const FrameState& s) override;

private:
  LookingIn frame_;
  std::array<double, 3> defaultSize_;
  vtkSmartPointer<vtkCubeSource> cube_;
  vtkSmartPointer<vtkActor> actor_;
};

/// An arrow from the centre: v0 at the first state, then R(t) R(0)^T v0 (absolute frame: a vector fixed in
/// the body) or R(t)^T R(0) v0 (body frame: a vector fixed in space). Hidden unless the scene enables it.
class VectorObject final : public VisualObject {
public:
  VectorObject(std::string name, LookingIn frame);
  bool shownByDefault() const override { return false; }
  void attach(vtkRenderer* renderer) override;
  void apply(const ObjectOptions& options) override;
  void show(const FrameState& s) override;
  void clear() override { haveStart_ = false; }
  /// The vector in the last frame shown.
  const Eigen::Vector3d& value() const { return value_; }

private:
  LookingIn frame_;
  Eigen::Vector3d v0_ = Eigen::Vector3d::UnitZ();
  Eigen::Matrix3d r0_ = Eigen::Matrix3d::Identity();
  bool haveStart_ = false;
  Eigen::Vector3d value_ = Eigen::Vector3d::UnitZ();
  vtkSmartPointer<vtkActor> actor_;
};

} // namespace rv
