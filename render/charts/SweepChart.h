// SweepChart.h -- the chart of a sweep (scenes/Sweep.h): over two axes a coloured map of the grid with a
// colour bar, over one axis a line, and for an orbit diagram the cloud of the map points kept at each value.
#pragma once
#include "render/charts/Chart.h"

#include <memory>
#include <string>
#include <vector>

namespace rv {

/// A curve drawn over a two-axis sweep chart, in its plane (x along the first axis): a bifurcation curve of
/// the same two parameters.
struct SweepOverlay {
  std::string name;
  std::vector<double> x, y;
};

/// What a sweep computed, in grid order (the first axis fastest).
struct SweepChartData {
  std::string title;
  std::vector<std::string> axes;    ///< one or two axis names
  std::vector<int> counts;          ///< grid points per axis
  std::vector<double> mins, maxs;   ///< each axis' range
  std::vector<std::string> columns; ///< the quantity's columns
  /// values[point * columns.size() + c]; NaN where a point failed
  std::vector<double> values;
  bool orbit = false; ///< every column is a point of an orbit diagram (drawn as a cloud over the first axis)
  std::vector<SweepOverlay> overlays; ///< two axes: curves drawn over the map of the grid
};

/// The chart of the data's first column (every column for an orbit diagram).
std::unique_ptr<Chart> makeSweepChart(const SweepChartData& data);

} // namespace rv
