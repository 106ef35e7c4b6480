// SurfaceObject.h -- the fixed surface a body rolls on when it is not the plane (the ellipsoid under a ball,
// the bowl), drawn from the model's SupportSurface or a sampled implicit surface; translucent by default so
// that the ball and its path stay visible.
#pragma once
#include "dynamics/core/Model.h"
#include "render/objects/VisualObject.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;

namespace rv {

class SurfaceObject final : public VisualObject {
public:
  SurfaceObject(std::string name, const SupportSurface& surface);
  /// A support given as a mesh with texture coordinates (an implicit support, sampled).
  SurfaceObject(std::string name, vtkSmartPointer<vtkPolyData> mesh);
  /// When the body (centred at `centre`, touching the surface at `contact`) rolls inside the surface, leaves
  /// out the faces that look away from it: a camera outside a bowl sees the body rolling in it. A body
  /// outside the surface keeps it whole.
  void hideTheFarSide(const Eigen::Vector3d& contact, const Eigen::Vector3d& centre);
  void attach(vtkRenderer* renderer) override;
  void apply(const ObjectOptions& options) override;

private:
  vtkSmartPointer<vtkActor> actor_;
  vtkSmartPointer<vtkPolyData> mesh_;
};

} // namespace rv
