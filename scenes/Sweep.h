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

#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
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

/// One point's outcome on a lane: its values, or the exception its evaluation threw.
struct LaneValues {
  std::vector<double> values;
  std::exception_ptr failure;
};

/// A tool's batch evaluation of its output `output` over the scenes of up to kMaxLanes grid points at once,
/// one per SIMD lane (dynamics/core/Lanes.h): per point its values or what its evaluation threw; nothing
/// where these scenes cannot go together (then each runs alone). Throws Stopped when stopped.
using LanesEvaluator = std::function<std::optional<std::vector<LaneValues>>(
    const std::string& output, const std::vector<Scene>& scenes, const ToolControl& control)>;
/// Gives registered tool `id` a batch evaluation on lanes, which every sweep of its outputs then uses (the
/// megno tool's is bound by registerBuiltinTools; a module's tool may bind one). InputError when it has one.
void addLanesEvaluator(const std::string& id, LanesEvaluator evaluate);
/// Tool `id`'s batch evaluation on lanes, or nullptr.
const LanesEvaluator* findLanesEvaluator(const std::string& id);

/// Grid points that go on lanes together: each point's model and initial state, and their common method and
/// settings.
struct PointsOnLanes {
  std::vector<const Model*> models;
  std::vector<Eigen::VectorXd> starts;
  RunSpec run;
};
/// The points of `scenes` where they may go on lanes together: their scenes differ only in the initial state
/// and the model's parameters (one problem, method and settings; each point its own model); else nothing.
std::optional<PointsOnLanes> pointsOnLanes(const std::vector<Scene>& scenes);

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
  /// Its first column is a category (a type, a count, yes/no): refined on any change.
  bool categorical = false;
  /// Its values at up to kMaxLanes grid points' scenes at once, one per SIMD lane (dynamics/core/Lanes.h), or
  /// nothing where these points cannot go together (another model, integrator or setting; a model without a
  /// lane kernel): then each is evaluated alone. Per point: its values, or what its evaluation threw.
  /// Throws Stopped when stopped. Unset for quantities that do not run on lanes.
  std::function<std::optional<std::vector<LaneValues>>(const SweepSpec&, const std::vector<Scene>&,
                                                       const ToolControl&)>
      evaluateLanes;
  /// Narrows a grid point's scene to what this quantity needs, the same numbers faster
  /// (ToolRunner::narrowTo); applied before `evaluate` and `evaluateLanes`, not to the scene a point opens in
  /// the GUI. May be empty.
  std::function<void(Scene&)> narrow = {};
};

/// Every quantity a sweep can chart: those the tools add (addSweepQuantity), then a number for each output
/// marked `quantity` (ToolEntry::outputs) of every tool with a runner.
const std::vector<SweepQuantity>& sweepQuantities();
/// Adds a quantity its tool computes otherwise than by reading a number of its result (a count of
/// exponents, a fixed point's type code, an orbit diagram): a built-in tool registers its own
/// (scenes/builtin/BuiltinTool.h), before the first sweep. InputError when the id is taken.
void addSweepQuantity(SweepQuantity quantity);

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
  /// Refinement levels (options.refine): the axes hold the finest grid, (count - 1) 2^refine + 1 values, of
  /// which the sweep computes the file's grid and then, level after level, the cells where the regimes meet.
  int refine = 0;
  double refineThreshold = 0; ///< options.refine_threshold
  /// options.refine_by value: cells are halved where corners lie on different sides of refineAt (NaN: by
  /// refineThreshold).
  double refineAt = std::numeric_limits<double>::quiet_NaN();
  int lanes = 0; ///< options.lanes: 0 points on SIMD lanes where the quantity can, 1 one at a time
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

/// The same sweep over another window (a zoom into its chart): `bounds` = min, max of each axis in order, at
/// the same counts (and refinement). InputError naming `what` (e.g. "--window") for a wrong count or an empty
/// range.
SweepSpec zoomSweep(const SweepSpec& spec, const std::vector<double>& bounds, const std::string& what);
/// The same sweep with some of its options changed (e.g. {"lanes": 1}): InputError naming `what` for a bad
/// one.
SweepSpec sweepWithOptions(const SweepSpec& spec, const nlohmann::json& options, const std::string& what);

/// The scene of grid point `index` (what "open this point" shows): InputError when the axis values make no
/// valid scene.
Scene sweepPointScene(const SweepSpec& spec, long index);

/// Computes grid point `index`; never throws: a point that fails is a record with ok = false and the reason.
SweepRecord evaluateSweepPoint(const SweepSpec& spec, long index, const ToolControl& control);
/// How many points evaluateSweepPoints takes at once: where the quantity runs on lanes, options.lanes, or the
/// CPU's width (laneWidth: 8 with AVX-512, else 4) where that is 0; else 1.
int sweepBatch(const SweepSpec& spec);
/// Computes the grid points `indices` (any number), each record handed to `sink` as it is computed, as
/// evaluateSweepPoint gives it: where the quantity runs on SIMD lanes, sweepBatch points at once (each
/// point's seconds: its share of its batch), and a point with no scene at its values takes no lane (the next
/// point does). Stops between batches when `control` asks (a batch cut short: records "stopped").
void evaluateSweepPoints(const SweepSpec& spec, const std::vector<long>& indices, const ToolControl& control,
                         const RecordSink& sink);
/// The same, the records returned in the order of `indices` (those a stop left out: "stopped").
std::vector<SweepRecord> evaluateSweepPoints(const SweepSpec& spec, const std::vector<long>& indices,
                                             const ToolControl& control);

/// The CSV header: the axes, the quantity's columns, seconds (with `timing`: what each point cost, the one
/// column that differs between runs), status. Without it the CSV of a sweep is the same file on any number of
/// threads and ranks.
std::vector<std::string> sweepCsvHeader(const SweepSpec& spec, bool timing = false);
/// The chart's description of the sweep (axes, ranges, columns), without values.
SweepChartData sweepChartData(const SweepSpec& spec);
/// The values of a finished sweep's CSV (written by `rollviz sweep` from this sweep file, with or without the
/// seconds column): InputError naming `what` (e.g. "--csv") when its header or rows do not match the sweep.
std::vector<double> readSweepCsv(const SweepSpec& spec, const std::string& path, const std::string& what);

/// The refinement level of a grid point: 0 on the sweep file's grid, L where it first appears at level L.
int sweepPointLevel(const SweepSpec& spec, long index);
/// The points level `level` computes (a flag per point; with level > 0 the points before it must be done):
/// level 0 is the sweep file's grid; level L halves every cell of level L - 1 whose corners differ (by more
/// than refine_threshold times the quantity's range over the grid of level 0, any change of a categorical
/// quantity, a failed corner beside a computed one).
std::vector<char> sweepLevelPoints(const SweepSpec& spec, const SweepStore& store, int level);
/// Runs a sweep level after level (one level without refinement): `runLevel` computes what the scheduler
/// hands out and says whether it finished (false: stopped, and so is the sweep). Returns whether the sweep is
/// complete. A store with records (a checkpoint) goes on where it stopped: the levels are a function of the
/// records.
bool runSweepLevels(const SweepSpec& spec, SweepStore& store, int workers,
                    const std::function<bool(ChunkScheduler&)>& runLevel);
/// The values of every grid point (points x columns, the first axis fastest): those computed as recorded, the
/// others of a refined sweep painted from the nearest computed point of the finest level around them (NaN
/// where none is computed yet, or where a point failed).
std::vector<double> sweepGridValues(const SweepSpec& spec, const SweepStore& store);
/// The same from points kept elsewhere: `done(i)` whether point i is computed, `read(i)` its record.
std::vector<double> sweepGridValues(const SweepSpec& spec, const std::function<bool(long)>& done,
                                    const std::function<SweepRecord(long)>& read);

/// One CSV row of a point (status "ok" or "failed: reason", quoted).
std::string sweepCsvRow(const SweepSpec& spec, long index, const SweepRecord& record, bool timing = false);

} // namespace rv
