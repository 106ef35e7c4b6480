// Chart.h -- what every chart window shows through: a 2D chart (PoincareChart and the tool charts) or a 3D
// one (Chart3D), drawn into a render window on screen or headless.
#pragma once
#include <ostream>

class vtkRenderWindow;

namespace rv {

class Chart {
public:
  virtual ~Chart() = default;
  /// Draws into `window` (the chart takes it over).
  virtual void attach(vtkRenderWindow* window) = 0;
  /// The data drawn, as CSV with a header: series, then the coordinates (round-trip exact).
  virtual void writeCsv(std::ostream& out) const = 0;
  /// The chart coordinates of a point of the window (pixels from the bottom left); false outside the plot
  /// area or for charts without a plane.
  virtual bool toChart(double px, double py, double& x, double& y) const {
    (void)px, (void)py, (void)x, (void)y;
    return false;
  }
};

} // namespace rv
