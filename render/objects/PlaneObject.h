// PlaneObject.h -- the supporting plane z = 0: a light checkerboard with a grid of cell size `cell`,
// re-centred under the body as it rolls (snapped to whole cells, so the pattern stays fixed in space).
// When the opaque floor fills the whole view the renderer's gradient background, hidden anyway, is not drawn
// for that frame: on software GL that is ~13 % of a 1080p frame (tests/bench).
#pragma once
#include "render/objects/VisualObject.h"

#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace rv {

class PlaneObject final : public VisualObject {
public:
  PlaneObject(std::string name, double cell, double halfSize);
  ~PlaneObject() override;
  void attach(vtkRenderer* renderer) override;
  void apply(const ObjectOptions& options) override;
  void show(const FrameState& s) override;

  /// Whether the floor, opaque, covers every pixel of the renderer's view (within the clipping range).
  bool fillsTheView() const;

private:
  void place(double cx, double cy);
  void beforeFrame();
  void afterFrame();
  vtkWeakPointer<vtkRenderer> renderer_;
  unsigned long startObserver_ = 0, endObserver_ = 0;
  bool backgroundHidden_ = false; ///< this frame's gradient was switched off here, to be switched back on
  double cell_, half_, cx_ = 1e300, cy_ = 1e300;
  vtkSmartPointer<vtkPolyData> quad_;
  vtkSmartPointer<vtkActor> actor_;
};

} // namespace rv
