#include "app/gui/PlotWindow.h"

#include "app/gui/QtVtkWidget.h"
#include "render/charts/PlotChart.h"

namespace rv {

namespace {
QString titleOf(const PlotSettings& s) {
  QStringList axes;
  for (const auto& a : s.axes)
    axes << QString::fromStdString(a);
  return QString("%1D plot: %2").arg(s.axes.size()).arg(axes.join(", "));
}
} // namespace

PlotWindow::PlotWindow(const Model& model, const PlotView& plot, QWidget* parent)
    : FilterWindow(titleOf(plot.settings), "plot", parent), plot_(plot), sampler_(model, plot.settings) {
  chart_ = std::make_unique<PlotChart>(plot.settings.axes, plot.chart);
  add(kViewRun, {0.1, 0.1, 0.1});
  chart_->attach(view()->renderWindow());
  setStatus(QString("a point each %1 of %2, at most %3 per trajectory")
                .arg(plot.settings.period)
                .arg(QString::fromStdString(plot.settings.condition))
                .arg(plot.settings.maxPoints));
  resize(560, 520);
}

PlotWindow::~PlotWindow() {
  for (auto& [id, s] : sources_)
    if (s.tap) s.tap->closed = true; // the jobs drop them
}

int PlotWindow::dimensions() const {
  return chart_->dimensions();
}

const Chart* PlotWindow::chart() const {
  return chart_.get();
}

PlotWindow::Source& PlotWindow::add(int id, const Rgb& colour) {
  Source& s = sources_[id];
  s.series = chart_->addSeries(colour);
  return s;
}

void PlotWindow::offer(double t, const double* x) {
  if (!sampler_.offer(t, x)) return;
  Source& s = sources_.at(kViewRun);
  for (std::size_t i = 0; i < sampler_.values().size(); ++i)
    s.values[i].push_back(sampler_.values()[i]);
  s.dirty = true;
}

void PlotWindow::clear(int id) {
  const auto it = sources_.find(id);
  if (it == sources_.end()) return;
  if (id == kViewRun) sampler_.clear(); // a trajectory's job restarts its own sampling
  Source& s = it->second;               // (a restarted job has emptied its tap of the old run's points)
  for (auto& v : s.values)
    v.clear();
  s.dirty = true;
  flush();
}

std::shared_ptr<PlotTap> PlotWindow::follow(int id, const Rgb& colour) {
  if (auto it = sources_.find(id); it != sources_.end()) return it->second.tap;
  Source& s = add(id, colour);
  s.tap = std::make_shared<PlotTap>(plot_.settings);
  return s.tap;
}

void PlotWindow::unfollow(int id) {
  const auto it = sources_.find(id);
  if (it == sources_.end() || id == kViewRun) return;
  it->second.tap->closed = true;
  chart_->setSeries(it->second.series, {}); // the chart keeps the (empty) series: indices stay
  sources_.erase(it);
  view()->update();
}

void PlotWindow::setColour(int id, const Rgb& colour) {
  if (const auto it = sources_.find(id); it != sources_.end()) {
    chart_->setColour(it->second.series, colour);
    view()->update();
  }
}

void PlotWindow::highlight(int id) {
  const auto it = sources_.find(id);
  chart_->select(it == sources_.end() ? -1 : it->second.series);
  view()->update();
}

void PlotWindow::flush() {
  bool changed = false;
  std::vector<std::vector<double>> batch;
  for (auto& [id, s] : sources_) {
    if (s.tap && s.tap->points.take(batch) > 0) {
      for (const auto& p : batch)
        for (std::size_t i = 0; i < p.size(); ++i)
          s.values[i].push_back(p[i]);
      s.dirty = true;
    }
    if (!s.dirty) continue;
    s.dirty = false;
    chart_->setSeries(s.series, s.values);
    changed = true;
  }
  if (changed && isVisible()) view()->update();
}

long PlotWindow::points(int id) const {
  const auto it = sources_.find(id);
  return it == sources_.end() ? 0 : static_cast<long>(it->second.values[0].size());
}

long PlotWindow::points() const {
  long n = 0;
  for (const auto& [id, s] : sources_)
    n += static_cast<long>(s.values[0].size());
  return n;
}

const std::vector<double>& PlotWindow::values(int id, int axis) const {
  return sources_.at(id).values.at(axis);
}

} // namespace rv
