#include "app/gui/ChartWindow.h"

#include "app/gui/QtVtkWidget.h"
#include "dynamics/core/Errors.h"
#include "dynamics/tools/ReturnMap.h"
#include "dynamics/tools/ToolRegistry.h"
#include "scenes/ChartTask.h"
#include "scenes/SceneCharts.h"
#include "scenes/SceneLoader.h"

#include <QHBoxLayout>
#include <QTimer>
#include <regex>
#include <vtkChartXY.h>
#include <vtkPlotPoints.h>

namespace rv {

QString inGuiWords(std::string error) {
  // the command line names its flag first ("--view spectrum: ..."); in a window the view is the window
  if (error.rfind("--", 0) == 0)
    if (const auto colon = error.find(": "); colon != std::string::npos) error = error.substr(colon + 2);
  // "the scene has no spectrum.function": say where the value is set
  static const std::regex missing(R"(the scene has no (\w+)\.(\w+))");
  std::smatch m;
  if (std::regex_search(error, m, missing)) {
    const ToolSection* section = findToolSection(m[1].str());
    const std::string tab = section ? section->title : m[1].str();
    error = m.prefix().str() + "no " + m[2].str() + " is chosen for " + tab +
            ": choose it in the control panel's " + tab + " tab (no Apply needed) and open the chart again" +
            m.suffix().str();
  }
  return QString::fromStdString(error);
}

ChartWindow::ChartWindow(JobTree& jobs, const nlohmann::json& document, const std::string& source,
                         const std::string& view, QWidget* parent, const std::string& diagram)
    : FilterWindow(QString::fromStdString(chartTitle(view) + (diagram.empty() ? "" : " " + diagram)),
                   QString::fromStdString(view), parent),
      viewName_(view), diagram_(diagram), jobs_(jobs) {
  document_ = document;
  showPlaceholder("computing " + QString::fromStdString(chartTitle(view)) + "…");
  setSavable(false, "nothing to save until the chart is drawn");
  setStatus("computing…");
  addProgress("Cancel", "stop the computation (the tool manager continues it)", [this] { cancel(); });
  Job& job = jobs_.add(std::make_unique<ChartTask>(document, source, view, diagram));
  jobId_ = job.id();
  job.start();
  auto* timer = new QTimer(this); // the job only stores its state; the window follows it
  connect(timer, &QTimer::timeout, this, &ChartWindow::poll);
  timer->start(100);
}

Job* ChartWindow::job() const {
  return jobs_.find(jobId_);
}

void ChartWindow::cancel() {
  if (Job* j = job()) j->stop(); // prompt: the computation polls between its steps; the timer shows the rest
}

ChartWindow::~ChartWindow() {
  if (Job* j = job()) jobs_.remove(*j);
}

void ChartWindow::poll() {
  Job* j = job();
  const Job::Status status = j ? j->status() : Job::Status::Failed;
  const bool running = status == Job::Status::Running;
  showProgress(running, j ? j->progress() : 0);
  if (running) {
    if (seen_ != status) {
      setStatus("computing…");
      if (!chart_)
        showPlaceholder("computing " + QString::fromStdString(chartTitle(viewName_)) + "…"); // continued
    }
    seen_ = status;
    return;
  }
  if (status == seen_ && j) return;
  seen_ = status;
  if (!j) {
    failure_ = "deleted in the tool manager";
    setStatus(failure_);
    if (!chart_) showPlaceholder(failure_), setSavable(false, failure_);
    emit finished();
    return;
  }
  auto* task = dynamic_cast<ChartTask*>(&j->task());
  const std::shared_ptr<Chart> chart = task ? task->chart() : nullptr;
  if (status == Job::Status::Failed) {
    failure_ = inGuiWords(j->error());
    setStatus("failed: " + failure_);
  } else {
    failure_ = status == Job::Status::Stopped && !chart ? "stopped" : "";
    setStatus(status == Job::Status::Finished ? QString::fromStdString(chartTitle(viewName_))
              : chart                         ? "stopped: what was computed so far"
                                              : "stopped");
  }
  if (chart && chart != chart_) {
    if (chart_) { // a chart is never attached to a view that drew another
      markSeries_.clear();
      chart_.reset();
      replaceView();
    }
    chart_ = chart;
    chart_->attach(view()->renderWindow());
    showView();
    setSavable(true);
    drawMarks();
    view()->update();
  }
  if (!chart_) { // nothing drawn: the page says why, and there is nothing to save
    const QString why = status == Job::Status::Failed ? "The chart cannot be drawn:\n" + failure_
                                                      : QString("Stopped before anything was computed");
    showPlaceholder(why);
    setSavable(false, why);
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
      plane->setColour(markSeries_[i], marks_[i].colour);
    } else {
      plane->setSeries(markSeries_[i], {}, {});
    }
  }
  view()->update();
}

} // namespace rv
