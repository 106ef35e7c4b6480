// SurfaceObject.h -- the fixed surface a body rolls on when it is not the plane (the ellipsoid under a ball,
// the bowl), drawn from the model's SupportSurface; translucent by default so that the ball and its path stay
// visible.
#pragma once
#include "dynamics/core/Model.h"
#include "render/objects/VisualObject.h"

#include <vtkSmartPointer.h>

class vtkActor;

namespace rv {

class SurfaceObject final : public VisualObject {
public:
  SurfaceObject(std::string name, const SupportSurface& surface);
  void attach(vtkRenderer* renderer) override;
  void apply(const ObjectOptions& options) override;

private:
  vtkSmartPointer<vtkActor> actor_;
};

} // namespace rv
