// Scene.h -- a scene file turned into a dynamics run (model, integrator, initial state) and render options.
#pragma once
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/core/SettingsTable.h"
#include "dynamics/integrators/Integrator.h"
#include "dynamics/jobs/RunSpec.h"
#include "dynamics/tools/PlotFilter.h"
#include "dynamics/tools/PoincareMap.h"
#include "render/ViewOptions.h"

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace rv {

/// The 2D / 3D plot filter of a scene ("plot" section): what to sample and how to draw it.
struct PlotView {
  PlotSettings settings;
  PlotChartOptions chart; ///< the window's ranges, proportions and point type
};

/// Sets a plot's numbers and window options from the "plot" section's table (PlotFilter.h plotTable):
/// period, max_points, time_limit, hold_proportions and point_type.
void applyPlotTable(const ParameterValues& v, PlotView& plot);

/// A validated scene: everything needed to integrate and to draw. Copies are cheap and share the immutable
/// model and parameter values (no JSON is parsed again).
struct Scene {
  std::string source;      ///< the file it came from (for messages)
  nlohmann::json document; ///< the document after --set overrides (what "save" writes)
  const ModelEntry* modelEntry = nullptr;
  std::shared_ptr<const Model> model;
  const IntegratorEntry* integratorEntry = nullptr;
  std::shared_ptr<const ParameterValues> integratorParameters;
  Eigen::VectorXd initialState;
  SectionSettings poincare; ///< "poincare": section, value, direction, points (maxPoints), ...
  PlotView plot;            ///< "plot"
  ViewOptions view;
  /// Every tool section's settings by key ("lyapunov", "fixedpoint", ...; dynamics/tools/ToolRegistry.h
  /// toolSections()), a tool's defaults where the scene gives none.
  std::map<std::string, std::shared_ptr<const ParameterValues>> tools;
  std::vector<double> guess;         ///< "fixedpoint": {"guess": [...]} (empty: none)
  std::string continuationParameter; ///< "continuation": {"parameter": ...}
  std::optional<double> continuationTo;
  /// The settings of a tool section (defaults when the scene has none).
  const ParameterValues& tool(const std::string& key) const { return *tools.at(key); }
  /// The same as the struct its table fills (dynamics/core/SettingsTable.h), e.g.
  /// settings(lyapunovSettingsTable(), "lyapunov").
  template <class S> S settings(const SettingsTable<S>& table, const std::string& key) const {
    return table.read(tool(key));
  }

  /// A fresh integrator of the scene's method, started at t = 0 from the initial state.
  std::unique_ptr<Integrator> startIntegrator() const;
  /// The scene in dynamics terms, for tasks and jobs.
  RunSpec runSpec() const;
};

/// Whether two scenes draw the same Poincare map: the same problem with the same parameter values, the same
/// method with the same settings, the same section (how many points a trajectory makes aside: that only
/// counts for the trajectories to come). What the GUI's Apply keeps the map for.
bool sameMap(const Scene& a, const Scene& b);

/// The observables named `ids` as indices into the model's observables; InputError "WHAT: unknown observable
/// 'x' of PROBLEM (rollviz describe PROBLEM)" for a name it does not know, or when `ids` is empty.
std::vector<int> observableColumns(const Model& model, const std::vector<std::string>& ids,
                                   const std::string& what);

/// What `rollviz integrate` samples: the scene integrated from its initial state, visit(t, row) with the
/// columns' values at t = 0, every, 2 every, ... up to `time`. Stops early (returns false) when visit returns
/// false, or when `keepGoing`, asked at every step with the time reached, returns false (a Ctrl-C polled, a
/// progress line, between rows far apart); throws ComputationError when a step fails.
bool sampleColumns(const Scene& scene, double time, double every, const std::vector<int>& columns,
                   const std::function<bool(double, const std::vector<double>&)>& visit,
                   const std::function<bool(double)>& keepGoing = {});

} // namespace rv
