#include "dynamics/tools/MapGrid.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>

namespace rv {

int GridAxis::count() const {
  return static_cast<int>(std::floor((max - min) / step * (1 + 1e-12))) + 1;
}

MapGrid::MapGrid(const ReturnMap& map, Kind kind, GridSettings settings, std::string levelObservable)
    : map_(map), kind_(kind), s_(settings) {
  const int d = map.dimension();
  if (s_.threeD && d != 3) throw InputError("grid: a 3D grid needs a 3D map");
  if (d != 2 && d != 3) throw InputError("grid: the map must be 2D or 3D");
  if (s_.threads < 1 || s_.threads > 256) throw InputError("--threads: between 1 and 256");
  const int axes = s_.threeD ? 3 : 2;
  long total = 1;
  for (int a = 0; a < axes; ++a) {
    const GridAxis& g = s_.axes[a];
    if (!(g.step > 0) || !(g.max >= g.min) || !std::isfinite(g.min) || !std::isfinite(g.max))
      throw InputError(
          format("grid: axis %s needs min <= max and a positive step", map.coordinateNames()[a].c_str()));
    grid_.size[a] = g.count();
    total *= grid_.size[a];
  }
  if (total > 50'000'000) throw InputError("grid: more than 5e7 points; use larger steps");
  grid_.values.assign(total, std::numeric_limits<double>::quiet_NaN());
  rowDone_.assign(static_cast<std::size_t>(grid_.size[1]) * grid_.size[2], 0);
  if (kind_ == Kind::AllowedRegion && d == 2) {
    const Model& m = map.model();
    if (levelObservable.empty()) {
      const auto& names = m.info().stateNames;
      for (int i = 0; i < m.info().coreDimension && levelObservable.empty(); ++i)
        if (std::find(map.coordinateNames().begin(), map.coordinateNames().end(), names[i]) ==
                map.coordinateNames().end() &&
            names[i] != m.info().section)
          levelObservable = names[i];
    }
    levelIndex_ = m.findObservable(levelObservable);
    if (levelIndex_ < 0) throw InputError("grid.level: unknown observable '" + levelObservable + "'");
    levelName_ = levelObservable;
    grid_.level.assign(total, std::numeric_limits<double>::quiet_NaN());
  }
}

Eigen::VectorXd MapGrid::node(int i, int j, int k) const {
  Eigen::VectorXd x(map_.dimension());
  x[0] = s_.axes[0].at(i), x[1] = s_.axes[1].at(j);
  if (map_.dimension() == 3) x[2] = s_.threeD ? s_.axes[2].at(k) : s_.zValue;
  return x;
}

void MapGrid::evaluateRow(int row, const ToolControl& control) {
  const int j = row % grid_.size[1], k = row / grid_.size[1];
  for (int i = 0; i < grid_.size[0]; ++i) {
    const Eigen::VectorXd x = node(i, j, k);
    const std::size_t at = (static_cast<std::size_t>(k) * grid_.size[1] + j) * grid_.size[0] + i;
    try {
      if (kind_ == Kind::Surface) {
        grid_.values[at] = map_.difference(map_(x, control), x).norm();
      } else {
        const Eigen::VectorXd state = map_.stateOf(x);
        grid_.values[at] = 1;
        if (levelIndex_ >= 0)
          grid_.level[at] = map_.model().observables()[levelIndex_].value(0, state.data());
      }
    } catch (const ComputationError&) {
      if (kind_ == Kind::AllowedRegion) grid_.values[at] = 0; // forbidden; the surface stays undefined (NaN)
    }
  }
}

bool MapGrid::run(const ToolControl& control) {
  const int rows = static_cast<int>(rowDone_.size());
  std::atomic<int> next{0};
  std::atomic<long> finished{0};
  std::atomic<bool> stop{false};
  for (char d : rowDone_)
    finished += d;
  std::mutex progressMutex;
  // the worker threads poll their own flag; the caller's control is only touched under a lock
  const ToolControl local{.stopRequested = [&] { return stop.load(); }};
  const auto work = [&] {
    for (;;) {
      const int row = next++;
      if (row >= rows || stop) return;
      if (rowDone_[row]) continue;
      try {
        evaluateRow(row, local);
      } catch (const Stopped&) {
        return;
      }
      rowDone_[row] = 1;
      const long f = ++finished;
      std::lock_guard lock(progressMutex);
      if (control.stopRequested()) stop = true;
      control.progress(static_cast<double>(f) / rows);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < s_.threads; ++t)
    pool.emplace_back(work);
  work();
  for (auto& t : pool)
    t.join();
  grid_.done = finished.load() * grid_.size[0];
  return finished.load() == rows;
}

void MapGrid::save(Snapshot& s) const {
  const auto column = [](const std::vector<double>& v) {
    return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size())).eval();
  };
  Eigen::VectorXd done(static_cast<Eigen::Index>(rowDone_.size()));
  for (std::size_t r = 0; r < rowDone_.size(); ++r)
    done[static_cast<Eigen::Index>(r)] = rowDone_[r];
  s.put(done), s.put(column(grid_.values)), s.put(column(grid_.level));
}

void MapGrid::restore(Snapshot& s) {
  Eigen::VectorXd done, values, level;
  s.get(done), s.get(values), s.get(level);
  if (static_cast<std::size_t>(done.size()) != rowDone_.size() ||
      static_cast<std::size_t>(values.size()) != grid_.values.size() ||
      static_cast<std::size_t>(level.size()) != grid_.level.size())
    throw InputError("checkpoint: saved for another grid");
  for (std::size_t r = 0; r < rowDone_.size(); ++r)
    rowDone_[r] = done[static_cast<Eigen::Index>(r)] != 0;
  grid_.values.assign(values.data(), values.data() + values.size());
  grid_.level.assign(level.data(), level.data() + level.size());
}

} // namespace rv
