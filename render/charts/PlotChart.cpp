#include "render/charts/PlotChart.h"

#include <algorithm>
#include <cmath>

namespace rv {

PlotChart::PlotChart(const std::vector<std::string>& axes, const PlotChartOptions& o) : options_(o) {
  if (axes.size() == 3) {
    space_ = std::make_unique<Chart3D>(std::array<std::string, 3>{axes[0], axes[1], axes[2]});
    space_->setRanges(o.range);
    space_->setEqualScales(o.holdProportions);
  } else {
    plane_ = std::make_unique<PoincareChart>(axes.at(0), axes.at(1));
    plane_->setMarkerSize(o.pointSize);
    plane_->setEqualAspect(o.holdProportions);
  }
}

PlotChart::~PlotChart() = default;

int PlotChart::addSeries(const Rgb& colour) {
  if (space_) return space_->addSeries({}, {}, {}, colour, options_.pointSize);
  bounds_.push_back({1e300, -1e300, 1e300, -1e300});
  return plane_->addSeries({}, {}, colour);
}

void PlotChart::setSeries(int index, const std::array<std::vector<double>, 3>& v) {
  if (space_) return space_->setSeries(index, v[0], v[1], v[2]);
  plane_->setSeries(index, v[0], v[1]);
  if (index < 0 || index >= static_cast<int>(bounds_.size())) return;
  auto& b = bounds_[index];
  b = {1e300, -1e300, 1e300, -1e300};
  for (int a = 0; a < 2; ++a)
    for (double c : v[a])
      if (std::isfinite(c)) b[2 * a] = std::min(b[2 * a], c), b[2 * a + 1] = std::max(b[2 * a + 1], c);
  fitRanges();
}

void PlotChart::fitRanges() {
  const auto& r = options_.range;
  if (!(r[0] || r[1] || r[2] || r[3])) return; // all follow the data (the chart's own behaviour)
  std::array<double, 4> all = {1e300, -1e300, 1e300, -1e300};
  for (const auto& b : bounds_)
    for (int i = 0; i < 4; ++i)
      all[i] = i % 2 ? std::max(all[i], b[i]) : std::min(all[i], b[i]);
  if (all[0] > all[1] || all[2] > all[3]) all = {-1, 1, -1, 1}; // no data yet
  plane_->setRanges(r[0].value_or(all[0]), r[1].value_or(all[1]), r[2].value_or(all[2]),
                    r[3].value_or(all[3]));
}

void PlotChart::setColour(int index, const Rgb& colour) {
  if (space_)
    space_->setColour(index, colour);
  else
    plane_->setColour(index, colour);
}

void PlotChart::select(int index) {
  if (space_)
    space_->select(index);
  else
    plane_->select(index);
}

void PlotChart::attach(vtkRenderWindow* window) {
  if (space_)
    space_->attach(window);
  else
    plane_->attach(window);
}

void PlotChart::writeCsv(std::ostream& out) const {
  if (space_)
    space_->writeCsv(out);
  else
    plane_->writeCsv(out);
}

} // namespace rv
