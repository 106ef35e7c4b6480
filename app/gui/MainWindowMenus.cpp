// MainWindowMenus.cpp -- the main window's toolbars and menus (File, Edit, Windows, Tools, Help) and the
// dialogs they open: where a user's action enters the window. What the actions do lives in MainWindow.cpp
// (the scene and its run), MainWindowSession.cpp (what is kept) and the panels.
#include "app/gui/MainWindow.h"

#include "app/gui/AboutDialog.h"
#include "app/gui/ChartWindow.h"
#include "app/gui/FilterWindow.h"
#include "app/gui/GalleryDialog.h"
#include "app/gui/MapPanel.h"
#include "app/gui/PlotFilterDialog.h"
#include "app/gui/QtVtkWidget.h"
#include "app/gui/RollingBodyDialog.h"
#include "scenes/SceneCharts.h"
#include "scenes/SceneLoader.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QDesktopServices>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QToolBar>
#include <QUrl>
#include <algorithm>

namespace rv {

void MainWindow::buildToolBars(QDockWidget* settingsDock) {
  auto* bar = addToolBar("Playback");
  bar->setObjectName("playback");
  bar->addAction("Open…", this, &MainWindow::openDialog)->setToolTip("Open a scene or a session (Ctrl+O)");
  playAction_ = bar->addAction("Pause", this, &MainWindow::togglePlay);
  playAction_->setShortcut(Qt::Key_Space);
  playAction_->setToolTip("Play / pause (Space)");
  auto* step = bar->addAction("Step", this, &MainWindow::stepFrame);
  step->setShortcut(Qt::Key_Period);
  step->setToolTip("Pause and go one frame (1/25 s of the real-time factor) further (.)");
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
  recordAction_ = bar->addAction("Record…", this, [this] { recording() ? stopRecording() : recordDialog(); });
  recordAction_->setToolTip(
      "Record what the 3D view shows into an MP4 until pressed again, the video as long "
      "as the recording (Ctrl+Shift+R); `rollviz video` renders exact frames offline");
  recordAction_->setShortcut(QKeySequence("Ctrl+Shift+R"));
  auto* view = addToolBar("Visualizer");
  view->setObjectName("visualizer");
  view->addAction("Reset camera", this,
                  [this] {
                    if (visual_) visual_->resetCamera();
                    view_->update();
                  })
      ->setToolTip("Put the camera back to the scene's placement");
  followAction_ = view->addAction("Follow body");
  followAction_->setObjectName("follow");
  followAction_->setCheckable(true);
  followAction_->setToolTip("Carry the camera along with the body as it rolls (else it stays where you put "
                            "it); either way you turn, move and zoom it");
  connect(followAction_, &QAction::toggled, this, [this](bool on) {
    edits_.setFollow(on);
    if (visual_) visual_->setFollow(on);
  });
  auto* style = styleBox_ = new QComboBox(this);
  style->setObjectName("surface_style");
  style->addItems({"fill", "grid", "both"});
  style->setToolTip("how surfaces are drawn: filled, as a grid, or both");
  connect(style, &QComboBox::currentIndexChanged, this, [this](int i) {
    setStyleOfAll(i == 1 ? SurfaceStyle::Grid : i == 2 ? SurfaceStyle::Both : SurfaceStyle::Fill);
  });
  view->addWidget(style);
  auto* axes = axesBox_ = new QComboBox(this);
  axes->setObjectName("axes_style");
  axes->addItems({"no axes", "normal axes", "box axes"});
  axes->setToolTip("the scene's coordinate axes (ticks and range: settings, tab axis)");
  connect(axes, &QComboBox::currentIndexChanged, this, [this](int i) {
    AxesOptions a =
        visual_ ? visual_->options().axes : edits_.axes().value_or(AxesOptions{}); // the rest as shown
    a.style = static_cast<AxesOptions::Style>(i);
    editAxes(a);
  });
  view->addWidget(axes);
  auto* toggle = settingsDock->toggleViewAction();
  toggle->setText("Settings");
  toggle->setToolTip("Show or hide the visualizer's settings (objects, axis)");
  view->addAction(toggle);
}

void MainWindow::buildMenus() {
  auto* file = menuBar()->addMenu("&File");
  auto* open = file->addAction("Open scene…", this, &MainWindow::openDialog);
  open->setToolTip("a scene file, or a session saved with Save session");
  open->setShortcut(QKeySequence("Ctrl+O")); // spelled out: some platforms map the standard keys to none
  file->addAction("Gallery…", this,
                  [this] {
                    GalleryDialog gallery(this, [this](const QString& path) {
                      if (mayReplaceMap("Opening " + QFileInfo(path).fileName())) openScene(path);
                    });
                    gallery.exec();
                  })
      ->setToolTip("famous motions, ready to watch: the rattleback turning back, chaos in Henon-Heiles, ...");
  file->addAction("Open model…", this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, "Open a model file (docs/models.md)", QString(),
                                                      "Model files (*.json)");
    if (!path.isEmpty() && mayReplaceMap("Opening " + QFileInfo(path).fileName())) openModel(path);
  });
  file->addAction("New rolling body…", this,
                  [this] {
                    RollingBodyDialog dialog(this, [this](const QString& path) {
                      if (mayReplaceMap("Opening " + QFileInfo(path).fileName())) openModel(path);
                    });
                    dialog.exec();
                  })
      ->setToolTip("a body described by its shape, masses and contact; rollviz derives its equations");
  file->addAction("Save scene as…", this, &MainWindow::saveDialog)->setShortcut(QKeySequence("Ctrl+Shift+S"));
  file->addSeparator();
  file->addAction("Save session…", this, &MainWindow::saveSessionDialog)
      ->setToolTip("the scene, every trajectory of the map (to go on from where it stands), the Results log "
                   "and the layout, in one file");
  file->addAction("Open session…", this, &MainWindow::openSessionDialog);
  file->addSeparator();
  file->addAction("Open sweep…", this,
                  [this] {
                    const QString path = QFileDialog::getOpenFileName(
                        this, "Open a sweep (a chart of regimes)",
                        QString::fromStdString(scenesDirectory() + "/sweeps"), "Sweep files (*.json)");
                    if (!path.isEmpty()) openSweep(path);
                  })
      ->setToolTip("a tool's number over a grid of parameters or initial points; click a cell to open it");
  file->addAction("Snapshot…\tCtrl+S", this, &MainWindow::snapshot) // the key is the toolbar action's
      ->setToolTip("the 3D view as a PNG (Ctrl+S; also on the toolbar)");
  file->addAction("Export web page…", this, &MainWindow::exportPageDialog)
      ->setToolTip(
          "the motion (and the map) as one self-contained web page: it plays, turns and scrubs in any "
          "browser, offline (rollviz page)");
  file->addAction("Export map…", this,
                  [this] {
                    if (scene_)
                      exportChartDialog(this, map_->view(), map_->chart(), "map",
                                        [this](const QString& m) { report(m, 8000); });
                  })
      ->setToolTip("the Poincaré map window as a figure (PNG, or SVG/PDF vectors) or its points as CSV");
  // the size every saved picture of a view has (Snapshot, Record, Export map, a chart's Save PNG): one
  // setting
  auto* sizes = file->addMenu("Picture size");
  sizes->setObjectName("picture_size");
  sizes->setToolTipsVisible(true);
  auto* sizeGroup = new QActionGroup(sizes);
  const auto addSize = [&](const QString& label, const QString& text) {
    auto* a = sizes->addAction(label, this, [text] { PictureSize::setCurrent(text); });
    a->setCheckable(true);
    a->setData(text);
    a->setActionGroup(sizeGroup);
  };
  addSize("As shown", "view");
  addSize("2 × the view", "x2");
  addSize("4 × the view", "x4");
  addSize("1920 × 1080", "1920x1080");
  addSize("3840 × 2160", "3840x2160");
  sizes->addAction("Other size…", this, [this] {
    bool ok = false;
    const QString text = QInputDialog::getText(this, "Picture size", "WIDTHxHEIGHT in pixels (16 to 16384)",
                                               QLineEdit::Normal, PictureSize::current().text, &ok);
    if (!ok) return;
    if (!PictureSize::valid(text.trimmed()))
      report("Picture size: give WIDTHxHEIGHT, e.g. 2400x1600 (16 to 16384 pixels a side), not " + text,
             8000);
    else
      PictureSize::setCurrent(text.trimmed());
  });
  connect(sizes, &QMenu::aboutToShow, this, [sizes] { // the setting ticked, whatever set it
    const QString now = PictureSize::current().text;
    for (QAction* a : sizes->actions())
      if (a->isCheckable()) a->setChecked(a->data().toString() == now);
  });
  sizes->menuAction()->setToolTip("the size of snapshots, recorded videos, exported maps and saved charts: "
                                  "rendered offscreen at that size, "
                                  "whatever the window's");
  recentMenu_ = file->addMenu("Recent scenes");
  fillRecentMenu();
  file->addSeparator();
  file->addAction("Quit", this, &QWidget::close)->setShortcut(QKeySequence::Quit);
  auto* edit = menuBar()->addMenu("&Edit");
  undoAction_ = edit->addAction("Undo", this, [this] {
    if (!undo()) report("nothing to undo", 3000);
  });
  undoAction_->setObjectName("undo");
  undoAction_->setShortcut(QKeySequence::Undo);
  undoAction_->setEnabled(false);
  redoAction_ = edit->addAction("Redo", this, [this] {
    if (!redo()) report("nothing to redo", 3000);
  });
  redoAction_->setObjectName("redo");
  redoAction_->setShortcut(QKeySequence::Redo);
  redoAction_->setEnabled(false);
  auto* windows = menuBar()->addMenu("&Windows");
  windows->addAction("2D plot…", this, [this] { plotDialog(2); })
      ->setToolTip("observables against each other along the 3D view's run and every trajectory of the map, "
                   "a point whenever the out condition has changed by the period (manual 2.4.1)");
  windows->addAction("3D plot…", this, [this] { plotDialog(3); })
      ->setToolTip(
          "three observables along the 3D view's run and every trajectory of the map (manual 2.4.2)");
  windows->addAction("Multipliers (live)", this, [this] { openMultipliersWindow(); })
      ->setToolTip("the multipliers of running continuations and bifurcation trees on the complex plane "
                   "(manual 2.4.3)");
  windows->addAction("Bifurcation diagram…", this, [this] { diagramDialog(); })
      ->setToolTip(
          "a bifurcation diagram of the problem on the plane of first integrals, with every trajectory "
          "of the map as a point (manual 2.4.4)");
  windows->addAction("Map3D (live)", map_, [this] { map_->openMap3D(); })
      ->setToolTip("a 3D map in three dimensions, beside its projection in the map window");
  windows->addAction("Apex motion", this, [this] { openApexWindow(); })
      ->setToolTip("the body's axes on the unit sphere as it turns (manual 2.4.5)");
  auto* charts = windows->addMenu("Charts");
  for (const auto& v : chartViews())
    charts->addAction(QString::fromStdString(chartTitle(v)), this, [this, v] { openChart(v); });
  auto* tools = menuBar()->addMenu("&Tools");
  auto* separatrices =
      tools->addAction("Separatrices of the fixed point", map_, &MapPanel::startSeparatrices);
  separatrices->setToolTip(
      "the four branches at the fixed point found from fixedpoint.guess (control panel)");
  separatrices->setShortcut(QKeySequence("Ctrl+Shift+E"));
  auto* continuation = tools->addAction("Continue the fixed point", map_, &MapPanel::startContinuation);
  continuation->setToolTip("the family in continuation.parameter up to continuation.to (control panel)");
  continuation->setShortcut(QKeySequence("Ctrl+Shift+C"));
  // branch switching: one entry per period doubling the last continuation located
  auto* doubled = tools->addMenu("Follow the doubled family");
  doubled->setToolTipsVisible(true);
  connect(doubled, &QMenu::aboutToShow, this, [this, doubled] {
    doubled->clear();
    const auto& doublings = map_->locatedDoublings();
    if (doublings.empty())
      doubled->addAction("no period doubling located yet: continue the fixed point first")->setEnabled(false);
    for (std::size_t k = 0; k < doublings.size(); ++k)
      doubled
          ->addAction("born at the " + doublings[k], map_,
                      [this, k] { map_->followDoubledFamily(static_cast<int>(k) + 1); })
          ->setToolTip("the family of fixed points of doubled order, continued to continuation.to");
  });
  auto* help = menuBar()->addMenu("&Help");
  help->addAction("About rollviz…", this, [this] { (new AboutDialog(view_, this))->show(); })
      ->setToolTip("the version, the libraries and the renderers (GPU or software) behind the pictures");
  help->addAction("Guide", this,
                  [this] {
                    const QString where = guideLocation();
                    if (!QDesktopServices::openUrl(QUrl::fromLocalFile(where)))
                      report("The guide is at " + where + " (no program here opens it)", 15000);
                  })
      ->setToolTip("the guide: getting started, tutorials, the tools and the command line (built by cmake "
                   "--build build/dev --target docs; else its pages in docs/)");
  help->addAction("Keyboard shortcuts…", this,
                  [this] { QMessageBox::information(this, "Keyboard shortcuts", shortcutsText()); })
      ->setShortcut(QKeySequence::HelpContents);
  // every dock can be shown again from the Windows menu (a closed one has no other handle)
  windows->addSeparator();
  for (QDockWidget* d : findChildren<QDockWidget*>())
    windows->addAction(d->toggleViewAction());
}

QString MainWindow::shortcutsText() const {
  QStringList lines;
  for (const QAction* a : findChildren<QAction*>())
    if (!a->shortcut().isEmpty())
      lines << a->shortcut().toString(QKeySequence::NativeText) + "\t" + QString(a->text()).remove('&');
  lines.sort();
  lines.removeDuplicates();
  return lines.join('\n');
}

QString MainWindow::guideLocation() {
  // the built guide where a build tree beside the sources has one, else its pages in docs/
  const QDir root = QFileInfo(QString::fromStdString(scenesDirectory())).dir();
  for (const char* built : {"build/dev/docs/html/index.html", "build/release/docs/html/index.html"})
    if (QFileInfo::exists(root.filePath(built))) return root.filePath(built);
  return root.filePath("docs");
}

QString MainWindow::askWhereToWrite(const QString& title, QStandardPaths::StandardLocation where,
                                    const QString& extension, const QString& filter) {
  // proposed in the user's pictures or videos folder (not the working directory, often the source tree),
  // named by the problem and the time shown
  const QString name =
      QString("%1-t%2.%3")
          .arg(scene_ ? QString::fromStdString(scene_->model->info().id) : QString("rollviz"))
          .arg(shownTime_, 0, 'f', 2)
          .arg(extension);
  QString path = QFileDialog::getSaveFileName(this, title, proposedPath(where, name), filter);
  // the file's format is the one its extension names: none gets ours, another is refused
  const QString suffix = QFileInfo(path).suffix();
  if (path.isEmpty() || suffix.compare(extension, Qt::CaseInsensitive) == 0) return path;
  if (suffix.isEmpty()) return path + "." + extension;
  QMessageBox::warning(this, "rollviz",
                       QString("%1: unsupported format '.%2' (the extension names it; supported: .%3)")
                           .arg(path, suffix, extension));
  return {};
}

void MainWindow::snapshot() {
  // the view held still while the dialog is open: the picture is the instant its proposed name says
  const bool wasPlaying = playing_;
  if (wasPlaying) togglePlay();
  const QString path =
      askWhereToWrite("Save snapshot", QStandardPaths::PicturesLocation, "png", "PNG (*.png)");
  if (!path.isEmpty() && !snapshotTo(path)) QMessageBox::warning(this, "rollviz", "Cannot write " + path);
  if (wasPlaying && !playing_) togglePlay();
}

void MainWindow::recordDialog() {
  const QString path =
      askWhereToWrite("Record video", QStandardPaths::MoviesLocation, "mp4", "MP4 video (*.mp4)");
  if (!path.isEmpty()) startRecording(path);
}

void MainWindow::diagramDialog() {
  if (!scene_) return;
  const auto diagrams = scene_->model->diagrams();
  if (diagrams.empty()) {
    report(QString::fromStdString(scene_->model->info().id + " has no bifurcation diagrams"), 8000);
    return;
  }
  QStringList items;
  for (const auto& d : diagrams)
    items << QString::fromStdString(d.id + ": " + d.title);
  bool ok = true;
  const QString chosen = diagrams.size() == 1 ? items.front()
                                              : QInputDialog::getItem(this, "Bifurcation diagram",
                                                                      "Diagram name", items, 0, false, &ok);
  if (ok) openChart("bifurcation", chosen.section(':', 0, 0).toStdString());
}

void MainWindow::plotDialog(int dimensions) {
  if (!scene_) return;
  PlotFilterDialog dialog(*scene_->model, scene_->plot, scene_->tool("plot"), dimensions, this);
  if (dialog.exec() == QDialog::Accepted) openPlotWindow(dialog.plot());
}

void MainWindow::rememberRecent(const QString& path) {
  QStringList recent = QSettings().value("recentScenes").toStringList();
  recent.removeAll(path);
  recent.prepend(path);
  while (recent.size() > 8)
    recent.removeLast();
  QSettings().setValue("recentScenes", recent);
  fillRecentMenu();
}

void MainWindow::fillRecentMenu() {
  recentMenu_->clear();
  const QStringList recent = QSettings().value("recentScenes").toStringList();
  for (const QString& p : recent) {
    // a name two files share says its folder too
    const QString name = QFileInfo(p).fileName();
    const bool shared = std::count_if(recent.begin(), recent.end(),
                                      [&](const QString& q) { return QFileInfo(q).fileName() == name; }) > 1;
    const QString label = shared ? QFileInfo(p).dir().dirName() + "/" + name : name;
    recentMenu_
        ->addAction(label, this,
                    [this, p] {
                      if (mayReplaceMap("Opening " + QFileInfo(p).fileName())) openScene(p);
                    })
        ->setToolTip(p);
  }
}

void MainWindow::openDialog() {
  const QString path = QFileDialog::getOpenFileName(
      this, "Open scene", QString::fromStdString(scenesDirectory()), "Scenes (*.json)");
  if (!path.isEmpty() && mayReplaceMap("Opening " + QFileInfo(path).fileName())) openScene(path);
}

} // namespace rv
