// ToolRunner.h -- the runnable part of a registered tool (dynamics/tools/ToolRegistry.h), in the layer that
// knows scenes: what the tool computes on a scene with its settings (the scene's section of the tool), under
// a stop/progress control, producing the outputs its entry declares, and how a result is drawn. Every front
// end derives its part from it: the CLI subcommand (the settings table's flags and the common ones), the
// Python method, the chart view (GUI chart window, `rollviz chart`), the sweep quantities (the outputs
// declared `quantity`), `describe-tool`. Modules add tools this way (scenes/Module.h).
#pragma once
#include "dynamics/core/Snapshot.h"
#include "dynamics/tools/ToolControl.h"
#include "dynamics/tools/ToolRegistry.h"
#include "render/charts/Chart.h"
#include "render/export/VtkXmlFiles.h"
#include "scenes/Scene.h"
#include "scenes/SceneLoader.h"

#include <array>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

namespace rv {

/// A result on a regular grid of nodes (surface, RAM): the table's rows are the nodes, x fastest, and its
/// first `coordinates` columns their coordinates. The CLI writes it as image data (-o FILE.vti), Python gives
/// the axes and each other column shaped (ny, nx) or (nz, ny, nx).
struct ToolGrid {
  int dimensions = 0;               ///< the axes it spans: 2 or 3 (0: the result is no grid)
  int coordinates = 0;              ///< the coordinate columns: a 2D grid of a 3D map has 3 (z constant)
  std::array<int, 3> size{1, 1, 1}; ///< nodes per axis (1 along an axis the grid does not span)
  std::array<double, 3> origin{0, 0, 0}, spacing{1, 1, 1};
};

/// A column of text among a result's numbers (a branch's id, a fixed point's type): the CSV writes it in its
/// place, Python gives a list of str.
struct TextColumn {
  std::string name;
  std::vector<std::string> values; ///< one per row of the table
  std::size_t at = 0;              ///< its place: before the table's column `at` (names.size(): the last)
};

/// What one run of a tool produced.
struct ToolResult {
  /// The named outputs (numbers, strings, arrays): `--json`, the Python result's keys, sweep quantities.
  nlohmann::json fields = nlohmann::json::object();
  /// The rows it computed (the CSV of `-o`, the Python result's arrays); may have no columns.
  NamedColumns table;
  /// Its columns of text, beside the table's numbers.
  std::vector<TextColumn> text = {};
  /// Stopped on request: the fields and rows hold what was computed until then.
  bool stopped = false;
  /// Where the rows are the nodes of a grid: its shape.
  ToolGrid grid = {};
  /// Where the rows are points in space: how many of the first columns (1-3) are their position (the others
  /// are data at the points in a .vtp).
  int cloud = 0;
  /// What the run said on the way, a line each (where a family's type changes, a tree's ratios): the CLI
  /// prints them (on standard error when the table goes to standard output); --json and Python leave them
  /// out.
  std::vector<std::string> notes = {};
  /// Why the computation ended early with a result worth keeping (a family that cannot be continued past a
  /// point): the CLI writes the result, then fails with this (exit 1); Python's result has it as "failure".
  std::string failure = {};
  /// The Python result where it is shaped otherwise than the fields beside the table's columns (a family's
  /// points as one array; null: those): the runner writes both shapes, so no front end is taught the tool.
  nlohmann::json python = nullptr;
};

/// A call argument of a tool besides its section's settings -- the CLI's `--NAME VALUE`, Python's
/// `NAME=value` -- that stands for scene settings: `--x MIN,MAX` is grid.x_min and grid.x_max. Every front
/// end applies it the same way (toSettings), before the run, so the computation reads settings only.
struct ToolArgument {
  std::string name;        ///< the flag and keyword, e.g. "x"
  std::string valueName;   ///< what the value looks like in --help, e.g. "MIN,MAX"
  std::string description; ///< one line
  /// The scene settings the value (as text: "0,1"; a Python sequence is joined by commas) stands for;
  /// InputError saying what is wrong with a value it cannot take (each front end puts the argument's name
  /// in its own spelling before it: "--x 1,0: ...", "x=(1, 0): ...").
  std::function<std::vector<SceneOverride>(const std::string& value)> toSettings;
  /// Takes no value (the CLI's `--doubled`, Python's `doubled=True`): toSettings("") when given.
  bool flag = false;
};

/// One run of a tool on a scene that can stop and go on: a stopped chart job continues it (GUI Continue),
/// `--checkpoint` saves it and a later process restores it, to the same result bit for bit.
class ToolRun {
public:
  virtual ~ToolRun() = default;
  /// Goes on from where it stopped (the start, the first time) to the end or a stop request; true when
  /// finished. Reports control.progress; throws ComputationError when the computation fails.
  virtual bool advance(const ToolControl& control) = 0;
  /// What it has computed so far: all of it once finished (`stopped` is set by the caller).
  virtual ToolResult result() const = 0;
  /// Saves what it needs to go on (the table so far included); restore() into a run started alike on the
  /// same scene goes on bit-identically. A run that cannot resume throws InputError.
  virtual void save(Snapshot& state) const = 0;
  virtual void restore(Snapshot& state) = 0;
};

/// Where the GUI shows a tool's run (MainWindow::createTool): what it draws decides, not its id.
enum class ToolWindow {
  Chart,         ///< a chart window of its result, computed as a job of the tool manager
  MapRows,       ///< the map window draws its rows as they come (ToolControl::row): each row's columns named
                 ///< like the map's coordinates place a point; its multipliers (re1, im1, ...) beside a
                 ///< column named like the continued parameter go to the multipliers filters; its notes to
                 ///< the Results dock
  MapTrajectory, ///< the map window's trajectory from the scene's initial state (the Poincare map itself)
  MapSearch,     ///< the map window's fixed-point search from the scene's guess, its path drawn
  PlotWindow     ///< the plot filter's live window, fed by the map window's trajectories
};

/// How a tool runs on a scene and how its result is drawn: `run` computes it at once; `start` instead begins
/// a run that stops and goes on (ToolRun; the CLI command then offers --checkpoint). Give one of them.
struct ToolRunner {
  /// Runs the tool on the scene (its settings: scene.tool(entry.section)); polls control.stopRequested and
  /// reports control.progress. Throws InputError for settings it cannot use, ComputationError when the
  /// computation fails, and returns with `stopped` set when stopped.
  std::function<ToolResult(const Scene&, const ToolControl&)> run;
  /// Draws a result; empty: the table's columns against its first, titled with the quantities
  /// (SceneCharts.cpp draws both; this file stays free of VTK code, so the fuzzers link it).
  std::function<std::unique_ptr<Chart>(const Scene&, const ToolResult&)> chart = {};
  /// Begins a resumable run on the scene (InputError for settings it cannot use).
  std::function<std::unique_ptr<ToolRun>(const Scene&)> start = {};
  /// The name the table goes by as one piece -- the Python result's key that holds it as one Table (e.g.
  /// "history"); empty: each column is a key of its own.
  std::string tableName = {};
  /// Call arguments besides the settings (an argument named like a setting replaces its flag).
  std::vector<ToolArgument> arguments = {};
  /// Its results are grids (ToolResult::grid): the CLI's -o also writes .vti image data.
  bool grid = false;
  /// Settings of its section that do not change the result (threads): a run saved with --checkpoint may be
  /// resumed with other values.
  std::vector<std::string> resultIndependent = {};
  /// The result in words for a terminal (the CLI without --json and -o); empty: each field as "name = value".
  std::function<std::string(const ToolResult&)> describe = {};
  /// The table is what it computes (a family, a branch): without -o the CLI writes its CSV on standard
  /// output.
  bool tableIsResult = false;
  /// Fields (at any depth of the result) that hold complex numbers as [re, im] pairs: Python gives them as
  /// complex arrays.
  std::vector<std::string> complexFields = {};
  /// Where the GUI shows a run (Tools > Create): in a chart window (the default), or drawn on the map window.
  ToolWindow window = ToolWindow::Chart;
  /// Drawn on the map (ToolWindow::MapRows) with multipliers in its rows: the multipliers filters (manual
  /// §2.4.3) show those of its elliptic points only, every one (a bifurcation tree's branches), rather than
  /// one per the filter's period of the parameter (a family).
  bool ellipticMultipliersEachRow = false;
  /// Its results are point clouds (ToolResult::cloud): the CLI's -o also writes .vtp poly data.
  bool cloud = false;
  /// Narrows the scene's settings so that a run computes output `output` alone, faster and to the same value
  /// (a sweep of that output runs it on every point's scene): the lyapunov tool's max follows one tangent
  /// vector, since the largest exponent's vector never sees the others. Empty: nothing to narrow.
  std::function<void(const std::string& output, Scene& scene)> narrowTo = {};
};

/// Begins a run of tool `id` on the scene: the runner's own resumable run, or its `run` wrapped in one that
/// computes from the start each time and cannot be saved (resumable() says which).
std::unique_ptr<ToolRun> startTool(const ToolEntry& tool, const Scene& scene);
/// Whether the tool's runs go on after a stop and can be saved (the runner has `start`).
bool resumable(const ToolEntry& tool);

/// Appends a row to the result's table, with the values of its text columns (in the order of result.text),
/// and hands it on to control.row: how a runner adds a row, so that a front end that draws the rows as they
/// come (the GUI's map window) sees each.
void addRow(ToolResult& result, const ToolControl& control, const std::vector<double>& row,
            const std::vector<std::string>& text = {});
/// Appends a note to the result and hands it on to control.note.
void addNote(ToolResult& result, const ToolControl& control, std::string note);

/// A table in a Snapshot (a ToolRun's save): its names' count, then each column; getTable checks the names.
void putTable(Snapshot& state, const NamedColumns& table);
void getTable(Snapshot& state, NamedColumns& table);

/// Binds a runner to the registered tool `id` (its chart view is the entry's chartView); InputError when the
/// tool is not registered or already has one.
void addToolRunner(const std::string& id, ToolRunner runner);
/// Sets the chart of tool `id`'s runner (kept apart from the computation: rollviz's own charts are bound
/// where VTK is linked); InputError when the tool has no runner.
void addToolChart(const std::string& id,
                  std::function<std::unique_ptr<Chart>(const Scene&, const ToolResult&)> chart);
/// The runner of tool `id`, or nullptr (a tool whose front ends are written by hand).
const ToolRunner* findToolRunner(const std::string& id);
/// The registered tool whose chart view is `view` and that has a runner, or nullptr.
const ToolEntry* runnableToolOfView(const std::string& view);

/// A finished result holds every output the entry declares (a field or a column); else a ComputationError
/// naming the missing one -- a runner that forgets one is not a silent gap in some front end.
void checkToolResult(const ToolEntry& tool, const ToolResult& result);
/// Runs tool `id` on the scene from the start to its end or a stop (startTool, then advance) and checks the
/// result (checkToolResult).
ToolResult runTool(const ToolEntry& tool, const Scene& scene, const ToolControl& control);

/// The sweep quantity an output marked `quantity` is: its quantityName, else "TOOL.OUTPUT".
std::string sweepQuantityId(const ToolEntry& tool, const ToolOutput& output);

/// The scene overrides argument `name` of the runner stands for, given its value as text; InputError for an
/// unknown name.
std::vector<SceneOverride> argumentSettings(const ToolRunner& runner, const std::string& name,
                                            const std::string& value);

/// The result as one JSON object: the fields, and "stopped" when the run was stopped.
nlohmann::json toolResultJson(const ToolResult& result);

} // namespace rv
