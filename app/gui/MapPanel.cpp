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

MapPanel::MapPanel(QWidget* parent) : QWidget(parent), map3D_(std::make_unique<Map3DWindow>(this)) {
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
    const Rgb c = megnoColour(y);
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
  series_.clear();
  searches_.clear();
  tools_.clear();
  filters_.newScene();
  scene_ = &scene;
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
  } else {
    chart_->clear();
    chart_->setTitles(axisNames_[0], axisNames_[1]);
  }
  sceneStart_ = -1;
  if (startTrajectory) startSceneTrajectory();
}

void MapPanel::startSceneTrajectory() {
  if (!scene_) return;
  start(scene_->initialState);
  sceneStart_ = series_.back().job->id();
  // where the scene says it starts (its first map point is one iteration or crossing later)
  const nlohmann::json map =
      scene_->document.value("initial", nlohmann::json::object()).value("map", nlohmann::json());
  QStringList at;
  if (map.is_array())
    for (const auto& v : map)
      if (v.is_number()) at << QString::number(v.get<double>(), 'g', 6);
  series_.back().origin = at.isEmpty() ? QString("the scene's initial state") : "(" + at.join(", ") + ")";
}

std::vector<int> MapPanel::addedJobs() const {
  std::vector<int> ids = sceneJobs();
  std::erase(ids, sceneStart_);
  return ids;
}

void MapPanel::start(const Eigen::VectorXd& state) {
  RunSpec spec = scene_->runSpec();
  spec.initialState = state;
  auto task = std::make_unique<PoincareTask>(spec, scene_->poincare);
  PoincareTask* raw = task.get();
  Job& job = jobs_.add(std::move(task));
  const Rgb colour = seriesColor(static_cast<int>(series_.size()));
  const int plot = chart_->addSeries({}, {}, colour);
  series_.push_back({&job, raw, {}, {}, {}, plot, colour});
  series_.back().since.start();
  feedPlots(series_.back());
  if (colourByMegno_) startMegno(series_.back());
  chart_->select(plot);
  job.start();
}

namespace {
std::map<std::string, double> valuesMap(const ParameterValues& v) {
  std::map<std::string, double> m;
  for (const auto& spec : v.table().specs())
    m[spec.id] = v[spec.id];
  return m;
}
void setValues(ParameterValues& v, const std::map<std::string, double>& m, const std::string& what) {
  for (const auto& [id, value] : m)
    v.set(id, value, what + "." + id);
}
} // namespace

std::size_t MapPanel::takePoints(Series& s, std::size_t most) {
  if (s.pendingAt >= s.pending.size()) {
    s.task->points().take(s.pending);
    s.pendingAt = 0;
  }
  const std::size_t end = s.pendingAt + std::min(most, s.pending.size() - s.pendingAt);
  for (std::size_t k = s.pendingAt; k < end; ++k) {
    MapPoint& p = s.pending[k];
    s.x.push_back(p.coordinates.at(0));
    s.y.push_back(p.coordinates.size() > 1 ? p.coordinates[1] : p.time);
    if (p.coordinates.size() > 2) s.z.push_back(p.coordinates[2]);
    // freed now, a few thousand a turn, not all at once when the next batch replaces this one (10^5 frees
    // in one turn of the event loop)
    std::vector<double>().swap(p.coordinates);
  }
  const std::size_t taken = end - s.pendingAt;
  s.pendingAt = end;
  return taken;
}

std::vector<SavedTrajectory> MapPanel::saveTrajectories(const std::vector<int>& ids, bool onlyRunning,
                                                        bool goOn) {
  std::vector<SavedTrajectory> out;
  for (auto& s : series_) {
    const bool wanted = ids.empty() || std::find(ids.begin(), ids.end(), s.job->id()) != ids.end();
    const bool running = s.job->running();
    if (!wanted || (onlyRunning && !running)) continue;
    s.job->stop(); // (its state is read only while it does not run)
    // what was produced before the stop, drawn or not yet, is part of what is saved
    while (takePoints(s, std::numeric_limits<std::size_t>::max()) > 0) {
    }
    Snapshot state;
    s.task->save(state);
    const RunSpec& spec = s.task->spec();
    SavedTrajectory t;
    t.start.assign(spec.initialState.data(), spec.initialState.data() + spec.initialState.size());
    t.parameters = valuesMap(spec.modelParameters);
    t.integrator = valuesMap(spec.integratorParameters);
    t.colour = s.colour;
    t.x = s.x, t.y = s.y, t.z = s.z;
    t.state = std::move(state.values);
    t.running = running;
    t.first = s.first, t.last = s.last;
    t.origin = s.origin.toStdString();
    t.id = s.job->id();
    out.push_back(std::move(t));
    if (goOn && running) s.job->start();
  }
  return out;
}

nlohmann::json MapPanel::saveRunning() {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& t : saveTrajectories({}, true, false))
    out.push_back(toJson(t));
  return out;
}

int MapPanel::resume(const nlohmann::json& saved) {
  if (!scene_ || !saved.is_array()) return 0;
  std::vector<SavedTrajectory> list;
  for (std::size_t i = 0; i < saved.size(); ++i)
    list.push_back(savedTrajectoryFromJson(saved[i], Where{"saved jobs", "[" + std::to_string(i) + "]"}));
  return restoreTrajectories(list);
}

int MapPanel::restoreTrajectories(const std::vector<SavedTrajectory>& saved) {
  if (!scene_) return 0;
  // checked whole first: a list that does not fit the scene adds nothing
  std::vector<std::unique_ptr<PoincareTask>> tasks;
  for (std::size_t n = 0; n < saved.size(); ++n) {
    const SavedTrajectory& t = saved[n];
    const std::string what = "saved trajectory " + std::to_string(n + 1);
    RunSpec spec = scene_->runSpec();
    if (static_cast<Eigen::Index>(t.start.size()) != spec.initialState.size())
      throw InputError(what + ": made for another problem");
    spec.initialState =
        Eigen::Map<const Eigen::VectorXd>(t.start.data(), static_cast<Eigen::Index>(t.start.size()));
    setValues(spec.modelParameters, t.parameters, what + ".parameters");
    setValues(spec.integratorParameters, t.integrator, what + ".integrator");
    auto task = std::make_unique<PoincareTask>(spec, scene_->poincare);
    Snapshot state{t.state, 0};
    task->restore(state);
    tasks.push_back(std::move(task));
  }
  for (std::size_t n = 0; n < saved.size(); ++n) {
    const SavedTrajectory& t = saved[n];
    PoincareTask* raw = tasks[n].get();
    Job& job = jobs_.add(std::move(tasks[n]), nullptr, t.id); // its number, where it is free
    const int plot = chart_->addSeries({}, {}, t.colour);
    series_.push_back({&job, raw, t.x, t.y, t.z, plot, t.colour});
    Series& s = series_.back();
    s.since.start();
    s.first = t.first, s.last = t.last;
    s.origin = QString::fromStdString(t.origin);
    drawSeries(s);
    feedPlots(s);
    if (colourByMegno_) startMegno(s);
    // a finished one finishes again at once (its limit is reached); one the user had stopped stays so
    if (t.running || (raw->limit() > 0 && raw->produced() >= raw->limit())) job.start();
  }
  return static_cast<int>(saved.size());
}

void MapPanel::keepScene(const Scene& scene) {
  scene_ = &scene; // the trajectories run on their own copies of what defines them
}

void MapPanel::replaceTrajectories(const std::vector<SavedTrajectory>& saved,
                                   const std::vector<SavedToolOutput>& tools) {
  for (int id : sceneJobs())
    if (Job* j = jobs_.find(id)) removeJob(*j);
  sceneStart_ = -1;
  restoreTrajectories(saved);
  restoreToolOutputs(tools);
  chart_->select(-1); // nothing is selected in the tool manager: none emphasised (the last one was)
}

bool MapPanel::morePoints(int id, long more) {
  for (auto& s : series_)
    if (s.job->id() == id) {
      if (s.job->running() || s.task->limit() <= 0) return false;
      s.job->edit([more](Task& t) { static_cast<PoincareTask&>(t).extend(more); });
      s.job->start();
      return true;
    }
  return false;
}

std::pair<std::vector<double>, std::vector<double>> MapPanel::trajectoryPoints(int id) const {
  for (const auto& s : series_)
    if (s.job->id() == id) return {s.x, s.y};
  return {};
}

void MapPanel::setMapRanges(const std::array<double, 4>& r) {
  chart_->setRanges(r[0], r[1], r[2], r[3]);
  chart_->holdRanges();
  view_->update();
}

std::vector<double> MapPanel::mapPoint(double x, double y) const {
  std::vector<double> point{x, y};
  if (scene_->model->info().mapCoordinates.size() == 3) { // a 3D map: Z from the scene's initial point
    const auto& doc = scene_->document;
    const bool hasZ =
        doc.contains("initial") && doc["initial"].contains("map") && doc["initial"]["map"].size() == 3;
    point.push_back(hasZ ? doc["initial"]["map"][2].get<double>() : 0.0);
  }
  return point;
}

QString MapPanel::startOnSection(double x, double y) {
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
  start(state);
  series_.back().origin = set.isEmpty() ? QString("the scene's state") : set.join(", ");
  const QString id = QString::fromStdString(scene_->model->info().id);
  return set.isEmpty()
             ? QString(
                   "from the scene's state: %1 has no map coordinates and the map's axes are not its state "
                   "variables (give the start in the control panel)")
                   .arg(id)
             : QString(
                   "at %1, the rest of the state the scene's (%2 has no map coordinates of its own: a click "
                   "sets the map's axes and the section's variable)")
                   .arg(set.join(", "), id);
}

bool MapPanel::startAt(double x, double y) {
  if (!scene_) return false;
  chart_->holdRanges(); // the next click lands where the user aims: the new points do not rescale the axes
  try {
    const auto& info = scene_->model->info();
    if (info.mapCoordinates.empty()) { // a flow whose map has no coordinates of its own (Lorenz)
      const QString how = startOnSection(x, y);
      emit message(QString("trajectory #%1 started %2").arg(series_.back().job->id()).arg(how));
      return true;
    }
    const MapPointSpec spec{.sectionValue = scene_->poincare.value,
                            .root = std::max(1, scene_->poincare.root)};
    start(scene_->model->stateFromMap(mapPoint(x, y), spec, "map point"));
    series_.back().origin = QString("(%1, %2)").arg(x, 0, 'g', 6).arg(y, 0, 'g', 6);
    // numbered as the tool manager numbers its jobs
    emit message(QString("trajectory #%1 started at (%2, %3)").arg(series_.back().job->id()).arg(x).arg(y));
    return true;
  } catch (const InputError& e) {
    emit message(QString::fromStdString(e.what()));
    return false;
  }
}

void MapPanel::feedPlots(const Series& s) {
  for (PlotWindow* p : plotWindows())
    s.task->taps().add(p->follow(s.job->id(), s.colour));
}

void MapPanel::addPlotWindow(PlotWindow* window) {
  filters_.addPlot(window);
  for (const auto& s : series_)
    s.task->taps().add(window->follow(s.job->id(), s.colour));
}

void MapPanel::addDiagramWindow(ChartWindow* window) {
  filters_.addDiagram(window);
  markDiagrams(true);
}

void MapPanel::markDiagrams(bool force) {
  if (!scene_) return;
  filters_.markDiagrams(
      *scene_->model,
      [this](const Diagram& d) {
        std::vector<ChartWindow::Mark> marks;
        for (const auto& s : series_) {
          const DiagramPoint p = d.place(s.task->levelState().data());
          marks.push_back({p[0], p[1], s.colour});
        }
        return marks;
      },
      force);
}

std::shared_ptr<PlotTap> MapPanel::tapTrajectory(int id, const PlotSettings& settings) {
  for (const auto& s : series_)
    if (s.job->id() == id) {
      try {
        PlotSampler check(*scene_->model, settings); // fail here, not on the job's thread
      } catch (const InputError&) {
        return nullptr;
      }
      auto tap = std::make_shared<PlotTap>(settings);
      s.task->taps().add(tap);
      return tap;
    }
  return nullptr;
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
  for (auto& s : series_) { // a MEGNO job that has ended colours its trajectory
    if (!s.megnoJob || s.megnoValue || s.megnoJob->running()) continue;
    if (s.megnoJob->status() == Job::Status::Finished) {
      const auto& last = s.megno->result().last;
      s.megnoValue = last.megno;
      applyColour(s);
      changed = true;
      // <Y> near 2 is a torus; on a chaotic orbit it grows like lambda t / 2 (the rate tends to lambda)
      emit message(QString("MEGNO (tool #%1) of trajectory #%2: <Y> = %3 at t = %4, rate %5")
                       .arg(s.megnoJob->id())
                       .arg(s.job->id())
                       .arg(last.megno, 0, 'g', 6)
                       .arg(last.time, 0, 'g', 6)
                       .arg(last.megnoRate, 0, 'g', 4));
    } else if (s.megnoJob->status() == Job::Status::Failed) {
      // drawn in its own colour; why it failed is said once, by the tool manager (as every job's failure)
      s.megnoValue = std::numeric_limits<double>::quiet_NaN();
    }
  }
  // the points a few milliseconds allow in this turn of the event loop (the map's frame comes after them in
  // the same turn), at most kDrainPerTick a series
  QElapsedTimer spent;
  spent.start();
  for (auto& s : series_) {
    std::size_t taken = 0;
    while (taken < kDrainPerTick && (taken == 0 || spent.elapsed() < kDrainMilliseconds)) {
      const std::size_t got = takePoints(s, std::min<std::size_t>(kDrainPerTick - taken, 4096));
      if (got == 0) break;
      taken += got;
    }
    if (taken == 0) {
      if (s.x.empty() && !s.noCrossingSaid && s.job->running() && !scene_->model->isMap() &&
          s.since.elapsed() > kNoCrossingMilliseconds) {
        s.noCrossingSaid = true; // once: e.g. the Chaplygin sleigh's spin dies out and never changes sign
        const SectionSettings& section = s.task->settings();
        emit message(
            QString("trajectory #%1 has not crossed the section %2 = %3 yet: its orbit may never reach "
                    "it (the Poincaré map tab chooses another section)")
                .arg(s.job->id())
                .arg(QString::fromStdString(section.observable.empty() ? scene_->model->info().section
                                                                       : section.observable))
                .arg(section.value));
      }
      continue;
    }
    drawSeries(s);
    changed = true;
  }
  filters_.flush();
  markDiagrams(false);
  if (changed) {
    view_->update();
    map3D_->feed(map3DTracks());
  }
  return changed;
}

void MapPanel::removeJob(Job& job) {
  const std::vector<Job*> gone = jobs_.subtree(job);
  const auto isGone = [&](const Job* j) { return std::find(gone.begin(), gone.end(), j) != gone.end(); };
  for (auto& s : series_)
    if (s.megnoJob && isGone(s.megnoJob) && !isGone(s.job)) { // its MEGNO alone: back to its own colour
      s.megnoJob = nullptr, s.megno = nullptr, s.megnoValue.reset();
      chart_->setColor(s.plot, s.colour);
    }
  for (auto it = series_.begin(); it != series_.end();)
    if (isGone(it->job)) {
      chart_->setSeries(it->plot, {}, {});
      for (PlotWindow* p : plotWindows())
        p->unfollow(it->job->id());
      it = series_.erase(it);
    } else {
      ++it;
    }
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
  for (auto& s : series_)
    if (s.job->id() == id) {
      s.x.clear(), s.y.clear(), s.z.clear();
      drawSeries(s);
      for (PlotWindow* p : plotWindows())
        p->clear(id);
    }
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
  long n = 0;
  for (const auto& s : series_)
    n += static_cast<long>(s.x.size());
  return n;
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
  int plot = -1, index = -1;
  for (std::size_t k = 0; k < series_.size(); ++k)
    if (series_[k].job->id() == id) plot = series_[k].plot, index = static_cast<int>(k);
  chart_->select(plot);
  view_->update();
  // every window that draws it (manual §2.1)
  for (PlotWindow* p : plotWindows())
    p->highlight(id);
  map3D_->select(index); // its series follow the trajectories' order
}

std::pair<long, long> MapPanel::shownSpan(const Series& s) {
  const long n = static_cast<long>(s.x.size());
  const long a = std::clamp(s.first - 1, 0L, n), b = s.last > 0 ? std::clamp(s.last, a, n) : n;
  return {a, b};
}

void MapPanel::drawSeries(const Series& s) {
  if (s.first <= 1 && s.last <= 0) return chart_->setSeries(s.plot, s.x, s.y);
  const auto [a, b] = shownSpan(s);
  chart_->setSeries(s.plot, {s.x.begin() + a, s.x.begin() + b}, {s.y.begin() + a, s.y.begin() + b});
}

bool MapPanel::isTrajectory(int id) const {
  return std::any_of(series_.begin(), series_.end(), [&](const Series& s) { return s.job->id() == id; });
}

QString MapPanel::trajectoryStart(int id) const {
  for (const auto& s : series_)
    if (s.job->id() == id) {
      if (!s.origin.isEmpty() || s.x.empty()) return s.origin;
      return QString("(%1, %2)").arg(s.x[0], 0, 'g', 6).arg(s.y[0], 0, 'g', 6);
    }
  return {};
}

bool MapPanel::setJobColor(int id, const Rgb& color) {
  for (auto& s : series_)
    if (s.job->id() == id) {
      s.colour = color;
      applyColour(s); // its own colour shows unless it is coloured by its MEGNO
      for (PlotWindow* p : plotWindows())
        p->setColor(id, color);
      view_->update();
      return true;
    }
  return false;
}

Rgb MapPanel::megnoColour(double megno) {
  // 2 and below blue (hue 240), 8 and above red (hue 0); NaN (a failed job) falls to blue
  const double t = std::clamp((megno - 2) / 6, 0.0, 1.0);
  const QColor c = QColor::fromHsvF(static_cast<float>(2.0 / 3.0 * (1 - t)), 0.85f, 0.9f);
  return {c.redF(), c.greenF(), c.blueF()};
}

void MapPanel::startMegno(Series& s) {
  if (s.megnoJob) return;
  auto task = std::make_unique<MegnoTask>(s.task->spec(), scene_->megno);
  s.megno = task.get();
  s.megnoJob = &jobs_.add(std::move(task), s.job);
  s.megnoJob->start();
}

void MapPanel::applyColour(const Series& s) {
  const Rgb c = shownColour(s.job->id());
  chart_->setColor(s.plot, c);
  view_->update();
}

void MapPanel::setColourByMegno(bool on) {
  colourByMegno_ = on;
  if (megnoBox_->isChecked() != on) megnoBox_->setChecked(on);
  megnoLegend_->setVisible(on);
  for (auto& s : series_) {
    if (on) startMegno(s);
    applyColour(s);
  }
}

std::optional<double> MapPanel::trajectoryMegno(int id) const {
  for (const auto& s : series_)
    if (s.job->id() == id) return s.megnoValue;
  return std::nullopt;
}

Rgb MapPanel::shownColour(int id) const {
  for (const auto& s : series_)
    if (s.job->id() == id)
      return colourByMegno_ && s.megnoValue && !std::isnan(*s.megnoValue) ? megnoColour(*s.megnoValue)
                                                                          : s.colour;
  return {0, 0, 0};
}

bool MapPanel::setJobRange(int id, long first, long last) {
  for (auto& s : series_)
    if (s.job->id() == id) {
      s.first = std::max(1L, first), s.last = last;
      drawSeries(s);
      view_->update();
      return true;
    }
  return false;
}

long MapPanel::shownPoints(int id) const {
  for (const auto& s : series_)
    if (s.job->id() == id) {
      const auto [a, b] = shownSpan(s);
      return b - a;
    }
  return 0;
}

std::vector<Map3DWindow::Track> MapPanel::map3DTracks() const {
  std::vector<Map3DWindow::Track> tracks;
  tracks.reserve(series_.size());
  for (const auto& s : series_)
    tracks.push_back({&s.x, &s.y, &s.z});
  return tracks;
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
  return map3D_->open({names[0], names[1], names[2]}, map3DTracks());
}

long MapPanel::map3DPoints() const {
  return map3D_->points();
}

} // namespace rv
