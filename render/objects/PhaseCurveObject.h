// PhaseCurveObject.h -- for systems without a body (Lorenz, ...): the trajectory in the space of the first
// three state components, with a marker at the current state; for point maps, the iterates as dots.
#pragma once
#include "render/GrowingPolyline.h"
#include "render/objects/VisualObject.h"

#include <vtkSmartPointer.h>

class vtkActor;

namespace rv {

class PhaseCurveObject final : public VisualObject {
public:
  PhaseCurveObject(std::string name, double scale, long maxPoints, bool asPoints);
  void attach(vtkRenderer* renderer) override;
  void apply(const ObjectOptions& options) override;
  void advance(const FrameState& s) override;
  void show(const FrameState& s) override;
  void clear() override { line_.clear(); }

private:
  double scale_;
  GrowingPolyline line_;
  vtkSmartPointer<vtkActor> marker_;
};

} // namespace rv
