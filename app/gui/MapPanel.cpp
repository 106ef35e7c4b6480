#include "app/gui/MapPanel.h"

#include "scenes/SnapshotJson.h"

#include "app/gui/ChartWindow.h"
#include "app/gui/MultipliersWindow.h"
#include "app/gui/PlotWindow.h"
#include "app/gui/QtVtkWidget.h"
#include "dynamics/core/Errors.h"
#include "dynamics/jobs/MegnoTask.h"
#include "dynamics/jobs/PoincareTask.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/SceneLoader.h"
#include "scenes/SceneTools.h"

#include <QCheckBox>
#include <QColor>
#include <QComboBox>
#include <QContextMenuEvent>
#include <QElapsedTimer>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QMouseEvent>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

namespace rv {

MapPanel::MapPanel(QWidget* parent)
    : QWidget(parent), map3D_(std::make_unique<Map3DWindow>(this)),
      trajectories_(
          jobs_, filters_, [this](const QString& m) { emit message(m); }, [this] { view_->update(); }) {
  view_ = new QtVtkWidget(this);
  // the chart's scene asks for a frame 40 ms after every change; drain() has painted it by then
  view_->setRenderWanted([this] { return chart_ && chart_->changedSincePainted(); });
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  modeBox_ = new QComboBox(this);
  modeBox_->setObjectName("click_mode");
  modeBox_->addItems({"Click: start a trajectory", "Click: search a fixed point", "Click: pan / zoom"});
  modeBox_->setToolTip(
      "what a click on the map does (Ctrl+click always starts a trajectory, Shift+click always "
      "searches a fixed point; the wheel zooms)");
  connect(modeBox_, &QComboBox::currentIndexChanged, this,
          [this](int i) { clickMode_ = static_cast<ClickMode>(i); });
  megnoBox_ = new QCheckBox("Colour by MEGNO", this);
  megnoBox_->setObjectName("colour_by_megno");
  megnoBox_->setToolTip(
      "colour each trajectory by its chaos indicator <Y> (MEGNO, the scene's megno settings; "
      "a job under the trajectory's): about 2 on a torus, growing on chaotic orbits");
  connect(megnoBox_, &QCheckBox::toggled, this, [this](bool on) { setColourByMegno(on); });
  // the colour scale, shown while colouring: three swatches of megnoColour
  QString legend = "&lt;Y&gt;:";
  for (const double y : {2.0, 5.0, 8.0}) {
    const Rgb c = MapTrajectories::megnoColour(y);
    legend += QString(" <span style='color:%1'>&#9632;</span> %2")
                  .arg(QColor::fromRgbF(static_cast<float>(c[0]), static_cast<float>(c[1]),
                                        static_cast<float>(c[2]))
                           .name())
                  .arg(y == 2   ? "2 (torus)"
                       : y == 8 ? "8+ (chaos)"
                                : "5");
  }
  megnoLegend_ = new QLabel(legend, this);
  megnoLegend_->setObjectName("megno_legend");
  megnoLegend_->setVisible(false);
  layout->addWidget(modeBox_);
  auto* fit = new QPushButton("Fit", this);
  fit->setObjectName("fit_map");
  fit->setToolTip(
      "ranges around every point drawn (the axes stay put while you click: new trajectories do not "
      "rescale them; the wheel zooms, a drag in the pan / zoom mode moves)");
  connect(fit, &QPushButton::clicked, this, [this] {
    if (!chart_) return;
    chart_->fitToData();
    view_->update();
  });
  auto* bar = new QHBoxLayout; // a row of its own: the panel is narrow
  bar->addWidget(megnoBox_);
  bar->addWidget(megnoLegend_, 1);
  bar->addWidget(fit);
  layout->addLayout(bar);
  // the map coordinates under the cursor, beside the chart: nothing of the cursor is drawn into it (or into
  // an export of it), and the text never runs off the window's edge
  cursorLabel_ = new QLabel(this);
  cursorLabel_->setObjectName("cursor_position");
  cursorLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(cursorLabel_);
  layout->insertWidget(layout->count() - 1, view_, 1);
  view_->installEventFilter(this);
  view_->setMouseTracking(true);
  setMinimumSize(320, 320);
}

void MapPanel::setClickMode(ClickMode mode) {
  modeBox_->setCurrentIndex(static_cast<int>(mode));
}

MapPanel::~MapPanel() {
  jobs_.removeAll();
}

std::vector<int> MapPanel::sceneJobs() const {
  std::vector<int> ids;
  for (const Job* j : jobs_.jobs())
    if (!j->parent() && !j->task().ownsItsScene()) ids.push_back(j->id());
  return ids;
}

void MapPanel::setScene(const Scene& scene, bool startTrajectory) {
  // the map's tools belong to the old scene; a chart's or a sweep's job belongs to its window, which computes
  // its own scene
  for (int id : sceneJobs()) // by id: removing one removes the tools under it
    if (Job* j = jobs_.find(id)) jobs_.remove(*j);
  trajectories_.clear();
  searches_.clear();
  tools_.clear();
  filters_.newScene();
  scene_ = &scene;
  trajectories_.setScene(scene_);
  resetMap3D(false);
  const auto names = PoincareMap(*scene.model, scene.startIntegrator(), scene.poincare).coordinateNames();
  // a map of one coordinate is drawn against the crossing time ("time": a rotated "t" read as an arrow)
  axisNames_ = {names.at(0), names.size() > 1 ? names[1] : "time"};
  // one chart for the panel's life: replacing it would leave the window's interactor (and its timers)
  // driving a destroyed chart scene
  if (!chart_) {
    chart_ = std::make_unique<PoincareChart>(axisNames_[0], axisNames_[1]);
    chart_->setPointLabel(false); // the cursor's coordinates show in cursorLabel_
    chart_->attach(view_->renderWindow());
    trajectories_.setChart(chart_.get());
  } else {
    chart_->clear();
    chart_->setTitles(axisNames_[0], axisNames_[1]);
  }
  sceneStart_ = -1;
  if (startTrajectory) startSceneTrajectory();
}

void MapPanel::startSceneTrajectory() {
  if (!scene_) return;
  // where the scene says it starts (its first map point is one iteration or crossing later)
  const nlohmann::json map =
      scene_->document.value("initial", nlohmann::json::object()).value("map", nlohmann::json());
  QStringList at;
  if (map.is_array())
    for (const auto& v : map)
      if (v.is_number()) at << QString::number(v.get<double>(), 'g', 6);
  sceneStart_ = trajectories_
                    .start(scene_->initialState,
                           at.isEmpty() ? QString("the scene's initial state") : "(" + at.join(", ") + ")")
                    .id();
}

std::vector<int> MapPanel::addedJobs() const {
  std::vector<int> ids = sceneJobs();
  std::erase(ids, sceneStart_);
  return ids;
}

Job& MapPanel::start(const Eigen::VectorXd& state, const QString& origin) {
  return trajectories_.start(state, origin);
}

nlohmann::json MapPanel::saveRunning() {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& t : trajectories_.save({}, true, false))
    out.push_back(toJson(t));
  return out;
}

int MapPanel::resume(const nlohmann::json& saved) {
  if (!scene_ || !saved.is_array()) return 0;
  std::vector<SavedTrajectory> list;
  for (std::size_t i = 0; i < saved.size(); ++i)
    list.push_back(savedTrajectoryFromJson(saved[i], Where{"saved jobs", "[" + std::to_string(i) + "]"}));
  return trajectories_.restore(list);
}

void MapPanel::keepScene(const Scene& scene) {
  scene_ = &scene; // the trajectories run on their own copies of what defines them
  trajectories_.setScene(scene_);
}

void MapPanel::replaceTrajectories(const std::vector<SavedTrajectory>& saved,
                                   const std::vector<SavedToolOutput>& tools) {
  for (int id : sceneJobs())
    if (Job* j = jobs_.find(id)) removeJob(*j);
  sceneStart_ = -1;
  trajectories_.restore(saved);
  restoreToolOutputs(tools);
  chart_->select(-1); // nothing is selected in the tool manager: none emphasised (the last one was)
}

void MapPanel::setMapRanges(const std::array<double, 4>& r) {
  chart_->setRanges(r[0], r[1], r[2], r[3]);
  chart_->holdRanges();
  view_->update();
}

std::vector<double> MapPanel::mapPoint(double x, double y) const {
  // the click names the first two coordinates; a map of more (a 3D map, the rolling disk's four) takes the
  // rest from the scene's initial map point, else its fixed point guess, so that a search or a start from a
  // click lies near the scene's motion
  std::vector<double> point{x, y};
  const std::size_t n = scene_->model->info().mapCoordinates.size();
  const auto& doc = scene_->document;
  const auto full = [&](const char* section, const char* key) -> const nlohmann::json* {
    if (!doc.contains(section) || !doc[section].is_object() || !doc[section].contains(key)) return nullptr;
    const nlohmann::json& p = doc[section][key];
    return p.is_array() && p.size() == n ? &p : nullptr;
  };
  const nlohmann::json* from = full("initial", "map");
  if (!from) from = full("fixedpoint", "guess");
  for (std::size_t k = 2; k < n; ++k)
    point.push_back(from && (*from)[k].is_number() ? (*from)[k].get<double>() : 0.0);
  return point;
}

std::pair<QString, int> MapPanel::startOnSection(double x, double y) {
  // The click names the map's two coordinates; where they (and the section's observable) are state variables,
  // the scene's state takes them, so that the trajectory starts on the section at the point clicked; the rest
  // of the state is the scene's.
  const auto& names = scene_->model->info().stateNames;
  const auto index = [&](const std::string& name) {
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1 : static_cast<int>(it - names.begin());
  };
  const auto axes =
      PoincareMap(*scene_->model, scene_->startIntegrator(), scene_->poincare).coordinateNames();
  Eigen::VectorXd state = scene_->initialState;
  QStringList set;
  for (std::size_t k = 0; k < std::min<std::size_t>(2, axes.size()); ++k)
    if (const int i = index(axes[k]); i >= 0) {
      state[i] = k == 0 ? x : y;
      set << QString("%1 = %2").arg(QString::fromStdString(axes[k])).arg(state[i], 0, 'g', 6);
    }
  const std::string section =
      scene_->poincare.observable.empty() ? scene_->model->info().section : scene_->poincare.observable;
  if (const int i = index(section); i >= 0 && !set.isEmpty()) {
    state[i] = scene_->poincare.value;
    set << QString("%1 = %2 (the section)").arg(QString::fromStdString(section)).arg(state[i], 0, 'g', 6);
  }
  const int job = start(state, set.isEmpty() ? QString("the scene's state") : set.join(", ")).id();
  const QString id = QString::fromStdString(scene_->model->info().id);
  return {
      set.isEmpty()
          ? QString("from the scene's state: %1 has no map coordinates and the map's axes are not its state "
                    "variables (give the start in the control panel)")
                .arg(id)
          : QString("at %1, the rest of the state the scene's (%2 has no map coordinates of its own: a click "
                    "sets the map's axes and the section's variable)")
                .arg(set.join(", "), id),
      job};
}

bool MapPanel::startAt(double x, double y) {
  if (!scene_) return false;
  chart_->holdRanges(); // the next click lands where the user aims: the new points do not rescale the axes
  try {
    const auto& info = scene_->model->info();
    if (info.mapCoordinates.empty()) { // a flow whose map has no coordinates of its own (Lorenz)
      const auto [how, job] = startOnSection(x, y);
      emit message(QString("trajectory #%1 started %2").arg(job).arg(how));
      return true;
    }
    const MapPointSpec spec{.sectionValue = scene_->poincare.value,
                            .root = std::max(1, scene_->poincare.root)};
    const Job& job = trajectories_.start(scene_->model->stateFromMap(mapPoint(x, y), spec, "map point"),
                                         QString("(%1, %2)").arg(x, 0, 'g', 6).arg(y, 0, 'g', 6));
    // numbered as the tool manager numbers its jobs
    emit message(QString("trajectory #%1 started at (%2, %3)").arg(job.id()).arg(x).arg(y));
    return true;
  } catch (const InputError& e) {
    emit message(QString::fromStdString(e.what()));
    return false;
  }
}

void MapPanel::addPlotWindow(PlotWindow* window) {
  filters_.addPlot(window);
  trajectories_.follow(window);
}

void MapPanel::addDiagramWindow(ChartWindow* window) {
  filters_.addDiagram(window);
  markDiagrams(true);
}

void MapPanel::markDiagrams(bool force) {
  if (!scene_) return;
  filters_.markDiagrams(
      *scene_->model, [this](const Diagram& d) { return trajectories_.marks(d); }, force);
}

std::vector<PlotWindow*> MapPanel::plotWindows() {
  return filters_.plots();
}

bool MapPanel::drain() {
  for (PlotWindow* p : plotWindows())
    p->flush();
  bool changed = false;
  for (auto& t : tools_) {
    const bool finished = t.job->status() == Job::Status::Finished; // read before the last points are taken
    if (t.pull(t)) {
      chart_->setSeries(t.plot, t.x, t.y);
      changed = true;
    } else if (finished && !t.endSaid && t.ended) { // all it made is drawn: its outcome to the Results dock
      t.endSaid = true;
      emit message(t.ended(t));
    }
  }
  changed = drainSearches() || changed;
  changed = trajectories_.drain() || changed;
  filters_.flush();
  markDiagrams(false);
  if (changed) {
    view_->update();
    map3D_->feed(trajectories_.tracks());
  }
  return changed;
}

void MapPanel::removeJob(Job& job) {
  const std::vector<Job*> gone = jobs_.subtree(job);
  const auto isGone = [&](const Job* j) { return std::find(gone.begin(), gone.end(), j) != gone.end(); };
  trajectories_.remove(isGone);
  for (auto it = tools_.begin(); it != tools_.end();)
    if (isGone(it->job)) {
      chart_->setSeries(it->plot, {}, {});
      filters_.forget(it->job->id());
      it = tools_.erase(it);
    } else {
      ++it;
    }
  for (auto it = searches_.begin(); it != searches_.end();)
    if (isGone(it->job)) {
      filters_.forget(it->job->id());
      chart_->setSeries(it->point, {}, {});
      chart_->setSeries(it->found, {}, {});
      if (it->path >= 0) chart_->setSeries(it->path, {}, {});
      it = searches_.erase(it);
    } else {
      ++it;
    }
  std::vector<int> ids;
  ids.reserve(gone.size());
  for (const Job* j : gone)
    ids.push_back(j->id());
  jobs_.remove(job);
  view_->update();
  resetMap3D(true); // its series follow the trajectories' order
  for (int id : ids)
    emit jobRemoved(id);
}

void MapPanel::editJob(Job& job, const Scene& edited) {
  bool goesOn = true;
  job.edit([&](Task& t) { goesOn = editTask(t, edited); });
  if (!goesOn) clearOutput(job.id());
}

void MapPanel::clearOutput(int id) {
  trajectories_.clearOutput(id);
  for (auto& t : tools_)
    if (t.job->id() == id) {
      t.x.clear(), t.y.clear(), t.multipliers.clear(), t.endSaid = false;
      chart_->setSeries(t.plot, {}, {});
      filters_.forget(id);
    }
  for (auto& s : searches_)
    if (s.job->id() == id) {
      s.x.clear(), s.y.clear(), s.reported = false, s.multipliers.clear(), s.foundAt.clear();
      filters_.forget(id);
      chart_->setSeries(s.point, {}, {});
      chart_->setSeries(s.found, {}, {});
      if (s.path >= 0) chart_->setSeries(s.path, {}, {});
    }
  view_->update();
  resetMap3D(true);
}

void MapPanel::stopAll() {
  jobs_.stopAll();
}

long MapPanel::points() const {
  return trajectories_.points();
}

bool MapPanel::eventFilter(QObject* watched, QEvent* event) {
  if (watched == view_ && chart_ && event->type() == QEvent::MouseMove) {
    const auto* e = static_cast<QMouseEvent*>(event);
    const double dpr = view_->devicePixelRatioF();
    double x, y;
    const bool inside =
        chart_->toChart(e->position().x() * dpr, (view_->height() - e->position().y()) * dpr, x, y);
    cursorLabel_->setText(inside ? QString("%1 = %2, %3 = %4")
                                       .arg(QString::fromStdString(axisNames_[0]))
                                       .arg(x, 0, 'g', 6)
                                       .arg(QString::fromStdString(axisNames_[1]))
                                       .arg(y, 0, 'g', 6)
                                 : QString());
  }
  if (watched == view_ && event->type() == QEvent::Leave) cursorLabel_->clear();
  if (watched == view_ && chart_ && event->type() == QEvent::Wheel) chart_->holdRanges(); // a zoom stays
  if (watched == view_ && event->type() == QEvent::ContextMenu && chart_) { // on a fixed point found
    const auto* e = static_cast<QContextMenuEvent*>(event);
    if (const int id = fixedPointAt(e->pos()); id >= 0) {
      auto* menu = new QMenu(this);
      menu->setObjectName("fixed_point_menu");
      menu->setAttribute(Qt::WA_DeleteOnClose);
      menu->addAction(QString("Continue this fixed point (tool #%1)").arg(id), this,
                      [this, id] { continueFixedPoint(id); })
          ->setToolTip(
              "its family in the parameter of the control panel's continuation tab, to its end value");
      menu->popup(e->globalPos());
      return true;
    }
  }
  if (watched == view_ && event->type() == QEvent::MouseButtonPress && chart_) {
    auto* e = static_cast<QMouseEvent*>(event);
    const bool ctrl = e->modifiers() & Qt::ControlModifier, shift = e->modifiers() & Qt::ShiftModifier;
    const bool plain = !ctrl && !shift && clickMode_ != ClickMode::Navigate;
    if (e->button() == Qt::LeftButton && (ctrl || shift || plain)) {
      const double dpr = view_->devicePixelRatioF();
      double x, y;
      if (chart_->toChart(e->position().x() * dpr, (view_->height() - e->position().y()) * dpr, x, y)) {
        if (ctrl || (plain && clickMode_ == ClickMode::Trajectory))
          startAt(x, y);
        else
          searchFixedPointAt(x, y);
      }
      return true; // not a pan or zoom of the chart
    }
  }
  return QWidget::eventFilter(watched, event);
}

void MapPanel::highlightJob(int id) {
  if (!chart_) return;
  const auto [plot, index] = trajectories_.plotOf(id);
  chart_->select(plot);
  view_->update();
  // every window that draws it (manual §2.1)
  for (PlotWindow* p : plotWindows())
    p->highlight(id);
  map3D_->select(index); // its series follow the trajectories' order
}

void MapPanel::setColourByMegno(bool on) {
  if (megnoBox_->isChecked() != on) megnoBox_->setChecked(on);
  megnoLegend_->setVisible(on);
  trajectories_.setColourByMegno(on);
}

void MapPanel::resetMap3D(bool reopen) {
  if (!map3D_->open()) return;
  const bool again = reopen && map3D_->visible();
  map3D_->reset(again);
  if (again) openMap3D();
}

QWidget* MapPanel::openMap3D() {
  if (!scene_) return nullptr;
  const auto names =
      PoincareMap(*scene_->model, scene_->startIntegrator(), scene_->poincare).coordinateNames();
  if (names.size() < 3) {
    emit message(
        "Map3D: this map is two-dimensional (Windows > Charts > map3d shows it on its energy level)");
    return nullptr;
  }
  return map3D_->open({names[0], names[1], names[2]}, trajectories_.tracks());
}

long MapPanel::map3DPoints() const {
  return map3D_->points();
}

} // namespace rv
