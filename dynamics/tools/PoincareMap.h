// PoincareMap.h -- points where a trajectory crosses a section (manual §2.3.1): the section is a level of an
// observable (an angle's level is crossed where sin(value - v0) changes sign with cos > 0), crossings are
// bracketed between steps and located on the integrator's dense output by the Illinois variant of regula
// falsi (Dowell & Jarratt, BIT 11 (1971) 168) to the requested accuracy in time. For an explicit map every
// iterate is a point.
#pragma once
#include "dynamics/core/ParameterTable.h"
#include "dynamics/integrators/Integrator.h"
#include "dynamics/tools/ToolControl.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rv {

struct SectionSettings {
  std::string observable; ///< empty: the model's default section
  double value = 0;       ///< the section's level
  bool checkDirection = true;
  int direction = +1;       ///< +1: the observable increases through the level, -1: decreases
  double accuracy = 1e-12;  ///< of the crossing time
  bool backward = false;    ///< integrate backward in time
  bool manySheeted = false; ///< keep only points on sheet `root`
  int root = 1;
  int order = 1;          ///< keep every order-th crossing (the map to this power)
  long maxPoints = 2000;  ///< how many points a map computes; 0: no limit (a trajectory run until stopped)
  double maxTime = 1e300; ///< stop integrating at this time
};

/// The scene section "poincare": its numbers and choices (the one declaration of their defaults; the
/// section's observable is the text key "section").
const ParameterTable& poincareTable();
/// The settings from the table's values and the section's observable (empty: the model's default).
SectionSettings poincareSettings(const ParameterValues& v, std::string observable);

struct MapPoint {
  std::vector<double> coordinates;
  double time = 0;
  int sheet =
      0; ///< the sheet (root of the completion) in many-sheeted mode; 0: not determined (it can be costly)
};

/// The crossings of one orbit with a section, found step by step from the steps an integrator takes: what a
/// PoincareMap integrates for, and what orbits integrated side by side on SIMD lanes find lane by lane
/// (dynamics/tools/TrajectoryLanes.h) -- the same points, bit for bit, from the same steps.
class SectionCrossings {
public:
  /// Throws InputError for an unknown section or an order below 1.
  SectionCrossings(const Model& model, SectionSettings settings);
  /// The orbit's first state: a start on the section is not its own first return.
  void start(double t, const Eigen::VectorXd& x);
  /// The step's dense output: the state at t in the last step.
  using Interpolate = std::function<void(double t, Eigen::VectorXd& out)>;
  /// After a step from tPrevious to t that ends at state x, integrating in `direction` (+1, -1): the point
  /// where it crosses the section, if the settings keep it (its direction, order and sheet).
  std::optional<MapPoint> afterStep(double tPrevious, double t, const Eigen::VectorXd& x, int direction,
                                    const Interpolate& interpolate);
  const std::vector<std::string>& coordinateNames() const { return names_; }
  /// The map coordinates of a state.
  std::vector<double> coordinatesOf(double t, const Eigen::VectorXd& x) const;
  /// The full state at the last point kept.
  const Eigen::VectorXd& lastState() const { return last_; }
  /// How many points it has kept.
  long points() const { return points_; }
  void save(Snapshot& s) const;
  void restore(Snapshot& s);

private:
  double sectionFunction(double t, const Eigen::VectorXd& x) const;
  bool acceptable(double t, const Eigen::VectorXd& x) const;
  const Model& model_;
  SectionSettings s_;
  const Observable* section_ = nullptr;
  std::vector<const Observable*> coords_;
  std::vector<std::string> names_;
  Eigen::VectorXd last_, work_;
  double sigma_ = 0;
  bool startOnSection_ = false; ///< a start on the section is not a crossing
  long crossings_ = 0, points_ = 0;
};

class PoincareMap {
public:
  /// `integrator` must be started (at the trajectory's first point). Throws InputError for an unknown
  /// section.
  PoincareMap(const Model& model, std::unique_ptr<Integrator> integrator, SectionSettings settings);
  /// The next point kept by the settings; nothing when stopped, at maxTime or after maxPoints points.
  std::optional<MapPoint> next(const ToolControl& control = {});
  /// Names of the map coordinates (the model's, or its core state for systems without them).
  const std::vector<std::string>& coordinateNames() const { return crossings_.coordinateNames(); }
  /// The full state at the last point returned.
  const Eigen::VectorXd& lastState() const { return crossings_.lastState(); }
  long points() const { return crossings_.points(); }
  const Integrator& integrator() const { return *integ_; }
  /// Called after every step of the integrator (the filters fed by a running map, manual §2.4); the
  /// observer runs on the caller's thread, inside next().
  void setStepObserver(std::function<void(const Integrator&)> observer) { observer_ = std::move(observer); }
  /// Saves where the map stands (its integrator, the section's last value, the counts): restore() into a map
  /// built from the same model and settings goes on with bit-identical points (resumable runs).
  void save(Snapshot& s) const;
  void restore(Snapshot& s);
  /// The map coordinates of a state.
  std::vector<double> coordinatesOf(double t, const Eigen::VectorXd& x) const {
    return crossings_.coordinatesOf(t, x);
  }

private:
  std::unique_ptr<Integrator> integ_;
  SectionSettings s_;
  SectionCrossings crossings_;
  std::function<void(const Integrator&)> observer_;
};

} // namespace rv
