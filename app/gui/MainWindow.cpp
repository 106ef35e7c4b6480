// MainWindow.cpp -- the main window's scene and its run: docks, scenes opened and applied, the 3D view's
// playback, snapshots and recordings, and the chart, sweep, plot and apex windows it opens.
#include "app/gui/MainWindow.h"

#include "app/gui/ApexWindow.h"
#include "app/gui/ChartWindow.h"
#include "app/gui/ControlPanel.h"
#include "app/gui/FilterWindow.h"
#include "app/gui/MapPanel.h"
#include "app/gui/MultipliersWindow.h"
#include "app/gui/PlotWindow.h"
#include "app/gui/QtVtkWidget.h"
#include "app/gui/SweepWindow.h"
#include "app/gui/ToolManager.h"
#include "app/gui/ViewRecorder.h"
#include "app/gui/VisualizerSettings.h"
#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "dynamics/jobs/PoincareTask.h"
#include "dynamics/tools/ToolRegistry.h"
#include "render/charts/PoincareChart.h"
#include "render/video/VideoExport.h"
#include "scenes/ModelFile.h"
#include "scenes/SceneCharts.h"
#include "scenes/SceneLoader.h"
#include "scenes/ToolRunner.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSaveFile>
#include <QSettings>
#include <QSignalBlocker>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTime>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <vtkCamera.h>
#include <vtkChartXY.h>
#include <vtkPlot.h>
#include <vtkRenderer.h>

namespace rv {

namespace {
/// The numbers a chart's legend names ("L1 = 0.091", "<Y> = 2.01", ...), joined, and in what order where the
/// legend orders them; empty when it names none.
QString numbersOf(const Chart& chart) {
  const auto* plane = dynamic_cast<const PoincareChart*>(&chart);
  if (!plane) return {};
  QStringList named;
  for (vtkIdType i = 0; i < plane->chart()->GetNumberOfPlots(); ++i) {
    vtkPlot* plot = plane->chart()->GetPlot(i);
    const QString label = QString::fromStdString(plot->GetLabel());
    if (plot->GetLegendVisibility() && label.contains(" = ")) named << label;
  }
  if (named.isEmpty() || plane->legendOrder().empty()) return named.join(", ");
  return QString::fromStdString(plane->legendOrder()) + ": " + named.join(", ");
}
} // namespace

void MainWindow::report(const QString& text, int timeoutMs) {
  statusBar()->showMessage(text, timeoutMs);
  results_->appendPlainText(QTime::currentTime().toString("HH:mm:ss") + "  " + text);
  results_->moveCursor(QTextCursor::End); // the newest line shows
  results_->ensureCursorVisible();
}

QString MainWindow::results() const {
  return results_->toPlainText();
}

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  view_ = new QtVtkWidget(this);
  setCentralWidget(view_);
  map_ = new MapPanel(this);
  auto* dock = new QDockWidget("Poincaré map", this);
  dock->setObjectName("map");
  dock->setWidget(map_);
  addDockWidget(Qt::RightDockWidgetArea, dock);
  control_ = new ControlPanel(this);
  auto* controlDock = new QDockWidget("Control panel", this);
  controlDock->setObjectName("control");
  controlDock->setWidget(control_);
  addDockWidget(Qt::LeftDockWidgetArea, controlDock);
  control_->setMinimumWidth(300); // labels and values readable side by side
  tools_ = new ToolManager(
      map_->jobs(), [this](Job& j) { map_->removeJob(j); }, this);
  tools_->setEditor([this](Job& job) {
    const Scene edited = sceneFromJson(control_->editedDocument(), scene_ ? scene_->source : "edited scene");
    map_->editJob(job, edited);
  });
  connect(tools_, &ToolManager::restarted, map_, &MapPanel::clearOutput);
  connect(tools_, &ToolManager::aboutToDelete, this,
          [this](const std::vector<int>& roots) { rememberDeletedForUndo(roots); });
  tools_->setMore([this](int id) { // as many points again as the scene gives a trajectory
    if (!scene_ || !map_->trajectories().morePoints(id, scene_->poincare.maxPoints)) return false;
    report(QString("trajectory #%1 goes on for %2 more points").arg(id).arg(scene_->poincare.maxPoints),
           5000);
    return true;
  });
  connect(tools_, &ToolManager::message, this, [this](const QString& m) { report(m, 8000); });
  connect(tools_, &ToolManager::selectedJob, map_, &MapPanel::highlightJob);
  apex_ = std::make_unique<ApexWindow>(this, [this](QWidget* w) { placeWindow(w); });
  recorder_ = new ViewRecorder(view_, this);
  connect(recorder_, &ViewRecorder::finished, this, &MainWindow::recordingWritten);
  connect(tools_, &ToolManager::selectedJob, this, [this](int id) {
    if (scene_ && apex_) apex_->follow(id, *map_, *scene_, shownTime_);
  });
  connect(map_, &MapPanel::jobRemoved, this, [this](int id) {
    if (scene_ && apex_) apex_->forget(id, *map_, *scene_, shownTime_);
  });
  tools_->setRowLook([this](int id) {
    ToolManager::RowLook look{map_->trajectories().origin(id), std::nullopt};
    if (map_->trajectories().contains(id)) look.colour = map_->trajectories().shownColour(id);
    return look;
  });
  tools_->setOutputActions(
      [this](int id, const Rgb& c) { return map_->trajectories().setColour(id, c); },
      [this](int id, long a, long b) { return map_->trajectories().setRange(id, a, b); });
  auto* toolsDock = new QDockWidget("Tool manager", this);
  toolsDock->setObjectName("tools");
  toolsDock->setWidget(tools_);
  addDockWidget(Qt::BottomDockWidgetArea, toolsDock);
  // the results of the session beside the tool manager: they outlive the status bar's few seconds
  auto* resultsPane = new QWidget(this);
  auto* resultsLayout = new QVBoxLayout(resultsPane);
  resultsLayout->setContentsMargins(2, 2, 2, 2);
  results_ = new QPlainTextEdit(resultsPane);
  results_->setObjectName("results");
  results_->setReadOnly(true);
  results_->setMinimumWidth(360); // a fixed point's line with its multipliers reads in two lines
  results_->setToolTip("every result and message of the session (select and copy; Clear empties it)");
  auto* clear = new QPushButton("Clear", resultsPane);
  clear->setObjectName("clear_results");
  connect(clear, &QPushButton::clicked, results_, &QPlainTextEdit::clear);
  resultsLayout->addWidget(results_, 1);
  resultsLayout->addWidget(clear, 0, Qt::AlignRight);
  auto* resultsDock = new QDockWidget("Results", this);
  resultsDock->setObjectName("results_dock");
  resultsDock->setWidget(resultsPane);
  addDockWidget(Qt::BottomDockWidgetArea, resultsDock);
  splitDockWidget(toolsDock, resultsDock, Qt::Horizontal);
  resizeDocks({toolsDock}, {220}, Qt::Vertical); // the 3D view keeps most of the height; six rows show
  resizeDocks({toolsDock, resultsDock}, {700, 500}, Qt::Horizontal);
  // wide enough for the first tabs' whole titles (Problem, Method, Tools, Poincare map) and the forms' fields
  resizeDocks({controlDock}, {400}, Qt::Horizontal);
  connect(control_, &ControlPanel::apply, this, [this](const nlohmann::json& doc) { applyDocument(doc); });
  connect(control_, &ControlPanel::create, this, [this](const std::string& id) { createTool(id); });
  connect(control_, &ControlPanel::problemChosen, this, [this](const std::string& id) { chooseProblem(id); });
  connect(control_, &ControlPanel::message, this, [this](const QString& m) { report(m, 8000); });
  settings_ = new VisualizerSettings(this);
  auto* settingsDock = new QDockWidget("Visualizer settings", this);
  settingsDock->setObjectName("settings");
  settingsDock->setWidget(settings_);
  addDockWidget(Qt::RightDockWidgetArea, settingsDock);
  settingsDock->hide();
  connect(settings_, &VisualizerSettings::objectEdited, this,
          [this](const std::string& n, const ObjectOptions& o) { editObject(n, o); });
  connect(settings_, &VisualizerSettings::axesEdited, this, [this](const AxesOptions& a) { editAxes(a); });
  setAcceptDrops(true);
  resize(1400, 800);

  buildToolBars(settingsDock);
  buildMenus();
  status_ = new QLabel(this);
  statusBar()->addWidget(status_, 1);
  connect(map_, &MapPanel::message, this, [this](const QString& m) { report(m, 8000); });
  // a tool started on the map runs with its tabs as the control panel shows them (no Apply needed); what
  // defines the map -- the problem, the method, the initial state, the section -- stays the scene's
  map_->setToolDocument([this] {
    nlohmann::json doc = scene_->document;
    if (!control_->pending()) return doc;
    const nlohmann::json edited = control_->editedDocument();
    for (const auto& t : toolSections()) {
      if (t.key == "poincare") continue;
      if (edited.contains(t.key))
        doc[t.key] = edited[t.key];
      else
        doc.erase(t.key);
    }
    return doc;
  });

  connect(&timer_, &QTimer::timeout, this, &MainWindow::tick);
  timer_.start(16);
  // the layout of the last session (docks, toolbars, size)
  restoreGeometry(QSettings().value("windowGeometry").toByteArray());
  restoreState(QSettings().value("windowState").toByteArray());
  clock_.start();
}

MainWindow::~MainWindow() {
  timer_.stop();
  qDeleteAll(findChildren<ChartWindow*>()); // their jobs live in the map's job tree, which goes first
  qDeleteAll(findChildren<SweepWindow*>());
  delete recorder_; // a recording in progress is finished, a video being finished written whole
  recorder_ = nullptr;
  map_->stopAll();
  stream_.reset();
  if (visual_) view_->renderWindow()->RemoveRenderer(visual_->renderer());
  apex_.reset();
}

void MainWindow::editObject(const std::string& name, const ObjectOptions& o) {
  edits_.setObject(name, o);
  if (visual_) visual_->setOptions(name, o);
  apex_->setOptions(name, o);
  showViewSettings();
  view_->update();
}

void MainWindow::editAxes(const AxesOptions& a) {
  edits_.setAxes(a);
  if (visual_) visual_->setAxes(a);
  showViewSettings();
  view_->update();
}

void MainWindow::showViewSettings() {
  if (!visual_) return;
  const ViewOptions& v = visual_->options(); // what is drawn: the scene's view with the edits laid over it
  std::vector<std::string> names;
  std::optional<SurfaceStyle> style;
  for (const auto& o : visual_->objects()) {
    names.push_back(o->name());
    if (!style && (o->name() == "ball" || o->name() == "body")) style = v.object(o->name()).style;
  }
  if (!style && !names.empty()) style = v.object(names.front()).style;
  const QSignalBlocker quietStyle(styleBox_), quietAxes(axesBox_); // showing is not editing
  styleBox_->setCurrentIndex(style == SurfaceStyle::Grid ? 1 : style == SurfaceStyle::Both ? 2 : 0);
  axesBox_->setCurrentIndex(static_cast<int>(v.axes.style));
  const QSignalBlocker quietFollow(followAction_);
  followAction_->setChecked(v.camera.follow);
  followAction_->setEnabled(scene_ && scene_->model->geometry()); // a body to follow
  settings_->setObjects(names, v);
}

void MainWindow::setStyleOfAll(SurfaceStyle style) {
  if (!visual_) return;
  for (const auto& o : visual_->objects()) {
    ObjectOptions opt = visual_->options().object(o->name());
    if (!visual_->options().objects.count(o->name())) opt.enabled = o->shownByDefault();
    opt.style = style;
    editObject(o->name(), opt);
  }
}

bool MainWindow::openScene(const QString& path) {
  std::unique_ptr<Scene> scene;
  try {
    if (readSessionIfAny(path.toStdString())) return openSession(path); // a saved session opens whole
    scene = std::make_unique<Scene>(loadScene(path.toStdString()));
  } catch (const std::exception& e) {
    QMessageBox::warning(this, "rollviz", QString("Cannot open the scene:\n%1").arg(e.what()));
    return false;
  }
  QSettings().setValue("lastScene", QFileInfo(path).absoluteFilePath());
  rememberRecent(QFileInfo(path).absoluteFilePath());
  edits_.clear(); // another file: its own appearance
  if (const auto r = scene->document.find("results"); r != scene->document.end()) // kept when it was saved
    for (const auto& line : *r)
      results_->appendPlainText(QString::fromStdString(line.get<std::string>()));
  useScene(std::move(scene), path);
  return true;
}

bool MainWindow::openModel(const QString& path) {
  const QString file = QFileInfo(path).absoluteFilePath();
  std::unique_ptr<Scene> scene;
  try {
    scene = std::make_unique<Scene>(sceneFromJson({{"problem", file.toStdString()}}, file.toStdString()));
  } catch (const std::exception& e) {
    QMessageBox::warning(this, "rollviz", QString("Cannot open the model:\n%1").arg(e.what()));
    return false;
  }
  edits_.clear();
  useScene(std::move(scene), file);
  return true;
}

void MainWindow::reloadModel() {
  if (!scene_) return;
  const QString file = QString::fromStdString(modelFileOf(*scene_->modelEntry));
  if (file.isEmpty()) return;
  const std::size_t jobs = map_->addedJobs().size();
  std::unique_ptr<Scene> scene;
  try {
    scene = std::make_unique<Scene>(sceneFromJson(scene_->document, scene_->source));
  } catch (const std::exception& e) { // kept running on the old model: the file is being edited
    report(QString("%1 changed but cannot be read; the model running is the one before:\n%2")
               .arg(QFileInfo(file).fileName(), e.what()),
           8000);
    return;
  }
  useScene(std::move(scene), scenePath_);
  report(QString("%1 changed: the model was reloaded%2")
             .arg(QFileInfo(file).fileName(),
                  jobs ? QString("; the %1 job(s) of the old model were stopped").arg(jobs) : QString()),
         8000);
}

bool MainWindow::chooseProblem(const std::string& id) {
  if (!mayReplaceMap(QString("Opening the default scene of %1").arg(QString::fromStdString(id)))) {
    if (auto* chooser = control_->findChild<QComboBox*>("problem_choice")) // shows the problem that stays
      chooser->setCurrentText(QString::fromStdString(scene_->model->info().id));
    return false;
  }
  if (!ModelRegistry::global().find(id)) // a model file's model: the newest file of that id
    for (const ModelEntry* e : loadedModelFiles())
      if (e->info->id == id && !modelFileOf(*e).empty())
        return openModel(QString::fromStdString(modelFileOf(*e)));
  return openScene(QString::fromStdString(defaultScenePath(id)));
}

std::unique_ptr<Scene> MainWindow::sceneOf(const nlohmann::json& document) {
  try {
    return std::make_unique<Scene>(sceneFromJson(document, scene_ ? scene_->source : "edited scene"));
  } catch (const std::exception& e) {
    // named as the control panel shows them (its tab and field), not by the scene file's JSON path
    QMessageBox::warning(this, "rollviz",
                         "Cannot run these values:\n" +
                             ControlPanel::inPanelWords(e.what(), scene_ ? scene_->source : "edited scene"));
    return nullptr;
  }
}

bool MainWindow::runDocument(const nlohmann::json& document, const QString& origin) {
  auto scene = sceneOf(document);
  if (!scene) return false;
  useScene(std::move(scene), scenePath_, origin);
  return true;
}

bool MainWindow::applyDocument(const nlohmann::json& document) {
  auto scene = sceneOf(document);
  if (!scene) return false;
  if (scene_ && sameMap(*scene_, *scene)) {
    useScene(std::move(scene), scenePath_, origin_, MapUse::Keep);
    return true;
  }
  if (!mayReplaceMap("Apply")) return false;
  useScene(std::move(scene), scenePath_, origin_);
  return true;
}

void MainWindow::useScene(std::unique_ptr<Scene> scene, const QString& path, const QString& origin,
                          MapUse mapUse) {
  const bool keep = mapUse == MapUse::Keep && scene_;
  // a new initial state on a kept map: its trajectory joins the others
  const bool newStart = keep && (scene_->initialState.size() != scene->initialState.size() ||
                                 scene_->initialState != scene->initialState);
  if (mapUse == MapUse::Replace && scene_) rememberMapForUndo();
  // the camera the user placed stays where it is unless the view's settings change (the camera moves only
  // when the user asks: an Apply with nothing changed used to put it back)
  vtkNew<vtkCamera> userCamera;
  const bool keepCamera =
      keep && visual_ && visual_->cameraMoved() && scene_->model->info().id == scene->model->info().id &&
      scene_->document.value("view", nlohmann::json()) == scene->document.value("view", nlohmann::json());
  if (keepCamera) userCamera->DeepCopy(visual_->renderer()->GetActiveCamera());
  stream_.reset();
  if (!keep) map_->stopAll(); // its jobs hold the old scene's model until setScene replaces them
  if (visual_) view_->renderWindow()->RemoveRenderer(visual_->renderer());
  visual_.reset();
  apex_->dropScene();
  if (!keep)
    for (PlotWindow* p : map_->plotWindows()) // they read the old model's observables
      delete p;
  scene_ = std::move(scene);
  scenePath_ = path;
  origin_ = origin;
  const QString run = QString::fromStdString(scene_->runSpec().describe()); // "rk4(step=0.001) problem(...)"
  method_ = scene_->model->isMap() ? QString("iterated map")
                                   : run.left(run.indexOf(')') + 1); // the method and its settings
  speedBox_->setValue(scene_->view.speed);
  // named by where it came from: its file, or (a sweep's cell) the sweep's point
  setWindowTitle(
      QString("rollviz — %1 (%2)").arg(sceneName(), QString::fromStdString(scene_->model->info().id)));
  if (keep) {
    map_->keepScene(*scene_);
    if (newStart) map_->startSceneTrajectory();
  } else {
    map_->setScene(*scene_, mapUse != MapUse::Restore);
  }
  control_->setScene(*scene_);
  watchModelFile();
  restart();
  if (keepCamera) {
    visual_->renderer()->GetActiveCamera()->DeepCopy(userCamera);
    visual_->renderer()->ResetCameraClippingRange();
    view_->update();
  }
  if (apex_->visible()) openApexWindow();
}

void MainWindow::watchModelFile() {
  if (!modelWatcher_) {
    modelWatcher_ = new QFileSystemWatcher(this);
    modelReload_.setSingleShot(true);
    modelReload_.setInterval(300); // an editor's save is often several writes
    connect(&modelReload_, &QTimer::timeout, this, &MainWindow::reloadModel);
    connect(modelWatcher_, &QFileSystemWatcher::fileChanged, this, [this](const QString& path) {
      if (!modelWatcher_->files().contains(path)) modelWatcher_->addPath(path); // replaced, not rewritten
      modelReload_.start();
    });
  }
  if (!modelWatcher_->files().isEmpty()) modelWatcher_->removePaths(modelWatcher_->files());
  const std::string file = modelFileOf(*scene_->modelEntry);
  if (!file.empty()) modelWatcher_->addPath(QString::fromStdString(file));
}

void MainWindow::restart() {
  if (!scene_) return;
  stream_.reset(); // joins the worker before anything it uses changes
  if (!visual_) {
    visual_ = std::make_unique<VisualScene>(*scene_->model, edits_.over(scene_->view), scene_->initialState);
    visual_->addTo(view_->renderWindow());
    showViewSettings();
  } else {
    visual_->clear();
    visual_->show(0.0, scene_->initialState);
    visual_->resetCamera();
  }
  apex_->restart(*scene_);
  for (PlotWindow* p : map_->plotWindows())
    p->clear();
  error_.clear();
  requested_ = shownTime_ = 0;
  lastStepEnd_.reset(), lastStep_ = 0;
  stream_ = std::make_unique<TrajectoryStream>(scene_->startIntegrator());
  clock_.restart();
  showStatus();
  view_->update();
}

void MainWindow::stepFrame() {
  if (playing_) togglePlay();
  requested_ = std::max(requested_, shownTime_) + speedBox_->value() / 25.0; // one video frame of simulation
}

void MainWindow::togglePlay() {
  playing_ = !playing_;
  if (!playing_) requested_ = shownTime_; // pause where the picture is
  playAction_->setText(playing_ ? "Pause" : "Play");
  clock_.restart();
  showStatus();
}

void MainWindow::tick() {
  const double wall = clock_.restart() / 1000.0;
  // the map's frame and the 3D view's in different turns of the event loop while the map fills: on software
  // GL each costs tens of milliseconds, and both in one turn would keep the window from answering for their
  // sum
  const bool mapFrame = !mapWaits_ && map_->drain();
  mapWaits_ = mapFrame;
  if (scene_) apex_->feedFromMap(*scene_);
  if (!stream_) return;
  if (playing_ && error_.isEmpty()) {
    // never run further ahead of what is shown than a fraction of a second of work
    if (requested_ - shownTime_ < 0.5 * speedBox_->value()) requested_ += wall * speedBox_->value();
  }
  if (error_.isEmpty()) stream_->requestUntil(requested_); // paused, a single step still goes
  if (!stream_->take(batch_)) return;
  const std::vector<PlotWindow*> plots = map_->plotWindows(); // drawn by the map's drain
  for (std::size_t i = 0; i < batch_.states.size(); ++i) {
    if (lastStepEnd_ && batch_.times[i] != *lastStepEnd_)
      lastStep_ = std::abs(batch_.times[i] - *lastStepEnd_);
    lastStepEnd_ = batch_.times[i];
    visual_->advance(batch_.times[i], batch_.states[i]);
    apex_->advance(batch_.times[i], batch_.states[i]);
    for (PlotWindow* p : plots)
      p->offer(batch_.times[i], batch_.states[i].data());
  }
  if (batch_.reached) {
    visual_->show(batch_.atTime, batch_.at);
    apex_->show(batch_.atTime, batch_.at);
    shownTime_ = batch_.atTime;
    apex_->update();
  }
  if (!batch_.error.empty()) {
    error_ = QString::fromStdString(batch_.error);
    playing_ = false;
    playAction_->setText("Play");
  }
  showStatus();
  if (!mapFrame) view_->update(); // else on the next tick
}

QString MainWindow::sceneName() const {
  return origin_.isEmpty() ? QFileInfo(scenePath_).fileName() : origin_;
}

QString MainWindow::statusText() const {
  return status_->text();
}

void MainWindow::showStatus() {
  QString s = QString("%1   t = %2   %3")
                  .arg(sceneName())
                  .arg(shownTime_, 0, 'f', 3)
                  .arg(playing_ ? "playing" : "paused");
  if (visual_ && visual_->energyError()) s += QString("   dE/E = %1").arg(*visual_->energyError(), 0, 'e', 2);
  if (!method_.isEmpty()) s += "   " + method_;
  if (lastStep_ > 0 && scene_ && !scene_->model->isMap())
    s += QString("   h = %1").arg(lastStep_, 0, 'g', 4); // the step taken (adaptive methods)
  if (!error_.isEmpty()) s += "   stopped: " + error_;
  status_->setText(s);
}

bool MainWindow::snapshotTo(const QString& path) {
  if (!savePicture(view_, path)) return false; // at File > Picture size
  report("snapshot written: " + path);
  return true;
}

bool MainWindow::recording() const {
  return recorder_ && recorder_->recording();
}

bool MainWindow::startRecording(const QString& path, int fps) {
  if (recorder_->recording()) return false;
  const qreal dpr = view_->devicePixelRatioF();
  const QSize shown(static_cast<int>(std::lround(view_->width() * dpr)),
                    static_cast<int>(std::lround(view_->height() * dpr)));
  const QSize size = PictureSize::current().of(shown); // File > Picture size: each frame rendered at it
  // the scene's video section: its frame rate unless one is given, its quality and preset
  const VideoSpec settings = scene_ ? videoSpec(scene_->tool("video"), 1) : VideoSpec{};
  const QString why = recorder_->start(path, fps > 0 ? fps : settings.fps, settings.encoder, size, shown);
  if (!why.isEmpty()) {
    report("Cannot record: " + why, 8000);
    return false;
  }
  recordAction_->setText("Stop recording");
  report(QString("recording %1 at %2x%3 (press Stop recording to end)")
             .arg(path)
             .arg(size.width())
             .arg(size.height()));
  return true;
}

void MainWindow::stopRecording() {
  if (!recorder_->recording()) return;
  recorder_->stop();
  recordAction_->setText("Record…");
  recordAction_->setEnabled(false); // until the file is written
}

void MainWindow::recordingWritten(bool ok, const QString& path, const QString& why, double seconds,
                                  long frames) {
  recordAction_->setEnabled(true);
  if (ok)
    report(QString("wrote %1 (%2 s, %3 frames)").arg(path).arg(seconds, 0, 'f', 1).arg(frames), 8000);
  else
    report("recording failed: " + why, 8000);
  emit recordingFinished(ok, path);
}

nlohmann::json MainWindow::documentWithEdits() const {
  nlohmann::json doc = scene_->document;
  edits_.writeInto(doc); // the settings panel's edits go into the document
  // the Results dock goes with the scene: what was found is there when the scene is opened again
  doc.erase("results");
  for (const QString& line : results().split('\n', Qt::SkipEmptyParts))
    doc["results"].push_back(line.toStdString());
  return doc;
}

void MainWindow::createTool(const std::string& id) {
  if (!scene_) return;
  // where the tool's runner says it shows: a chart window (a job of the tool manager), or the map window,
  // which draws its rows as they come, its own trajectory or search, or the plot filter's live window
  const ToolRunner* runner = findToolRunner(id);
  switch (runner ? runner->window : ToolWindow::Chart) {
  case ToolWindow::Chart:
    openChart(ToolRegistry::global().get(id).chartView);
    return;
  case ToolWindow::MapRows:
    map_->startRows(id);
    return;
  case ToolWindow::MapTrajectory:
    map_->trajectories().start(scene_->initialState);
    return;
  case ToolWindow::MapSearch:
    map_->searchFromGuess();
    return;
  case ToolWindow::PlotWindow:
    openPlotWindow(scene_->plot);
    return;
  }
}

ChartWindow* MainWindow::openChart(const std::string& view, const std::string& diagram) {
  if (!scene_) return nullptr;
  // with the control panel's values as they stand (Apply not needed for a chart)
  return openChartOf(control_->editedDocument(), view, diagram);
}

ChartWindow* MainWindow::openChartOf(const nlohmann::json& document, const std::string& view,
                                     const std::string& diagram) {
  if (!scene_) return nullptr;
  ChartWindow* w = nullptr;
  try { // the document is the control panel's edit, applied or not: it may not make a scene (found by the
        // monkey)
    w = new ChartWindow(map_->jobs(), document, scene_->source, view, this, diagram);
  } catch (const std::exception& e) {
    report(QString("Cannot open the chart: %1").arg(e.what()), 15000);
    return nullptr;
  }
  w->setAttribute(Qt::WA_DeleteOnClose);
  // every outcome in the Results dock: the numbers a finished chart shows (its failures: the tool manager)
  connect(w, &ChartWindow::finished, this, [this, w, view] {
    if (!w->ready() || !w->failure().isEmpty()) return;
    // with its job's number, as the tool manager lists it
    if (const QString numbers = numbersOf(*w->drawn()); !numbers.isEmpty())
      report(QString("%1 (tool #%2): %3")
                 .arg(QString::fromStdString(chartTitle(view)))
                 .arg(w->jobId())
                 .arg(numbers),
             8000);
  });
  placeWindow(w);
  w->show();
  if (view == "bifurcation") map_->addDiagramWindow(w); // the map's trajectories are points on it
  return w;
}

SweepWindow* MainWindow::openSweep(const QString& path) {
  try {
    auto* w = new SweepWindow(map_->jobs(), loadSweep(path.toStdString()), this);
    w->setAttribute(Qt::WA_DeleteOnClose);
    const QString origin = "a point of " + QFileInfo(path).fileName();
    w->setSceneOpener([this, origin](const nlohmann::json& doc) {
      return mayReplaceMap("Opening a point of the sweep") && runDocument(doc, origin);
    });
    placeWindow(w);
    w->show();
    return w;
  } catch (const std::exception& e) {
    QMessageBox::warning(this, "rollviz", QString("Cannot open the sweep:\n%1").arg(e.what()));
    return nullptr;
  }
}

void MainWindow::placeWindow(QWidget* w) const {
  // over the 3D view, below the menu and the toolbars (a window put at the main window's corner hid them),
  // cascaded so that windows do not open on one spot
  int open = 0;
  for (const QWidget* other : QApplication::topLevelWidgets())
    open += other != w && other != this && other->isVisible() && other->parentWidget() == this;
  w->move(view_->mapToGlobal(QPoint(24 + 32 * (open % 10), 24 + 32 * (open % 10))));
}

PlotWindow* MainWindow::openPlotWindow(const PlotView& plot) {
  if (!scene_) return nullptr;
  try {
    auto* w = new PlotWindow(*scene_->model, plot, this);
    w->setAttribute(Qt::WA_DeleteOnClose);
    placeWindow(w);
    w->show();
    map_->addPlotWindow(w);
    return w;
  } catch (const std::exception& e) {
    report(QString("Cannot plot: %1").arg(e.what()), 8000);
    return nullptr;
  }
}

MultipliersWindow* MainWindow::openMultipliersWindow() {
  auto* w = new MultipliersWindow(this);
  w->setAttribute(Qt::WA_DeleteOnClose);
  placeWindow(w);
  w->show();
  map_->addMultipliersWindow(w);
  return w;
}

QWidget* MainWindow::openApexWindow() {
  if (!scene_) return nullptr;
  return apex_->open(*scene_, edits_.over(scene_->view));
}

void MainWindow::closeEvent(QCloseEvent* e) {
  saveRunningJobs();
  QSettings().setValue("windowState", saveState());
  QSettings().setValue("windowGeometry", saveGeometry());
  QMainWindow::closeEvent(e);
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
  if (e->mimeData()->hasUrls()) e->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* e) {
  for (const QUrl& url : e->mimeData()->urls())
    if (url.isLocalFile() && url.toLocalFile().endsWith(".json")) {
      if (mayReplaceMap("Opening " + url.fileName())) openScene(url.toLocalFile());
      break;
    }
}

} // namespace rv
