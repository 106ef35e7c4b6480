#include "app/gui/SweepWindow.h"

#include "app/gui/QtVtkWidget.h"
#include "dynamics/core/Errors.h"
#include "scenes/SceneLoader.h"
#include "scenes/SweepTask.h"
#include "scenes/ToolTask.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QMouseEvent>
#include <QPushButton>
#include <QRubberBand>
#include <QTimer>
#include <cmath>
#include <fmt/core.h>

namespace rv {

SweepWindow::SweepWindow(JobTree& jobs, SweepSpec spec, QWidget* parent)
    : FilterWindow(QString::fromStdString(
                       spec.title.empty() ? "Sweep: " + spec.quantity->id + spec.quantityName : spec.title),
                   "sweep", parent),
      spec_(spec), jobs_(jobs) {
  setStatus("computing…");
  addProgress("Stop", "stop the sweep (the tool manager continues it with the points left)", [this] {
    if (Job* j = job()) j->stop();
  });
  Job& job = jobs_.add(std::make_unique<SweepTask>(std::move(spec)));
  jobId_ = job.id();
  history_.push_back({spec_, jobId_});
  job.start();
  view()->installEventFilter(this);
  view()->setToolTip("click a cell: open that point's scene in the main window");
  zoomButton_ = new QPushButton("Zoom", this);
  zoomButton_->setObjectName("zoom");
  zoomButton_->setCheckable(true);
  zoomButton_->setToolTip("then drag a rectangle on the chart: that window is computed at the same number of "
                          "points (a job of the tool manager)");
  backButton_ = new QPushButton("Back", this);
  backButton_->setToolTip("the window before this zoom");
  forwardButton_ = new QPushButton("Forward", this);
  forwardButton_->setToolTip("the zoom after this one");
  connect(backButton_, &QPushButton::clicked, this, [this] { back(); });
  connect(forwardButton_, &QPushButton::clicked, this, [this] { forward(); });
  bar()->insertWidget(0, forwardButton_);
  bar()->insertWidget(0, backButton_);
  bar()->insertWidget(0, zoomButton_);
  band_ = new QRubberBand(QRubberBand::Rectangle, this);
  updateZoomButtons();
  if (spec_.axes.size() == 2) {
    curveButton_ = new QPushButton("Bifurcation curve", this);
    curveButton_->setObjectName("bifurcationCurve");
    curveButton_->setCheckable(true);
    curveButton_->setToolTip(
        "then click a cell: its fixed point is continued in the first axis' parameter to its "
        "bifurcation_curve.kind (fold, period doubling, Neimark-Sacker), which is followed "
        "in the chart's two parameters and drawn over it");
    bar()->insertWidget(0, curveButton_);
  }
  auto* timer = new QTimer(this); // the job only stores its results; the window reads them
  connect(timer, &QTimer::timeout, this, &SweepWindow::poll);
  timer->start(250);
}

SweepWindow::~SweepWindow() {
  if (Job* j = curveJob()) jobs_.remove(*j);
  for (auto it = history_.rbegin(); it != history_.rend(); ++it) // the zooms are children of the first job
    if (Job* j = jobs_.find(it->jobId)) jobs_.remove(*j);
}

bool SweepWindow::zoomTo(const std::vector<double>& bounds) {
  if (zoomButton_) zoomButton_->setChecked(false);
  try {
    SweepSpec zoomed = zoomSweep(history_.front().spec, bounds, "zoom");
    while (history_.size() > at_ + 1) { // a new zoom drops the ones ahead
      if (Job* j = jobs_.find(history_.back().jobId)) jobs_.remove(*j);
      history_.pop_back();
    }
    Job* parent = jobs_.find(history_.front().jobId);
    Job& job = jobs_.add(std::make_unique<SweepTask>(zoomed), parent);
    history_.push_back({std::move(zoomed), job.id()});
    job.start();
    showZoom(history_.size() - 1);
    return true;
  } catch (const std::exception& e) {
    setStatus(QString("no zoom: %1").arg(e.what()));
    return false;
  }
}

bool SweepWindow::back() {
  if (at_ == 0) return false;
  showZoom(at_ - 1);
  return true;
}

bool SweepWindow::forward() {
  if (at_ + 1 >= history_.size()) return false;
  showZoom(at_ + 1);
  return true;
}

void SweepWindow::showZoom(std::size_t zoom) {
  at_ = zoom;
  spec_ = history_[zoom].spec;
  jobId_ = history_[zoom].jobId;
  read_.clear(); // the chart is read again from that job's store
  done_ = -1;
  generation_ = 0;
  seen_ = Job::Status::Ready;
  redraw_ = true;
  std::string where;
  for (const auto& a : spec_.axes)
    where += fmt::format("{}{} in [{:.6g}, {:.6g}]", where.empty() ? "" : ", ", a.id, a.min, a.max);
  setStatus(QString::fromStdString(zoom == 0 ? "the sweep file's window: " + where
                                             : "zoom " + std::to_string(zoom) + ": " + where));
  updateZoomButtons();
  poll();
}

void SweepWindow::updateZoomButtons() {
  backButton_->setEnabled(at_ > 0);
  forwardButton_->setEnabled(at_ + 1 < history_.size());
}

Job* SweepWindow::curveJob() const {
  return curveJobId_ < 0 ? nullptr : jobs_.find(curveJobId_);
}

void SweepWindow::startCurve(long index) {
  if (curveButton_) curveButton_->setChecked(false);
  if (spec_.axes.size() != 2 || curveJob()) return;
  const SweepAxis &ax = spec_.axes[0], &ay = spec_.axes[1];
  try {
    if (ax.mapCoordinate >= 0 || ay.mapCoordinate >= 0 || ax.id.find('.') != std::string::npos ||
        ay.id.find('.') != std::string::npos)
      throw InputError("a bifurcation curve lies in a plane of two model parameters; these axes are " +
                       ax.id + " and " + ay.id);
    const nlohmann::json base = sweepPointScene(spec_, index).document;
    const double here = spec_.axisValues(index)[0];
    // toward the farther end of the first axis first, then toward the other
    std::vector<double> ends{ax.max, ax.min};
    if (std::abs(ax.min - here) > std::abs(ax.max - here)) std::swap(ends[0], ends[1]);
    std::vector<nlohmann::json> documents;
    for (const double to : ends) {
      if (to == here) continue;
      nlohmann::json d = base;
      d["continuation"]["parameter"] = ax.id;
      d["continuation"]["to"] = to;
      d["continuation"]["step"] = (to - here) / 50;
      auto& c = d["bifurcation_curve"];
      c["second_parameter"] = ay.id;
      c["first_min"] = ax.min, c["first_max"] = ax.max, c["second_min"] = ay.min, c["second_max"] = ay.max;
      documents.push_back(std::move(d));
    }
    Job& job = jobs_.add(std::make_unique<ToolTask>("bifurcation_curve", std::move(documents),
                                                    "grid point " + std::to_string(index) + " of the sweep"));
    curveJobId_ = job.id();
    job.start();
    setStatus(QString("following the bifurcation curve from %1 = %2, %3 = %4…")
                  .arg(QString::fromStdString(ax.id))
                  .arg(here)
                  .arg(QString::fromStdString(ay.id))
                  .arg(spec_.axisValues(index)[1]));
  } catch (const std::exception& e) {
    setStatus(QString("no bifurcation curve: %1").arg(e.what()));
  }
}

void SweepWindow::takeCurve() {
  Job* j = curveJob();
  if (!j || j->status() == Job::Status::Running || j->status() == Job::Status::Ready) return;
  const auto& task = static_cast<const ToolTask&>(j->task());
  if (const auto r = task.result(); r && r->table.names.size() >= 2) {
    overlays_.push_back(
        {r->fields.value("kind", std::string("bifurcation")), r->table.values[0], r->table.values[1]});
    redraw_ = true;
    std::string events;
    for (const auto& e : r->fields.value("events", nlohmann::json::array()))
      events += "; " + e.value("what", std::string());
    setStatus(QString::fromStdString(r->fields.value("kind", std::string()) +
                                     " curve: " + std::to_string(r->table.rows()) + " points" + events));
  } else {
    setStatus(QString::fromStdString(j->status() == Job::Status::Failed
                                         ? "no bifurcation curve: " + j->error()
                                         : "the bifurcation curve was stopped"));
  }
  jobs_.remove(*j);
  curveJobId_ = -1;
}

Job* SweepWindow::job() const {
  return jobs_.find(jobId_);
}

long SweepWindow::pointAt(double x, double y) const {
  long index = 0, stride = 1;
  const double at[2] = {x, y};
  for (std::size_t a = 0; a < spec_.axes.size(); ++a) {
    const SweepAxis& axis = spec_.axes[a];
    const double step = axis.count > 1 ? (axis.max - axis.min) / (axis.count - 1) : 1;
    const long i = axis.count > 1 ? std::lround((at[a] - axis.min) / step) : 0;
    if (i < 0 || i >= axis.count || std::abs(at[a] - axis.at(static_cast<int>(i))) > step) return -1;
    index += i * stride;
    stride *= axis.count;
  }
  return index;
}

void SweepWindow::openPoint(long index) {
  try {
    std::string where;
    for (std::size_t a = 0; a < spec_.axes.size(); ++a)
      where +=
          (where.empty() ? "" : ", ") + spec_.axes[a].id + " = " + std::to_string(spec_.axisValues(index)[a]);
    const nlohmann::json document = sweepPointScene(spec_, index).document;
    if (opener_ && !opener_(document)) {
      setStatus(QString::fromStdString("not opened (" + where + "): the main window kept its map"));
      return;
    }
    setStatus(QString::fromStdString("opened " + where));
  } catch (const std::exception& e) {
    setStatus(QString("no scene there: %1").arg(e.what()));
  }
}

long SweepWindow::pointUnder(const QPointF& position) const {
  const double dpr = view()->devicePixelRatioF();
  double x = 0, y = 0;
  if (!chart_ || !chart_->toChart(position.x() * dpr, (view()->height() - position.y()) * dpr, x, y))
    return -1;
  return pointAt(x, spec_.axes.size() == 1 ? 0 : y); // a one-axis chart: the nearest grid value along it
}

bool SweepWindow::eventFilter(QObject* watched, QEvent* event) {
  // Zoom: press, drag (the rubber band shows the window), release. The band belongs to this window, not to
  // the view: a redraw replaces the view (and everything it owns), and the band must outlive it.
  const auto chartAt = [this](const QPointF& p, double& x, double& y) {
    const double dpr = view()->devicePixelRatioF();
    return chart_ && chart_->toChart(p.x() * dpr, (view()->height() - p.y()) * dpr, x, y);
  };
  const auto bandRect = [this](const QPoint& to) {
    return QRect(view()->mapTo(this, pressed_), view()->mapTo(this, to)).normalized();
  };
  const bool mouse = event->type() == QEvent::MouseButtonPress || event->type() == QEvent::MouseMove ||
                     event->type() == QEvent::MouseButtonRelease;
  if (watched != view() || !mouse) return FilterWindow::eventFilter(watched, event);
  auto* e = static_cast<QMouseEvent*>(event);
  if (zoomButton_ && zoomButton_->isChecked() && chart_) {
    if (event->type() == QEvent::MouseButtonPress && e->button() == Qt::LeftButton) {
      if (chartAt(e->position(), pressedAt_[0], pressedAt_[1])) {
        pressed_ = e->position().toPoint();
        dragging_ = true;
        band_->setGeometry(bandRect(pressed_));
        band_->show();
        band_->raise();
      }
      return true;
    }
    if (event->type() == QEvent::MouseMove && dragging_) {
      band_->setGeometry(bandRect(e->position().toPoint()));
      return true;
    }
    if (event->type() == QEvent::MouseButtonRelease && dragging_) {
      endDrag();
      double x = 0, y = 0;
      if (chartAt(e->position(), x, y) && std::abs(e->position().x() - pressed_.x()) > 3) {
        std::vector<double> bounds{std::min(x, pressedAt_[0]), std::max(x, pressedAt_[0])};
        if (spec_.axes.size() == 2) {
          if (std::abs(e->position().y() - pressed_.y()) <= 3) return true; // a line is no window
          bounds.push_back(std::min(y, pressedAt_[1]));
          bounds.push_back(std::max(y, pressedAt_[1]));
        }
        zoomTo(bounds);
      }
      return true;
    }
  }
  // a cell click: pressed and released at (nearly) one place; a drag without Zoom opens nothing
  if (e->button() != Qt::LeftButton || !chart_) return FilterWindow::eventFilter(watched, event);
  if (event->type() == QEvent::MouseButtonPress) {
    clickAt_ = e->position().toPoint();
    clicking_ = true;
    return true;
  }
  if (event->type() == QEvent::MouseButtonRelease && clicking_) {
    clicking_ = false;
    if ((e->position().toPoint() - clickAt_).manhattanLength() > 3) return true;
    if (const long i = pointUnder(e->position()); i >= 0) {
      if (curveButton_ && curveButton_->isChecked())
        startCurve(i);
      else
        openPoint(i);
    }
    return true;
  }
  return FilterWindow::eventFilter(watched, event);
}

void SweepWindow::endDrag() {
  dragging_ = false;
  band_->hide();
}

void SweepWindow::poll() {
  takeCurve();
  Job* j = job();
  const Job::Status status = j ? j->status() : Job::Status::Failed;
  const bool running = status == Job::Status::Running;
  showProgress(running, j ? j->progress() : 0);
  if (!j) {
    if (seen_ != Job::Status::Failed) setStatus("deleted in the tool manager");
    seen_ = Job::Status::Failed;
    return;
  }
  const auto& task = static_cast<const SweepTask&>(j->task());
  const long done = task.store().doneCount();
  if (task.generation() != generation_) { // restarted: its store is new
    generation_ = task.generation();
    read_.clear();
    done_ = -1;
  }
  // new points or curves: draw again (a chart is never attached to a view that drew another) -- but not
  // under a zoom being dragged: the view it is dragged on stays until the button is released
  if ((done != done_ || redraw_) && !dragging_) {
    done_ = done;
    redraw_ = false;
    task.updateChartData(data_, read_); // only the points done since the last time are read
    data_.overlays = overlays_;
    if (chart_) {
      chart_.reset();
      replaceView();
      view()->installEventFilter(this);
    }
    chart_ = makeSweepChart(data_);
    chart_->attach(view()->renderWindow());
    view()->update();
  }
  const QString count = QString("%1 of %2 points").arg(done).arg(spec_.points());
  if (curveJob()) {
    // the curve's job says how it goes
  } else if (running) {
    setStatus("computing… " + count);
  } else if (status != seen_) {
    setStatus(status == Job::Status::Finished ? count + "; click a cell to open its scene"
              : status == Job::Status::Failed ? "failed: " + QString::fromStdString(j->error())
                                              : "stopped: " + count);
  }
  const bool ended =
      status == Job::Status::Finished || status == Job::Status::Stopped || status == Job::Status::Failed;
  if (status != seen_ && ended) emit finished();
  seen_ = status;
}

} // namespace rv
