// PlotChart.h -- the chart of the 2D / 3D plot filters (manual §2.4.1-§2.4.2): a PoincareChart for two axes,
// a Chart3D for three, set up by the filter's window options (ranges, hold proportions, point type), with one
// point series per trajectory feeding it. `rollviz chart --view plot` and the live plot window both draw it.
#pragma once
#include "render/ViewOptions.h"
#include "render/charts/Chart3D.h"
#include "render/charts/PoincareChart.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rv {

class PlotChart final : public Chart {
public:
  /// `axes`: the titles of two or three axes.
  PlotChart(const std::vector<std::string>& axes, const PlotChartOptions& options);
  ~PlotChart() override;
  int dimensions() const { return space_ ? 3 : 2; }
  /// A new (empty) series; returns its index.
  int addSeries(const Rgb& colour);
  /// Replaces the points of series `index`: values[i] along axis i (the third ignored in 2D).
  void setSeries(int index, const std::array<std::vector<double>, 3>& values);
  void setColour(int index, const Rgb& colour);
  /// Draws series `index` emphasised (-1: none).
  void select(int index);
  void attach(vtkRenderWindow* window) override;
  void writeCsv(std::ostream& out) const override;

private:
  void fitRanges(); ///< 2D with some ranges given: the others follow the data of every series
  PlotChartOptions options_;
  std::unique_ptr<PoincareChart> plane_;
  std::unique_ptr<Chart3D> space_;
  std::vector<std::array<double, 4>> bounds_; ///< per series (2D): x_min, x_max, y_min, y_max
};

} // namespace rv
