#include "app/gui/MapPanel.h"

#include "app/gui/QtVtkWidget.h"
#include "dynamics/core/Errors.h"
#include "dynamics/jobs/PoincareTask.h"

#include <QMouseEvent>
#include <QVBoxLayout>

namespace rv {

MapPanel::MapPanel(QWidget* parent) : QWidget(parent) {
  view_ = new QtVtkWidget(this);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(view_);
  view_->installEventFilter(this);
  view_->setToolTip("Ctrl+click: start a trajectory at this point of the map");
  setMinimumSize(320, 320);
}

MapPanel::~MapPanel() {
  jobs_.removeAll();
}

void MapPanel::setScene(const Scene& scene) {
  jobs_.removeAll();
  series_.clear();
  scene_ = &scene;
  const auto names = PoincareMap(*scene.model, scene.startIntegrator(), scene.poincare).coordinateNames();
  chart_ = std::make_unique<PoincareChart>(names.at(0), names.size() > 1 ? names[1] : "t");
  chart_->attach(view_->renderWindow());
  start(scene.initialState);
}

void MapPanel::start(const Eigen::VectorXd& state) {
  RunSpec spec = scene_->runSpec();
  spec.initialState = state;
  auto task = std::make_unique<PoincareTask>(spec, scene_->poincare);
  PoincareTask* raw = task.get();
  Job& job = jobs_.add(std::move(task));
  const int plot = chart_->addSeries({}, {}, seriesColor(static_cast<int>(series_.size())));
  series_.push_back({&job, raw, {}, {}, plot});
  chart_->select(plot);
  job.start();
}

bool MapPanel::startAt(double x, double y) {
  if (!scene_) return false;
  try {
    const MapPointSpec spec{.sectionValue = scene_->poincare.value,
                            .root = std::max(1, scene_->poincare.root)};
    std::vector<double> point{x, y};
    if (scene_->model->info().mapCoordinates.size() == 3) { // a 3D map: Z from the scene's initial point
      const auto& doc = scene_->document;
      const bool hasZ =
          doc.contains("initial") && doc["initial"].contains("map") && doc["initial"]["map"].size() == 3;
      point.push_back(hasZ ? doc["initial"]["map"][2].get<double>() : 0.0);
    }
    start(scene_->model->stateFromMap(point, spec, "map point"));
    emit message(QString("trajectory %1 started at (%2, %3)").arg(series_.size()).arg(x).arg(y));
    return true;
  } catch (const InputError& e) {
    emit message(QString::fromStdString(e.what()));
    return false;
  }
}

void MapPanel::drain() {
  bool changed = false;
  std::vector<MapPoint> batch;
  for (auto& s : series_) {
    if (s.task->points().take(batch) == 0) continue;
    for (const auto& p : batch) {
      s.x.push_back(p.coordinates.at(0));
      s.y.push_back(p.coordinates.size() > 1 ? p.coordinates[1] : p.time);
    }
    chart_->setSeries(s.plot, s.x, s.y);
    changed = true;
  }
  if (changed) view_->update();
}

void MapPanel::stopAll() {
  jobs_.stopAll();
}

long MapPanel::points() const {
  long n = 0;
  for (const auto& s : series_)
    n += static_cast<long>(s.x.size());
  return n;
}

bool MapPanel::eventFilter(QObject* watched, QEvent* event) {
  if (watched == view_ && event->type() == QEvent::MouseButtonPress && chart_) {
    auto* e = static_cast<QMouseEvent*>(event);
    if (e->button() == Qt::LeftButton && (e->modifiers() & Qt::ControlModifier)) {
      const double dpr = view_->devicePixelRatioF();
      double x, y;
      if (chart_->toChart(e->position().x() * dpr, (view_->height() - e->position().y()) * dpr, x, y))
        startAt(x, y);
      return true; // not a pan or zoom of the chart
    }
  }
  return QWidget::eventFilter(watched, event);
}

} // namespace rv
