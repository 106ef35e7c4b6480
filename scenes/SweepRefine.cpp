// SweepRefine.cpp -- a sweep refined where its regimes meet (scenes/Sweep.h): the levels of the grid, the
// cells each level halves, the levels run in turn, and the grid's values painted from the points computed.
#include "dynamics/core/NaN.h"
#include "scenes/SweepGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rv {

namespace {

// calls visit(k) for every point from `from` to `to` (per axis, inclusive) in steps of `step`
template <class Visit>
void forLattice(const std::vector<long>& from, const std::vector<long>& to, long step, Visit visit) {
  std::vector<long> k = from;
  while (true) {
    visit(k);
    std::size_t a = 0;
    for (; a < k.size(); ++a) {
      if (k[a] + step <= to[a]) {
        k[a] += step;
        break;
      }
      k[a] = from[a];
    }
    if (a == k.size()) return;
  }
}

} // namespace

std::vector<long> sweepGridIndices(const SweepSpec& spec, long index) {
  std::vector<long> k;
  for (const auto& a : spec.axes) {
    k.push_back(index % a.count);
    index /= a.count;
  }
  return k;
}

long sweepGridIndex(const SweepSpec& spec, const std::vector<long>& k) {
  long index = 0;
  for (std::size_t a = spec.axes.size(); a-- > 0;)
    index = index * spec.axes[a].count + k[a];
  return index;
}

int sweepPointLevel(const SweepSpec& spec, long index) {
  int level = 0;
  const auto k = sweepGridIndices(spec, index);
  for (std::size_t a = 0; a < k.size(); ++a) {
    int zeros = 0; // how many times 2 divides the index (an index 0 lies on every level's lattice)
    for (long v = k[a]; v != 0 && v % 2 == 0 && zeros < spec.refine; v /= 2)
      ++zeros;
    if (k[a] == 0) zeros = spec.refine;
    level = std::max(level, spec.refine - zeros);
  }
  return level;
}

std::vector<char> sweepLevelPoints(const SweepSpec& spec, const SweepStore& store, int level) {
  const long n = spec.points();
  std::vector<char> wanted(static_cast<std::size_t>(n), 0);
  if (level == 0) {
    for (long i = 0; i < n; ++i)
      wanted[static_cast<std::size_t>(i)] = sweepPointLevel(spec, i) == 0 ? 1 : 0;
    return wanted;
  }
  const long cell = 1L << (spec.refine - level + 1), half = cell / 2; // the cells of level - 1, halved
  // the quantity's range over level 0: what "differ" is measured against
  double lo = INFINITY, hi = -INFINITY;
  for (long i = 0; i < n; i += 1) {
    if (sweepPointLevel(spec, i) != 0 || !store.done(i)) continue;
    const SweepRecord r = store.read(i);
    if (r.ok && !r.values.empty() && std::isfinite(r.values[0])) {
      lo = std::min(lo, r.values[0]);
      hi = std::max(hi, r.values[0]);
    }
  }
  const double tolerance = hi > lo ? spec.refineThreshold * (hi - lo) : 0.0;
  const auto differ = [&](const SweepRecord& a, const SweepRecord& b) {
    if (a.ok != b.ok) return true;
    if (!a.ok) return false;
    const double x = a.values.empty() ? kNaN : a.values[0], y = b.values.empty() ? kNaN : b.values[0];
    if (std::isnan(x) || std::isnan(y)) return std::isnan(x) != std::isnan(y);
    if (!std::isnan(spec.refineAt)) return (x < spec.refineAt) != (y < spec.refineAt); // across the value
    return spec.quantity->categorical ? x != y : std::abs(x - y) > tolerance;
  };
  std::vector<long> origin(spec.axes.size(), 0), last(spec.axes.size()), cellLast(spec.axes.size());
  for (std::size_t a = 0; a < spec.axes.size(); ++a)
    last[a] = spec.axes[a].count > 1 ? spec.axes[a].count - 1 - cell : 0; // the last cell's origin
  forLattice(origin, last, cell, [&](const std::vector<long>& c) {
    // a cell of level - 1 exists where every corner is computed (its parent was halved)
    std::vector<SweepRecord> corners;
    std::vector<long> far(c);
    for (std::size_t a = 0; a < c.size(); ++a)
      far[a] = spec.axes[a].count > 1 ? c[a] + cell : c[a];
    bool complete = true;
    forLattice(c, far, cell, [&](const std::vector<long>& k) {
      const long i = sweepGridIndex(spec, k);
      if (!store.done(i)) {
        complete = false;
        return;
      }
      corners.push_back(store.read(i));
    });
    if (!complete) return;
    bool split = false;
    for (std::size_t p = 1; p < corners.size() && !split; ++p)
      split = differ(corners[0], corners[p]);
    if (!split) return;
    forLattice(c, far, half, [&](const std::vector<long>& k) {
      const long i = sweepGridIndex(spec, k);
      if (!store.done(i)) wanted[static_cast<std::size_t>(i)] = 1;
    });
  });
  return wanted;
}

bool runSweepLevels(const SweepSpec& spec, SweepStore& store, int workers,
                    const std::function<bool(ChunkScheduler&)>& runLevel) {
  const long chunk = static_cast<long>(spec.options->get("chunk"));
  for (int level = 0; level <= spec.refine; ++level) {
    ChunkScheduler scheduler(store, workers, chunk,
                             spec.refine > 0 ? sweepLevelPoints(spec, store, level) : std::vector<char>{},
                             sweepBatch(spec));
    if (!runLevel(scheduler)) return false;
  }
  return true;
}

namespace {

// the grid's values from the points computed (done(i), read(i)): see sweepGridValues
template <class Done, class Read>
std::vector<double> gridValues(const SweepSpec& spec, const Done& done, const Read& read) {
  const std::size_t columns = spec.columns.size();
  const long n = spec.points();
  std::vector<double> values(static_cast<std::size_t>(n) * columns, kNaN);
  const auto put = [&](long to, const SweepRecord& r) {
    for (std::size_t c = 0; c < columns && c < r.values.size(); ++c)
      values[static_cast<std::size_t>(to) * columns + c] = r.values[c];
  };
  if (spec.refine == 0) {
    for (long i = 0; i < n; ++i)
      if (done(i)) put(i, read(i));
    return values;
  }
  // coarse to fine: each computed point paints the box of its level's half spacing around it, finer points
  // over coarser ones
  std::vector<std::vector<long>> byLevel(static_cast<std::size_t>(spec.refine) + 1);
  for (long i = 0; i < n; ++i)
    if (done(i)) byLevel[static_cast<std::size_t>(sweepPointLevel(spec, i))].push_back(i);
  for (int level = 0; level <= spec.refine; ++level) {
    const long reach = (1L << (spec.refine - level)) / 2;
    for (long i : byLevel[static_cast<std::size_t>(level)]) {
      const SweepRecord r = read(i);
      const auto k = sweepGridIndices(spec, i);
      std::vector<long> from(k), to(k);
      for (std::size_t a = 0; a < k.size(); ++a) {
        from[a] = std::max(0L, k[a] - reach);
        to[a] = std::min<long>(spec.axes[a].count - 1, k[a] + reach);
      }
      forLattice(from, to, 1, [&](const std::vector<long>& p) { put(sweepGridIndex(spec, p), r); });
    }
  }
  return values;
}

} // namespace

std::vector<double> sweepGridValues(const SweepSpec& spec, const SweepStore& store) {
  return gridValues(
      spec, [&](long i) { return store.done(i); }, [&](long i) { return store.read(i); });
}

std::vector<double> sweepGridValues(const SweepSpec& spec, const std::function<bool(long)>& done,
                                    const std::function<SweepRecord(long)>& read) {
  return gridValues(spec, done, read);
}

} // namespace rv
