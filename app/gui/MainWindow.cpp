#include "app/gui/MainWindow.h"

#include "app/gui/ControlPanel.h"
#include "app/gui/MapPanel.h"
#include "app/gui/QtVtkWidget.h"
#include "app/gui/ToolManager.h"
#include "dynamics/core/Errors.h"
#include "scenes/SceneLoader.h"

#include <QAction>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QToolBar>
#include <vtkRenderer.h>

namespace rv {

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
  auto* toolsDock = new QDockWidget("Tool manager", this);
  toolsDock->setObjectName("tools");
  toolsDock->setWidget(tools_);
  addDockWidget(Qt::BottomDockWidgetArea, toolsDock);
  resizeDocks({toolsDock}, {150}, Qt::Vertical); // the 3D view keeps most of the height
  connect(control_, &ControlPanel::apply, this, [this](const nlohmann::json& doc) { runDocument(doc); });
  resize(1400, 800);

  auto* bar = addToolBar("Playback");
  bar->setObjectName("playback");
  auto* open = bar->addAction("Open…", this, &MainWindow::openDialog);
  open->setShortcut(QKeySequence::Open);
  playAction_ = bar->addAction("Pause", this, &MainWindow::togglePlay);
  playAction_->setShortcut(Qt::Key_Space);
  playAction_->setToolTip("Play / pause (Space)");
  auto* reset = bar->addAction("Reset", this, &MainWindow::restart);
  reset->setShortcut(Qt::Key_R);
  reset->setToolTip("Start the motion again from the scene's initial state (R)");
  bar->addSeparator();
  bar->addWidget(new QLabel(" Speed ×", this));
  speedBox_ = new QDoubleSpinBox(this);
  speedBox_->setRange(0.01, 1000);
  speedBox_->setDecimals(2);
  speedBox_->setValue(1.0);
  speedBox_->setToolTip("simulation seconds per second of wall-clock time (real-time factor)");
  bar->addWidget(speedBox_);
  bar->addSeparator();
  auto* snap = bar->addAction("Snapshot", this, &MainWindow::snapshot);
  snap->setShortcut(QKeySequence::Save);
  snap->setToolTip("Save the 3D view as a PNG (Ctrl+S)");
  auto* tools = menuBar()->addMenu("&Tools");
  auto* separatrices =
      tools->addAction("Separatrices of the fixed point", map_, &MapPanel::startSeparatrices);
  separatrices->setToolTip(
      "the four branches at the fixed point found from fixedpoint.guess (control panel)");
  separatrices->setShortcut(QKeySequence("Ctrl+Shift+E"));
  auto* continuation = tools->addAction("Continue the fixed point", map_, &MapPanel::startContinuation);
  continuation->setToolTip("the family in continuation.parameter up to continuation.to (control panel)");
  continuation->setShortcut(QKeySequence("Ctrl+Shift+C"));
  status_ = new QLabel(this);
  statusBar()->addWidget(status_, 1);
  connect(map_, &MapPanel::message, this, [this](const QString& m) { statusBar()->showMessage(m, 5000); });

  connect(&timer_, &QTimer::timeout, this, &MainWindow::tick);
  timer_.start(16);
  clock_.start();
}

MainWindow::~MainWindow() {
  timer_.stop();
  map_->stopAll();
  stream_.reset();
  if (visual_) view_->renderWindow()->RemoveRenderer(visual_->renderer());
}

bool MainWindow::openScene(const QString& path) {
  std::unique_ptr<Scene> scene;
  try {
    scene = std::make_unique<Scene>(loadScene(path.toStdString()));
  } catch (const std::exception& e) {
    QMessageBox::warning(this, "rollviz", QString("Cannot open the scene:\n%1").arg(e.what()));
    return false;
  }
  QSettings().setValue("lastScene", QFileInfo(path).absoluteFilePath());
  useScene(std::move(scene), path);
  return true;
}

bool MainWindow::runDocument(const nlohmann::json& document) {
  std::unique_ptr<Scene> scene;
  try {
    scene = std::make_unique<Scene>(sceneFromJson(document, scene_ ? scene_->source : "edited scene"));
  } catch (const std::exception& e) {
    QMessageBox::warning(this, "rollviz", QString("Cannot run these values:\n%1").arg(e.what()));
    return false;
  }
  useScene(std::move(scene), scenePath_);
  return true;
}

void MainWindow::useScene(std::unique_ptr<Scene> scene, const QString& path) {
  stream_.reset();
  map_->stopAll(); // its jobs hold the old scene's model until setScene replaces them
  if (visual_) view_->renderWindow()->RemoveRenderer(visual_->renderer());
  visual_.reset();
  scene_ = std::move(scene);
  scenePath_ = path;
  speedBox_->setValue(scene_->view.speed);
  setWindowTitle(QString("rollviz — %1 (%2)")
                     .arg(QFileInfo(path).fileName(), QString::fromStdString(scene_->model->info().id)));
  map_->setScene(*scene_);
  control_->setScene(*scene_);
  restart();
}

void MainWindow::restart() {
  if (!scene_) return;
  stream_.reset(); // joins the worker before anything it uses changes
  if (!visual_) {
    visual_ = std::make_unique<VisualScene>(*scene_->model, scene_->view, scene_->initialState);
    visual_->addTo(view_->renderWindow());
  } else {
    visual_->clear();
    visual_->show(0.0, scene_->initialState);
    visual_->resetCamera();
  }
  error_.clear();
  requested_ = shownTime_ = 0;
  stream_ = std::make_unique<TrajectoryStream>(scene_->startIntegrator());
  clock_.restart();
  showStatus();
  view_->update();
}

void MainWindow::togglePlay() {
  playing_ = !playing_;
  playAction_->setText(playing_ ? "Pause" : "Play");
  clock_.restart();
  showStatus();
}

void MainWindow::tick() {
  const double wall = clock_.restart() / 1000.0;
  map_->drain();
  if (!stream_) return;
  if (playing_ && error_.isEmpty()) {
    // never run further ahead of what is shown than a fraction of a second of work
    if (requested_ - shownTime_ < 0.5 * speedBox_->value()) requested_ += wall * speedBox_->value();
    stream_->requestUntil(requested_);
  }
  if (!stream_->take(batch_)) return;
  for (std::size_t i = 0; i < batch_.states.size(); ++i)
    visual_->advance(batch_.times[i], batch_.states[i]);
  if (batch_.reached) {
    visual_->show(batch_.atTime, batch_.at);
    shownTime_ = batch_.atTime;
  }
  if (!batch_.error.empty()) {
    error_ = QString::fromStdString(batch_.error);
    playing_ = false;
    playAction_->setText("Play");
  }
  showStatus();
  view_->update();
}

void MainWindow::showStatus() {
  QString s = QString("%1   t = %2   %3")
                  .arg(QFileInfo(scenePath_).fileName())
                  .arg(shownTime_, 0, 'f', 3)
                  .arg(playing_ ? "playing" : "paused");
  if (!error_.isEmpty()) s += "   stopped: " + error_;
  status_->setText(s);
}

void MainWindow::snapshot() {
  const QString path = QFileDialog::getSaveFileName(this, "Save snapshot", "snapshot.png", "PNG (*.png)");
  if (path.isEmpty()) return;
  if (!view_->grabFramebuffer().save(path, "PNG"))
    QMessageBox::warning(this, "rollviz", "Cannot write " + path);
}

void MainWindow::openDialog() {
  const QString path = QFileDialog::getOpenFileName(
      this, "Open scene", QString::fromStdString(scenesDirectory()), "Scenes (*.json)");
  if (!path.isEmpty()) openScene(path);
}

} // namespace rv
