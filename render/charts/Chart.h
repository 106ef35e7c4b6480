// Chart.h -- what every chart window shows through: a 2D chart (PoincareChart and the tool charts) or a 3D
// one (Chart3D), drawn into a render window on screen or headless.
#pragma once

class vtkRenderWindow;

namespace rv {

class Chart {
public:
  virtual ~Chart() = default;
  /// Draws into `window` (the chart takes it over).
  virtual void attach(vtkRenderWindow* window) = 0;
};

} // namespace rv
