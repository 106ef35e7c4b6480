#include "dynamics/tools/ToolRegistry.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/tools/FourierSpectrum.h"
#include "dynamics/tools/Megno.h"
#include "dynamics/tools/PlotFilter.h"
#include "dynamics/tools/PoincareMap.h"
#include "dynamics/tools/ToolSettings.h"

namespace rv {

namespace {
std::vector<ToolSection>& sections() {
  static std::vector<ToolSection> s{
      {"poincare", "Poincaré map", &poincareTable(), "section"},
      {"spectrum", "Fourier spectrum", &spectrumSettingsTable().table(), "function"},
      {"fixedpoint", "Fixed point finding", &fixedPointSettingsTable().table()},
      {"continuation", "Fixed point continuation", &continuationSettingsTable().table()},
      {"separatrix", "Separatrix", &separatrixSettingsTable().table()},
      {"bifurcation_tree", "Bifurcating tree", &bifurcationTreeSettingsTable().table()},
      {"bifurcation_curve", "Bifurcation curve", &bifurcationCurveSettingsTable().table()},
      {"grid", "Surface |Map(x) - x| and region of allowed motion", &gridSettingsTable().table()},
      {"diagram", "Topological analysis", &diagramTable()},
      {"lyapunov", "Lyapunov exponents", &lyapunovSettingsTable().table()},
      {"megno", "MEGNO and FLI", &megnoSettingsTable().table()},
      {"plot", "2D / 3D plot", &plotTable()},
  };
  return s;
}
} // namespace

const std::vector<ToolSection>& toolSections() {
  return sections();
}

void addToolSection(ToolSection section) {
  if (const ToolSection* s = findToolSection(section.key))
    throw InputError(alreadyRegistered("settings section", section.key, s->origin));
  sections().push_back(std::move(section));
}

const ToolSection* findToolSection(const std::string& key) {
  for (const auto& s : toolSections())
    if (s.key == key) return &s;
  return nullptr;
}

const ToolRegistry& ToolRegistry::global() {
  return mutableGlobal();
}

void ToolRegistry::add(ToolEntry entry) {
  if (const ToolEntry* e = find(entry.id)) throw InputError(alreadyRegistered("tool", entry.id, e->origin));
  if (!entry.command.empty())
    for (const auto& e : entries_)
      if (e.command == entry.command) throw InputError(alreadyRegistered("command", entry.command, e.origin));
  if (!entry.parent.empty() && !find(entry.parent))
    throw InputError("tool '" + entry.id + "': its parent '" + entry.parent + "' is not registered");
  entries_.push_back(std::move(entry));
}

ToolRegistry& ToolRegistry::mutableGlobal() {
  static ToolRegistry r = [] {
    ToolRegistry t;
    const auto add = [&t](ToolEntry e) { t.entries_.push_back(std::move(e)); };
    add({.id = "poincare",
         .title = "Poincaré map",
         .description = "a trajectory's crossings of the section (poincare.section = poincare.value), on the "
                        "map window",
         .section = "poincare",
         .command = "poincare",
         .commandHelp = "points of the Poincare map of a scene's trajectory, as CSV",
         .chartView = "poincare",
         .outputs = {{"<map coordinates>", "the point on the section"},
                     {"t", "the time of the crossing"},
                     {"sheet", "the root of the completion the point lies on"}},
         .reference = "manual §2.3.1",
         .computation = "dynamics/tools/PoincareMap.h (PoincareMap); as a job dynamics/jobs/PoincareTask.h"});
    add({.id = "spectrum",
         .title = "Fourier spectrum",
         .parent = "poincare",
         .description = "of spectrum.function along the trajectory (a chart window)",
         .section = "spectrum",
         .command = "spectrum",
         .commandHelp = "Fourier spectrum of an observable along a scene's trajectory",
         .chartView = "spectrum",
         .outputs = {{"frequency", "the frequencies (a column of the table)"},
                     {"amplitude", "the amplitude at each frequency (a column of the table)"},
                     {"peaks", "the largest peaks, each a frequency and its amplitude"},
                     {"function", "the observable expanded (spectrum.function)"},
                     {"step", "the sampling step in time"},
                     {"samples", "the number of samples"}},
         .reference = "manual §2.3.2; FFTW",
         .computation = "dynamics/tools/FourierSpectrum.h (fourierSpectrum)"});
    add({.id = "lyapunov",
         .title = "Lyapunov exponents",
         .parent = "poincare",
         .description = "the spectrum of exponents against time (a chart window)",
         .section = "lyapunov",
         .command = "lyapunov",
         .commandHelp = "Lyapunov exponents along a scene's trajectory (Benettin)",
         .chartView = "lyapunov",
         .outputs = {{"exponents", "the estimates at the end in Gram-Schmidt order (L1 the growth of one "
                                   "vector, L1 + L2 of areas, ...; largest first once converged)"},
                     {"max", "L1 at the end of lyapunov.time: the largest exponent once converged", true},
                     {"sum", "their sum (0 for a measure-preserving flow)"},
                     {"time", "the time reached"},
                     {"converged", "whether the stopping rule held"},
                     {"t", "the history's times (every lyapunov.output_period), beside L1, L2, ..."}},
         .reference = "Benettin, Galgani, Giorgilli, Strelcyn, Meccanica 15 (1980) 9-30",
         .computation = "dynamics/tools/Lyapunov.h (LyapunovRun)"});
    add({.id = "megno",
         .title = "MEGNO and FLI",
         .parent = "poincare",
         .description =
             "the chaos indicators against time: <Y> -> 2 on tori, -> 0 on stable periodic orbits of "
             "maps, ~ lambda t / 2 on chaotic orbits (a chart window)",
         .section = "megno",
         .command = "megno",
         .commandHelp = "the chaos indicators MEGNO and FLI along a scene's trajectory",
         .chartView = "megno",
         .outputs = {{"megno",
                      "<Y>, the time-averaged MEGNO at the end of megno.time (2: torus, growing: chaos)",
                      true, "megno"},
                     {"megno_rate", "<Y> / (t/2): tends to the largest Lyapunov exponent on chaotic orbits",
                      true},
                     {"y", "Y, the instantaneous MEGNO at the end"},
                     {"fli", "ln |w(t)|, the fast Lyapunov indicator at the end of megno.time", true, "fli"},
                     {"time", "the time reached"},
                     {"t", "the history's times (every megno.output_period), beside megno, y and fli"}},
         .reference = "Cincotta & Simo, A&AS 147 (2000) 205; Froeschle, Lega & Gonczi, CeMDA 67 (1997) 41",
         .computation = "dynamics/tools/Megno.h (MegnoRun)"});
    add({.id = "map3d",
         .title = "Map3D",
         .parent = "poincare",
         .description = "the map in three dimensions (a chart window)",
         .command = "map3d",
         .commandHelp =
             "the map's points in three dimensions (a 2D map's: the first three state variables), as CSV",
         .chartView = "map3d",
         .outputs = {{"<three coordinates>", "the points in space"}},
         .reference = "manual §2.3.1",
         .computation = "dynamics/tools/PoincareMap.h (PoincareMap)"});
    add({.id = "plot",
         .title = "2D / 3D plot",
         .parent = "poincare",
         .description =
             "the plot section's observables along the 3D view's run and every trajectory of the map "
             "(a live filter window)",
         .section = "plot",
         .command = "plot",
         .commandHelp = "the plot section's observables along a scene's trajectory, as CSV",
         .chartView = "plot",
         .outputs = {{"<plot.x, plot.y[, plot.z]>", "the observables at each output"}},
         .reference = "manual §2.4.1-§2.4.2",
         .computation = "dynamics/tools/PlotFilter.h (PlotSampler); live: dynamics/jobs/PlotTap.h"});
    add({.id = "fixedpoint",
         .title = "Fixed points",
         .description = "Newton (or gradient) search from fixedpoint.guess; its type and multipliers",
         .section = "fixedpoint",
         .command = "fixedpoint",
         .commandHelp = "a fixed point of order n of the scene's map, its multipliers and type",
         .outputs = {{"point", "the fixed point"},
                     {"coordinates", "the names of its coordinates"},
                     {"type", "elliptic, hyperbolic, ..."},
                     {"multipliers", "the eigenvalues of D(Map^n), [re, im] each (complex in Python)"},
                     {"residual", "|Map^n(x) - x|"},
                     {"iterations", "the search's iterations"},
                     {"evaluations", "the map evaluations it spent"},
                     {"order", "n"},
                     {"<path>",
                      "with fixedpoint.path = yes (--path): each point of the search and its residual "
                      "(always in Python, as rows)"}},
         .reference = "manual §2.3.4",
         .computation = "dynamics/tools/FixedPoint.h (findFixedPoint); its runner scenes/MapTools.cpp"});
    add({.id = "continuation",
         .title = "Continuation",
         .parent = "fixedpoint",
         .description = "the family of the fixed point in continuation.parameter up to continuation.to",
         .section = "continuation",
         .command = "continue",
         .commandHelp =
             "continue a fixed point in a parameter: the family, its multipliers and where its type changes",
         .chartView = "continuation",
         .outputs = {{"parameter",
                      "the continued parameter: its name (JSON), its value at each point (a column)"},
                     {"<map coordinates>", "the fixed point"},
                     {"<re1, im1, ...>", "its multipliers"},
                     {"residual", "|Map^n(x) - x| at each point"},
                     {"type", "its type"},
                     {"changes", "JSON: where the type changes"},
                     {"points", "JSON: how many points the family has"},
                     {"end", "JSON: why the family ends"},
                     {"<doubled>",
                      "JSON, with continuation.switch: the family of doubled order followed instead "
                      "(its points are the table)"}},
         .reference = "manual §2.3.5",
         .computation = "dynamics/tools/Continuation.h (Continuation); its runner scenes/MapTools.cpp"});
    add({.id = "multipliers",
         .title = "Multipliers",
         .parent = "continuation",
         .description = "the multipliers of the continued fixed point on the complex plane",
         .command = "multipliers",
         .commandHelp =
             "the multipliers of a fixed point along its continuation (or of the point alone), as CSV",
         .chartView = "multipliers",
         .outputs = {{"step", "the continuation's step (a column, beside re1, im1, re2, im2, ...)"},
                     {"multipliers", "JSON: each step's multipliers, [re, im] each (complex in Python)"}},
         .reference = "manual §2.4.3",
         .computation = "dynamics/tools/Continuation.h (Continuation)"});
    add({.id = "separatrix",
         .title = "Separatrices",
         .parent = "fixedpoint",
         .description = "the branches of the invariant manifolds of a hyperbolic point",
         .section = "separatrix",
         .command = "separatrix",
         .commandHelp = "the separatrices of a hyperbolic fixed point of a 2D map, as CSV",
         .outputs = {{"branch", "1..4, each point's branch"},
                     {"<map coordinates>", "the points of the branch"},
                     {"parameter", "each point's k + s: the image F^k of the linear segment's point s"},
                     {"fixedpoint", "JSON: the hyperbolic point (as the fixedpoint tool gives it)"},
                     {"branches",
                      "JSON: each branch grown: its multiplier, direction (outgoing or incoming), "
                      "linear region and why it ended"}},
         .reference = "manual §2.3.6",
         .computation = "dynamics/tools/Separatrix.h (growSeparatrix); its runner scenes/MapTools.cpp"});
    add({.id = "bifurcation_tree",
         .title = "Bifurcation tree",
         .parent = "fixedpoint",
         .description = "period doublings along the continuation",
         .section = "bifurcation_tree",
         .command = "bifurcation-tree",
         .commandHelp = "the period-doubling cascade of an elliptic fixed point",
         .outputs = {{"level", "the level of each point's branch in the tree (0: the starting family)"},
                     {"order", "the order of each point's branch"},
                     {"<parameter>", "the continued parameter's value at each point"},
                     {"<map coordinates>", "the fixed point"},
                     {"<re1, im1, ...>", "its multipliers"},
                     {"type", "each point's type"},
                     {"doublings", "JSON: each period doubling (level, order, parameter)"},
                     {"ratios", "JSON: the Feigenbaum ratios"},
                     {"end",
                      "why the tree ended (levels reached, the finite value, a family that could not be "
                      "followed, ...)"}},
         .reference = "manual §2.3.7",
         .computation = "dynamics/tools/BifurcationTree.h (bifurcationTree); its runner scenes/MapTools.cpp",
         .alsoSections = {"continuation"}});
    add({.id = "bifurcation_curve",
         .title = "Bifurcation curve",
         .parent = "continuation",
         .description =
             "the curve of a fold, period doubling or Neimark-Sacker point of the continued family in "
             "the plane of continuation.parameter and bifurcation_curve.second_parameter (a chart "
             "window)",
         .section = "bifurcation_curve",
         .command = "bifurcation-curve",
         .commandHelp =
             "continue the fixed point to its first fold, period doubling or Neimark-Sacker point and "
             "follow that bifurcation in two parameters: the curve as CSV, where it meets others",
         .chartView = "bifurcation_curve",
         .outputs = {{"<first>, <second>", "CSV: a point of the curve in the parameter plane"},
                     {"<map coordinates>", "CSV: the fixed point there"},
                     {"kind", "the bifurcation followed"},
                     {"parameters", "the two parameters' ids"},
                     {"start", "the bifurcation the curve starts from: parameter values and point"},
                     {"points", "how many points the curve has"},
                     {"events", "where the curve meets another: what, parameter values, point, multipliers"},
                     {"end", "how each way of the curve ended (the box, a closed curve, ...)"}},
         .reference = "Kuznetsov, Elements of Applied Bifurcation Theory (2004) §10.3; Govaerts (2000) ch. 4",
         .computation =
             "dynamics/tools/BifurcationCurve.h (bifurcationCurve); runner scenes/BuiltinTools.cpp",
         .alsoSections = {"continuation"}});
    add({.id = "surface",
         .title = "Surface |Map(x) - x|",
         .description = "on the grid section's rectangle (a chart window)",
         .section = "grid",
         .command = "surface",
         .commandHelp = "the surface z = |Map^n(x) - x| on a grid: CSV or .vti image data",
         .chartView = "surface",
         .outputs = {{"<map coordinates>", "the grid's node (x fastest)"},
                     {"distance",
                      "|Map^n(x) - x| at the node: zeros are fixed points (NaN: the map is undefined)"},
                     {"least", "the node of the least distance: distance, at (a guess for a fixed point)"},
                     {"nodes", "how many nodes the grid has"},
                     {"done", "how many of them are evaluated"},
                     {"search_path",
                      "with fixedpoint.guess: the search's path from it, drawn on the surface (else empty)"}},
         .reference = "manual §2.3.8",
         .computation = "dynamics/tools/MapGrid.h (MapGrid); runner scenes/GridTools.cpp",
         .alsoSections = {"fixedpoint"}});
    add({.id = "ram",
         .title = "Region of allowed motion",
         .description = "on the grid section's rectangle (a chart window)",
         .section = "grid",
         .command = "ram",
         .commandHelp = "the region of allowed motion on a grid of the map's plane: CSV or .vti image data",
         .chartView = "ram",
         .outputs = {{"<map coordinates>", "the grid's node (x fastest)"},
                     {"allowed", "1 where motion is allowed at the node, 0 where not"},
                     {"level", "2D maps: the height of the energy level above the region (NaN elsewhere)"},
                     {"level_name", "the observable whose value `level` is (grid.level)"},
                     {"allowed_fraction", "the share of the evaluated nodes where motion is allowed"},
                     {"nodes", "how many nodes the grid has"},
                     {"done", "how many of them are evaluated"}},
         .reference = "manual §2.3.9",
         .computation = "dynamics/tools/MapGrid.h (MapGrid); runner scenes/GridTools.cpp",
         .alsoSections = {"fixedpoint"}});
    add({.id = "diagram",
         .title = "Topological analysis",
         .description = "the bifurcation diagram on the plane of first integrals",
         .section = "diagram",
         .command = "diagram",
         .commandHelp = "a bifurcation diagram on the plane of first integrals, with the scene's point",
         .chartView = "bifurcation",
         .outputs = {{"branch", "CSV: the branch's id (the last row, \"state\", is the scene's point)"},
                     {"parameter", "CSV: the branch's parameter"},
                     {"<the diagram's axes>", "CSV: the point on the diagram's plane"},
                     {"diagram", "the diagram's id"},
                     {"title", "what the diagram shows"},
                     {"axes", "the names of its two axes (first integrals)"},
                     {"diagrams", "the ids of every diagram of the problem"},
                     {"branches", "each branch: id, description, parameter and its default min, max, step"},
                     {"state", "the scene's point on the diagram"}},
         .reference = "manual §2.3.10",
         .computation = "dynamics/core/Diagram.h (each model's diagrams(), e.g. "
                        "dynamics/models/ChaplyginDiagram.h); runner scenes/BuiltinTools.cpp"});
    add({.id = "sweep",
         .title = "Chart of regimes (sweep)",
         .description =
             "a number one of the tools above yields (its sweep quantities), over a grid of one or "
             "two model parameters, scene keys or initial map points; on threads or MPI ranks "
             "(docs/sweeps.md)",
         .command = "sweep",
         .commandHelp = "a chart of regimes: a tool's number over a grid of parameters or initial points "
                        "(docs/sweeps.md); runs on threads, or on ranks under mpirun",
         .outputs = {{"<axes>", "the grid point's axis values (the first axis fastest)"},
                     {"<quantity columns>", "the quantity: one column, or several (orbit, reversal, ...)"},
                     {"seconds", "what the point cost"},
                     {"status", "ok, or failed: the reason"}},
         .reference = "Cincotta & Simo, A&AS 147 (2000) 205 (MEGNO charts); Polychronopoulos & Kuck, IEEE TC "
                      "36 (1987) 1425 (guided self-scheduling)",
         .computation = "dynamics/jobs/SweepStore.h (the store, chunks and threads); scenes/Sweep.h "
                        "(evaluateSweepPoint); app/cli/SweepMpi.h (the ranks)",
         .options = &sweepOptionsTable()});
    return t;
  }();
  return r;
}

const ToolEntry* ToolRegistry::find(const std::string& id) const {
  for (const auto& e : entries_)
    if (e.id == id) return &e;
  return nullptr;
}

const ToolEntry& ToolRegistry::get(const std::string& id) const {
  if (const ToolEntry* e = find(id)) return *e;
  std::string known;
  for (const auto& e : entries_)
    known += " " + e.id;
  throw InputError("unknown tool '" + id + "' (known:" + known + ")");
}

} // namespace rv
