#include "app/gui/PlotWindow.h"

#include "app/gui/QtVtkWidget.h"
#include "render/charts/PoincareChart.h"

#include <QVBoxLayout>

namespace rv {

PlotWindow::PlotWindow(const Model& model, const PlotSettings& settings, QWidget* parent)
    : QWidget(parent, Qt::Window), sampler_(model, settings) {
  setWindowTitle(
      QString("rollviz — 2D plot: %1 against %2")
          .arg(QString::fromStdString(settings.axes[1]), QString::fromStdString(settings.axes[0])));
  view_ = new QtVtkWidget(this);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(view_);
  chart_ = std::make_unique<PoincareChart>(settings.axes[0], settings.axes[1]);
  chart_->addSeries({}, {}, seriesColor(0));
  chart_->attach(view_->renderWindow());
  resize(560, 480);
}

PlotWindow::~PlotWindow() = default;

void PlotWindow::offer(double t, const double* x) {
  if (!sampler_.offer(t, x)) return;
  x_.push_back(sampler_.values()[0]);
  y_.push_back(sampler_.values()[1]);
  dirty_ = true;
}

void PlotWindow::flush() {
  if (!dirty_) return;
  dirty_ = false;
  chart_->setSeries(0, x_, y_);
  if (isVisible()) view_->update();
}

void PlotWindow::clear() {
  sampler_.clear();
  x_.clear(), y_.clear();
  dirty_ = true;
  flush();
}

} // namespace rv
