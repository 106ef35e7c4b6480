// PlaneObject.h -- the supporting plane z = 0: a light checkerboard with a grid of cell size `cell`,
// re-centred under the body as it rolls (snapped to whole cells, so the pattern stays fixed in space).
#pragma once
#include "render/objects/VisualObject.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;

namespace rv {

class PlaneObject final : public VisualObject {
public:
  PlaneObject(std::string name, double cell, double halfSize);
  void attach(vtkRenderer* renderer) override;
  void apply(const ObjectOptions& options) override;
  void show(const FrameState& s) override;

private:
  void place(double cx, double cy);
  double cell_, half_, cx_ = 1e300, cy_ = 1e300;
  vtkSmartPointer<vtkPolyData> quad_;
  vtkSmartPointer<vtkActor> actor_;
};

} // namespace rv
