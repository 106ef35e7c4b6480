// BallObject.h -- a textured ball placed by the body pose, with a soft dark disc on the plane under it
// (a cheap depth cue on software GL).
#pragma once
#include "render/objects/VisualObject.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkTexturedSphereSource;

namespace rv {

class BallObject final : public VisualObject {
public:
  BallObject(std::string name, double radius);
  void attach(vtkRenderer* renderer) override;
  void apply(const ObjectOptions& options) override;
  void show(const FrameState& s) override;

private:
  double radius_;
  vtkSmartPointer<vtkActor> ball_, shadow_;
};

} // namespace rv
