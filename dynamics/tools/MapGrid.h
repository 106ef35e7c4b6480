// MapGrid.h -- tools that evaluate the map over a grid of its plane (or space), on several threads and
// cancellable: the surface z = |Map^n(x) - x| (manual §2.3.8), whose zeros are the fixed points and whose
// breaks show where map coordinates must be rotated, and the regions of allowed motion (manual §2.3.9): the
// grid points that can be completed into a state at the problem's integrals, with, for 2D maps, the height of
// the energy level above them (the completed value of a chosen state component or observable).
#pragma once
#include "dynamics/tools/ReturnMap.h"

#include <algorithm>
#include <array>
#include <thread>

namespace rv {

/// One axis of a grid: min, min + step, ..., up to max.
struct GridAxis {
  double min = 0, max = 1, step = 0.1;
  int count() const;
  double at(int i) const { return min + i * step; }
};

/// A grid's settings; a default-constructed one holds the defaults of gridSettingsTable() (ToolSettings.h).
struct GridSettings {
  /// the map coordinates in order; the third only for 3D grids
  std::array<GridAxis, 3> axes{GridAxis{-1, 1, 0.02}, GridAxis{-1, 1, 0.02}, GridAxis{0, 1, 0.05}};
  bool threeD = false; ///< a 3D map on a 3D grid (false: the 2D grid, at z = zValue for 3D maps)
  double zValue = 0;   ///< the third coordinate of a 2D section of a 3D map
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
};

/// Values on the grid, x fastest: value(i, j, k) = values[(k * ny + j) * nx + i]; NaN where undefined.
struct GridValues {
  std::array<int, 3> size{1, 1, 1};
  std::vector<double> values;
  std::vector<double> level; ///< RAM: the energy-level height at allowed points (empty for the surface)
  long done = 0;             ///< grid points evaluated
  double& at(int i, int j, int k) {
    return values[(static_cast<std::size_t>(k) * size[1] + j) * size[0] + i];
  }
};

/// Evaluates a grid row by row on `threads` threads; resumable after a stop.
class MapGrid {
public:
  enum class Kind { Surface, AllowedRegion };
  /// `levelObservable`: for the RAM, the observable whose value at the completed state is the energy level's
  /// height (empty: the first core state component that is neither a map coordinate nor the section).
  MapGrid(const ReturnMap& map, Kind kind, GridSettings settings, std::string levelObservable = {});
  /// Goes on with the rows left; true when every point is done, false when stopped.
  bool run(const ToolControl& control = {});
  const GridValues& result() const { return grid_; }
  const GridSettings& settings() const { return s_; }
  const std::string& levelName() const { return levelName_; }
  /// Saves the rows done and their values; restore() into a grid built from the same map and settings (the
  /// number of threads aside) goes on with the rest. The result does not depend on when it was saved.
  void save(Snapshot& s) const;
  void restore(Snapshot& s);
  /// The map point of grid node (i, j, k).
  Eigen::VectorXd node(int i, int j, int k) const;

private:
  void evaluateRow(int row, const ToolControl& control);
  const ReturnMap& map_;
  Kind kind_;
  GridSettings s_;
  int levelIndex_ = -1;
  std::string levelName_;
  GridValues grid_;
  std::vector<char> rowDone_;
};

} // namespace rv
