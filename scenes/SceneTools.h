// SceneTools.h -- a scene's map with the fixed-point family's settings folded in (scene sections, then the
// caller's overrides), ready to run: what the command line, the charts and the GUI share.
#pragma once
#include "dynamics/jobs/RunSpec.h"
#include "dynamics/jobs/Task.h"
#include "dynamics/tools/Continuation.h"
#include "dynamics/tools/FixedPoint.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/Scene.h"

#include <complex>
#include <optional>

namespace rv {

/// What a command or a window may change of the scene's fixed-point settings.
struct MapToolOverrides {
  int order = 0;              ///< 0: fixedpoint.order
  std::string method;         ///< empty: fixedpoint.method
  std::vector<double> guess;  ///< empty: fixedpoint.guess, else the scene's initial map point
  std::string parameter;      ///< empty: continuation.parameter
  std::optional<double> to;   ///< continuation.to
  std::optional<double> step; ///< continuation.step
};

class SceneMap {
public:
  /// Throws InputError naming the flag (--order, --method, --guess) for bad values; `needGuess` false for the
  /// grids, which start from no point.
  SceneMap(Scene scene, const MapToolOverrides& overrides = {}, bool needGuess = true);
  SceneMap(const SceneMap&) = delete; // its map refers to its own members
  SceneMap& operator=(const SceneMap&) = delete;

  const Scene& scene() const { return scene_; }
  const RunSpec& spec() const { return run_; }
  const FixedPointSettings& search() const { return search_; }
  const SectionSettings& section() const { return section_; }
  const Eigen::VectorXd& guess() const { return guess_; }
  IntegratorFactory integrators() const;
  /// The scene's map (of order fixedpoint.order).
  ReturnMap map() const;
  /// Continuation settings: the scene's section with the overrides; InputError naming --param, --to, --step.
  ContinuationSettings continuation() const;
  /// A continuation of the scene's fixed point.
  std::unique_ptr<Continuation> continuationRun() const;

private:
  Scene scene_;
  RunSpec run_;
  FixedPointSettings search_;
  SectionSettings section_; ///< of the map's order
  Eigen::VectorXd guess_;
  MapToolOverrides overrides_;
};

/// Edit properties (manual §2.1): gives a stopped tool the values of an edited scene (problem, method,
/// section and the tool's own settings). A Poincare map goes on from where it stopped (returns true); a
/// registered tool run on the map (ToolTask: a search, a family, a separatrix branch, a tree) starts again
/// with them and its own settings, a chart (ChartTask) is computed again with them (returns false). Throws
/// InputError when the tool cannot take them (a map's last point has no state on the new level; a tool with
/// no such settings).
bool editTask(Task& task, const Scene& edited);

/// The scene's Poincare map from its initial state; `points` > 0 overrides poincare.points (default 2000).
std::unique_ptr<PoincareMap> scenePoincareMap(const Scene& scene, long points = 0);

/// The multipliers of the scene's fixed point along its continuation (the scene's continuation section), or
/// of the point alone when the scene continues nothing; a family that ends early is drawn as far as it goes.
std::vector<std::vector<std::complex<double>>> multiplierPath(const SceneMap& map,
                                                              const ToolControl& control);

} // namespace rv
