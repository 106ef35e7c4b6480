#include "app/gui/MultipliersWindow.h"

#include "app/gui/QtVtkWidget.h"
#include "render/charts/ToolCharts.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <cmath>

namespace rv {

MultipliersWindow::MultipliersWindow(QWidget* parent)
    : FilterWindow("fixed point multipliers", "multipliers", parent) {
  chart_ = std::make_unique<PoincareChart>("Re", "Im");
  radius_ = drawUnitCircle(*chart_);
  chart_->setMarkerSize(6);
  chart_->attach(view()->renderWindow());
  period_ = new QDoubleSpinBox(this);
  period_->setObjectName("period");
  period_->setDecimals(6);
  period_->setRange(0, 1e6);
  period_->setToolTip("a continuation's point is drawn when its parameter has changed by this since the last "
                      "one drawn (0: every point); a tree draws every step of its elliptic branches");
  bar()->insertWidget(0, new QLabel("Period", this));
  bar()->insertWidget(1, period_);
  setStatus("multipliers of running continuations and bifurcation trees, and of the fixed points found");
  resize(720, 760); // about square for the chart (the unit circle round), with the bar under it
}

MultipliersWindow::~MultipliersWindow() = default;

const Chart* MultipliersWindow::chart() const {
  return chart_.get();
}

void MultipliersWindow::setPeriod(double period) {
  period_->setValue(period);
}

bool MultipliersWindow::offer(int job, double parameter, const std::vector<std::complex<double>>& m,
                              bool everyStep) {
  Family& f = families_[job];
  // "changed by the period": a family stepping by a divisor of it lands on it up to rounding
  const double period = period_->value();
  if (!everyStep && !f.parameters.empty() && std::abs(parameter - f.parameters.back()) < period * (1 - 1e-9))
    return false;
  f.outputs.push_back(m);
  f.parameters.push_back(parameter);
  dirty_ = true;
  return true;
}

void MultipliersWindow::showFixedPoint(int job, const QString& caption,
                                       const std::vector<std::complex<double>>& multipliers) {
  Family& f = families_[job];
  f.outputs.assign(1, multipliers); // a search finds one point (again, when it is continued)
  f.parameters.assign(1, 0.0);
  dirty_ = true;
  setStatus(caption);
}

QString MultipliersWindow::caption() const {
  return status();
}

void MultipliersWindow::forget(int job) {
  if (families_.erase(job) > 0) dirty_ = true;
}

void MultipliersWindow::clear() {
  families_.clear();
  radius_ = 1.2;
  dirty_ = true;
  flush();
}

void MultipliersWindow::flush() {
  if (!dirty_) return;
  dirty_ = false;
  // one series per multiplier index, over every family
  std::vector<std::vector<double>> x, y;
  for (const auto& [job, f] : families_)
    for (const auto& m : f.outputs) {
      if (m.size() > x.size()) x.resize(m.size()), y.resize(m.size());
      for (std::size_t k = 0; k < m.size(); ++k)
        if (std::isfinite(std::abs(m[k]))) {
          x[k].push_back(m[k].real()), y[k].push_back(m[k].imag());
          radius_ = std::max({radius_, 1.1 * std::abs(m[k].real()), 1.1 * std::abs(m[k].imag())});
        }
    }
  while (series_.size() < x.size())
    series_.push_back(chart_->addSeries({}, {}, seriesColour(static_cast<int>(series_.size()))));
  for (std::size_t k = 0; k < series_.size(); ++k)
    chart_->setSeries(series_[k], k < x.size() ? x[k] : std::vector<double>{},
                      k < y.size() ? y[k] : std::vector<double>{});
  chart_->setRanges(-radius_, radius_, -radius_, radius_);
  if (isVisible()) view()->update();
}

long MultipliersWindow::points() const {
  long n = 0;
  for (const auto& [job, f] : families_)
    for (const auto& m : f.outputs)
      n += static_cast<long>(m.size());
  return n;
}

const std::vector<std::vector<std::complex<double>>>& MultipliersWindow::outputs(int job) const {
  static const std::vector<std::vector<std::complex<double>>> none;
  const auto it = families_.find(job);
  return it == families_.end() ? none : it->second.outputs;
}

const std::vector<double>& MultipliersWindow::parameters(int job) const {
  static const std::vector<double> none;
  const auto it = families_.find(job);
  return it == families_.end() ? none : it->second.parameters;
}

} // namespace rv
