// Sweep.h -- charts of regimes: a number a registered tool produces (the largest Lyapunov exponent, MEGNO,
// a fixed point's type, ...) evaluated over a grid of one or two axes -- model parameters, scene keys
// (dotted, as with --set) or the initial point on the Poincare section (`map.0`, `map.1`). A sweep file
// (JSON) names the scene, the axes, the quantity, overrides of the scene (`set`) and the sweep's own options;
// docs/sweeps.md describes it. Every grid point is an independent run of a scene, so points can be computed
// in any order, on any thread or MPI rank, with the same result (dynamics/jobs/SweepStore.h).
#pragma once
#include "dynamics/core/ParameterTable.h"
#include "dynamics/jobs/SweepStore.h"
#include "render/charts/SweepChart.h"
#include "scenes/Scene.h"

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rv {

/// One axis of the grid: count values from min to max, evenly spaced (count 1: min).
struct SweepAxis {
  std::string id; ///< a model parameter, a dotted scene key, or map.K (the K-th map coordinate)
  double min = 0, max = 0;
  int count = 1;
  int mapCoordinate = -1; ///< K for map.K, else -1
  double at(int i) const;
};

struct SweepSpec;

/// A number per grid point, computed by a registered tool (ToolRegistry id `tool`).
struct SweepQuantity {
  std::string id;          ///< as written in a sweep file; a trailing '.' takes a name ("observable.")
  std::string tool;        ///< the registered tool that computes it ("": the scene's own integration)
  std::string description; ///< one line for `rollviz list quantities` and docs
  /// The CSV columns it fills.
  std::function<std::vector<std::string>(const SweepSpec&)> columns;
  /// Its values at one grid point's scene; throws ComputationError (or Stopped) when there are none.
  std::function<std::vector<double>(const SweepSpec&, const Scene&, const ToolControl&)> evaluate;
  bool needsMap = false;     ///< computed on the scene's map: a flow needs a Poincare section
  bool cloud = false;        ///< every column is a point of an orbit diagram (drawn as a cloud)
  bool optionalName = false; ///< takes ".NAME" but has a default (reversal[.NAME])
};

/// Every quantity a sweep can chart.
const std::vector<SweepQuantity>& sweepQuantities();

/// A validated sweep.
struct SweepSpec {
  std::string source; ///< the sweep file (for messages)
  std::string title;
  /// The sweep with the scene inlined and `set` applied: what MPI ranks receive and what names a checkpoint.
  nlohmann::json resolved;
  Scene base; ///< the scene after `set`
  std::vector<SweepAxis> axes;
  const SweepQuantity* quantity = nullptr;
  std::string quantityName; ///< the name after the prefix (observable.NAME, reversal.NAME)
  std::shared_ptr<const ParameterValues> options;
  std::vector<std::string> columns; ///< the quantity's CSV columns
  long points() const;
  /// The grid indices of a point (the first axis fastest) and its axis values.
  std::vector<double> axisValues(long index) const;
  /// An axis' name for charts: the id, for map axes with the coordinate's name ("py (map.1)").
  std::string axisLabel(std::size_t axis) const;
};

/// Reads and validates a sweep file: InputError "file:field: reason" for an unknown axis or quantity, a count
/// below 1, min above max, a missing scene, ...
SweepSpec loadSweep(const std::string& path);
/// Validates a sweep document; its "scene" is a path (relative to `source`'s folder, then to the working
/// folder) or the scene document itself.
SweepSpec sweepFromJson(nlohmann::json document, const std::string& source);

/// The scene of grid point `index` (what "open this point" shows): InputError when the axis values make no
/// valid scene.
Scene sweepPointScene(const SweepSpec& spec, long index);

/// Computes grid point `index`; never throws: a point that fails is a record with ok = false and the reason.
SweepRecord evaluateSweepPoint(const SweepSpec& spec, long index, const ToolControl& control);

/// The CSV header: the axes, the quantity's columns, seconds (with `timing`: what each point cost, the one
/// column that differs between runs), status. Without it the CSV of a sweep is the same file on any number of
/// threads and ranks.
std::vector<std::string> sweepCsvHeader(const SweepSpec& spec, bool timing = false);
/// The chart's description of the sweep (axes, ranges, columns), without values.
SweepChartData sweepChartData(const SweepSpec& spec);
/// The values of a finished sweep's CSV (written by `rollviz sweep` from this sweep file, with or without the
/// seconds column): InputError naming `what` (e.g. "--csv") when its header or rows do not match the sweep.
std::vector<double> readSweepCsv(const SweepSpec& spec, const std::string& path, const std::string& what);

/// One CSV row of a point (status "ok" or "failed: reason", quoted).
std::string sweepCsvRow(const SweepSpec& spec, long index, const SweepRecord& record, bool timing = false);

} // namespace rv
