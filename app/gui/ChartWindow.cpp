#include "app/gui/ChartWindow.h"

#include "app/gui/QtVtkWidget.h"
#include "dynamics/core/Errors.h"
#include "dynamics/tools/ReturnMap.h"
#include "scenes/SceneCharts.h"
#include "scenes/SceneLoader.h"

#include <QHBoxLayout>
#include <QProgressBar>
#include <QPushButton>
#include <QTimer>
#include <vtkChartXY.h>
#include <vtkPlotPoints.h>

namespace rv {

ChartWindow::ChartWindow(const nlohmann::json& document, const std::string& source, const std::string& view,
                         QWidget* parent, const std::string& diagram)
    : FilterWindow(QString::fromStdString(diagram.empty() ? view : view + " " + diagram),
                   QString::fromStdString(view), parent),
      viewName_(view), diagram_(diagram) {
  setStatus("computing…");
  progressBar_ = new QProgressBar(this);
  progressBar_->setRange(0, 1000);
  progressBar_->setTextVisible(false);
  cancel_ = new QPushButton("Cancel", this);
  cancel_->setToolTip("stop the computation");
  connect(cancel_, &QPushButton::clicked, this, &ChartWindow::cancel);
  bar()->insertWidget(1, progressBar_);
  bar()->insertWidget(2, cancel_);
  auto* poll = new QTimer(this); // the worker only stores its progress; the window shows it
  connect(poll, &QTimer::timeout, this, [this, poll] {
    if (chart_ || !failure_.isEmpty()) return poll->stop();
    progressBar_->setValue(static_cast<int>(1000 * progress_.load()));
  });
  poll->start(100);
  worker_ = std::thread([this, document, source, view, diagram] {
    std::unique_ptr<Chart> chart;
    QString failure;
    try {
      const Scene scene = sceneFromJson(document, source);
      ToolControl control;
      control.stopRequested = [this] { return stop_.load(); };
      control.progress = [this](double f) { progress_.store(f); };
      chart = sceneChart(scene, view, control, 0, diagram);
    } catch (const Stopped&) {
      failure = "stopped";
    } catch (const std::exception& e) {
      failure = e.what();
    }
    if (closing_) return; // the window is going away: it joins this thread
    // shared: if the window goes before the call is delivered, the discarded call frees the chart
    QMetaObject::invokeMethod(
        this, [this, c = std::shared_ptr<Chart>(std::move(chart)), failure] { deliver(c, failure); },
        Qt::QueuedConnection);
  });
}

void ChartWindow::cancel() {
  stop_ = true;
  cancel_->setEnabled(false);
  setStatus("stopping…");
}

ChartWindow::~ChartWindow() {
  closing_ = true;
  stop_ = true;
  if (worker_.joinable()) worker_.join();
}

void ChartWindow::deliver(std::shared_ptr<Chart> chart, const QString& failure) {
  if (worker_.joinable()) worker_.join();
  failure_ = failure;
  progressBar_->hide();
  cancel_->hide();
  if (chart) {
    chart_ = std::move(chart);
    chart_->attach(view()->renderWindow());
    drawMarks();
    setStatus(QString::fromStdString(viewName_));
    view()->update();
  } else {
    setStatus("failed: " + failure);
  }
  emit finished();
}

void ChartWindow::setMarks(const std::vector<Mark>& marks) {
  marks_ = marks;
  drawMarks();
}

void ChartWindow::drawMarks() {
  auto* plane = dynamic_cast<PoincareChart*>(chart_.get());
  if (!plane) return;
  while (markSeries_.size() < marks_.size()) {
    markSeries_.push_back(plane->addSeries({}, {}, {0, 0, 0}));
    if (auto* p = vtkPlotPoints::SafeDownCast(plane->chart()->GetPlot(markSeries_.back())))
      p->SetMarkerSize(9);
  }
  for (std::size_t i = 0; i < markSeries_.size(); ++i) {
    if (i < marks_.size()) {
      plane->setSeries(markSeries_[i], {marks_[i].x}, {marks_[i].y});
      plane->setColor(markSeries_[i], marks_[i].colour);
    } else {
      plane->setSeries(markSeries_[i], {}, {});
    }
  }
  view()->update();
}

} // namespace rv
