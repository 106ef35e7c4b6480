// PlotFilter.h -- the 2D / 3D plot filters (manual §2.4.1-§2.4.2): observables of a trajectory sampled
// whenever the output condition (an observable, by default the time) has changed by the period since the
// last point, up to a number of points. Sampling in time uses the dense output (exact times).
#pragma once
#include "dynamics/core/Model.h"
#include "dynamics/core/ParameterTable.h"
#include "dynamics/integrators/Integrator.h"
#include "dynamics/tools/ToolControl.h"

#include <string>
#include <vector>

namespace rv {

struct PlotSettings {
  std::vector<std::string> axes = {"t", "E"}; ///< observable ids: 2 (2D plot) or 3 (3D plot)
  std::string condition = "t";                ///< the output condition's observable
  double period = 0.05;                       ///< its change between two points
  long maxPoints = 20000;
  double timeLimit = 1000; ///< integration time at most (a condition that stops changing ends the plot)
  /// Keep the whole state, (t, x...), instead of the axes' values (a view of the motion fed by a trajectory:
  /// the apex filter); the axes are then not used.
  bool wholeState = false;
};

/// The numbers and choices of the "plot" scene section, declared once: period, max_points, time_limit, and
/// the window's hold_proportions (no/yes) and point_type (small/middle/big). The observables (x, y, z,
/// condition) and the ranges (x_min ... z_max) are read beside the table.
const ParameterTable& plotTable();
/// Sets the period, point limit and time limit from the table's values.
void applyPlotTable(const ParameterValues& v, PlotSettings& s);

/// The filter's rule applied to states as they come (a running trajectory feeding an open plot window):
/// a state is kept when the condition has moved by the period since the last kept one, up to maxPoints.
class PlotSampler {
public:
  /// Throws InputError naming `context` for an unknown observable or a bad setting.
  PlotSampler(const Model& model, const PlotSettings& settings, const std::string& context = "plot");
  /// Offers the state x at time t; true when it is kept (then values() holds the axes' values).
  bool offer(double t, const double* x);
  const std::vector<double>& values() const { return values_; }
  long kept() const { return kept_; }
  bool full() const { return kept_ >= settings_.maxPoints; }
  /// Offers the integrator's last step, calling keep(values()) for each point kept in it: with the time as
  /// the condition, the states at exact multiples of the period from the first time offered (dense output,
  /// as samplePlot does); otherwise the step's end state by offer().
  void offerStep(const Integrator& integrator, const std::function<void(const std::vector<double>&)>& keep);
  /// The axes' values at a state (kept or not).
  std::vector<double> valuesAt(double t, const double* x) const;
  /// Forgets the last kept state (a new run).
  void clear() { kept_ = 0, started_ = false; }

private:
  PlotSettings settings_;
  std::vector<std::function<double(double, const double*)>> axes_;
  std::function<double(double, const double*)> condition_;
  int dimension_ = 0; ///< of the state (wholeState)
  std::vector<double> values_;
  double last_ = 0; ///< the condition's value at the last kept point; in time: the first time offered
  Eigen::VectorXd work_;
  long kept_ = 0;
  bool started_ = false;
};

/// points[k] = the axes' values at the k-th output. Throws InputError naming `context` for an unknown
/// observable or a bad period; stops (returning what it has) when the control asks.
std::vector<std::vector<double>> samplePlot(const Model& model, Integrator& integrator, const PlotSettings& s,
                                            const ToolControl& control, const std::string& context = "plot");

} // namespace rv
