// BodyAxesObject.h -- the body's principal axes (manual §2.4.6: the body's axes), three segments from its
// centre along the rotated e1, e2, e3 (red, green, blue), a little longer than the body. Hidden unless the
// scene enables it (view.objects.axes.enabled).
#pragma once
#include "render/objects/VisualObject.h"

#include <array>
#include <vtkSmartPointer.h>

class vtkActor;
class vtkPoints;
class vtkPolyData;

namespace rv {

class BodyAxesObject final : public VisualObject {
public:
  BodyAxesObject(std::string name, const BodyGeometry& geometry, double scale);
  bool shownByDefault() const override { return false; }
  void attach(vtkRenderer* renderer) override;
  void apply(const ObjectOptions& options) override;
  void show(const FrameState& s) override;
  /// The tip of axis i (0, 1, 2) in the last frame shown, in world coordinates.
  const Eigen::Vector3d& tip(int i) const { return tips_[i]; }

private:
  std::array<double, 3> lengths_;
  std::array<Eigen::Vector3d, 3> tips_;
  vtkSmartPointer<vtkPoints> points_;
  vtkSmartPointer<vtkPolyData> data_;
  vtkSmartPointer<vtkActor> actor_;
};

} // namespace rv
