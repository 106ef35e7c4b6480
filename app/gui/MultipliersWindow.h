// MultipliersWindow.h -- the fixed point multiplicators filter as a live window (manual §2.4.3): the
// multipliers of the fixed points a running continuation or bifurcation tree produces, on the complex plane
// with the unit circle, one colour per multiplier. A continuation outputs whenever its parameter has changed
// by the window's period since the last output; a tree outputs every step, of its elliptic branches only.
#pragma once
#include "app/gui/FilterWindow.h"

#include <complex>
#include <map>
#include <memory>
#include <vector>

class QDoubleSpinBox;

namespace rv {

class PoincareChart;

class MultipliersWindow : public FilterWindow {
  Q_OBJECT
public:
  explicit MultipliersWindow(QWidget* parent = nullptr);
  ~MultipliersWindow() override;
  /// The output period in the continuation parameter (0: every point).
  void setPeriod(double period);
  /// A fixed point of job `job`'s family at `parameter`: drawn if the filter's condition lets it through
  /// (`everyStep`: a tree's step, always). Returns whether it was.
  bool offer(int job, double parameter, const std::vector<std::complex<double>>& multipliers,
             bool everyStep = false);
  /// A fixed point found by a search (job `job`): its multipliers drawn, `caption` (the point, its type and
  /// multipliers in words) under the chart. Drawn at the next flush.
  void showFixedPoint(int job, const QString& caption, const std::vector<std::complex<double>>& multipliers);
  /// The text under the chart.
  QString caption() const;
  /// The job was deleted: its points go.
  void forget(int job);
  /// Every family goes (another scene).
  void clear();
  /// Draws what arrived since the last call.
  void flush();
  /// Points drawn (multipliers of all outputs).
  long points() const;
  /// The multipliers drawn for a job, output by output (tests).
  const std::vector<std::vector<std::complex<double>>>& outputs(int job) const;
  /// The family's parameter at each output.
  const std::vector<double>& parameters(int job) const;

protected:
  const Chart* chart() const override;

private:
  struct Family { ///< what was output, with the family's parameter at each output
    std::vector<std::vector<std::complex<double>>> outputs;
    std::vector<double> parameters;
  };
  std::map<int, Family> families_;
  std::unique_ptr<PoincareChart> chart_;
  std::vector<int> series_; ///< one per multiplier index
  QDoubleSpinBox* period_;
  double radius_ = 1.2; ///< half the square shown
  bool dirty_ = false;
};

} // namespace rv
