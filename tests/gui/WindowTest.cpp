// Qt Tests of the main window on a real X server (xvfb) and GL (llvmpipe through GLX): the visualizer's
// settings panel recolours the ball in the next frame (pixel check) and the edit survives a re-run; snapshot
// and record write a real PNG and a valid MP4 (ffprobe) while the event loop keeps running; a chart (filter)
// window and the apex window draw real pictures. Screenshots of each window are kept in ROLLVIZ_TEST_OUTPUT.
#include "app/gui/AboutDialog.h"
#include "app/gui/ApexWindow.h"
#include "app/gui/ChartWindow.h"
#include "app/gui/ControlPanel.h"
#include "app/gui/FilterWindow.h"
#include "app/gui/GalleryDialog.h"
#include "app/gui/MainWindow.h"
#include "app/gui/MapPanel.h"
#include "app/gui/MultipliersWindow.h"
#include "app/gui/ParameterForm.h"
#include "app/gui/PlotWindow.h"
#include "app/gui/QtVtkWidget.h"
#include "app/gui/RollingBodyDialog.h"
#include "app/gui/SweepWindow.h"
#include "app/gui/ToolManager.h"
#include "app/gui/VisualizerSettings.h"
#include "dynamics/jobs/JobTree.h"
#include "dynamics/jobs/PoincareTask.h"
#include "dynamics/tools/ToolRegistry.h"
#include "render/charts/Chart3D.h"
#include "render/charts/PoincareChart.h"
#include "render/context/HeadlessContext.h"
#include "scenes/BuiltinTools.h"
#include "scenes/ModelFile.h"
#include "scenes/SceneLoader.h"
#include "scenes/SweepTask.h"
#include "scenes/ToolRunner.h"
#include "tests/gui/JobStatusText.h"
#include <vtkAxis.h>
#include <vtkCamera.h>
#include <vtkChartXY.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkPlotPoints.h>
#include <vtkTable.h>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QContextMenuEvent>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QPointer>
#include <QPushButton>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QStyle>
#include <QTabBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolBar>
#include <QTreeWidget>
#include <QtTest>
#include <array>
#include <cstdio>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <vtkCamera.h>
#include <vtkChartXY.h>
#include <vtkPlot.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

namespace rv {

namespace {
// how many pixels of a picture are of a kind
long countPixels(const QImage& img, const std::function<bool(const QColor&)>& kind) {
  long n = 0;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x)
      n += kind(img.pixelColor(x, y));
  return n;
}
// the non-empty lines of a written CSV file (none when it cannot be read)
QStringList csvRows(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {};
  return QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
}
// pixels that are strongly red (the recoloured ball)
long redPixels(const QImage& img) {
  return countPixels(img, [](const QColor& c) { return c.red() > 150 && c.green() < 90 && c.blue() < 90; });
}
// a real picture, not a blank widget: many distinct colours
bool varied(const QImage& img) {
  std::set<QRgb> colours;
  for (int y = 0; y < img.height(); y += 2)
    for (int x = 0; x < img.width(); x += 2)
      colours.insert(img.pixel(x, y));
  return colours.size() > 200;
}
// pixels drawn darker than the charts' white background and light grid
long inked(const QImage& img) {
  return countPixels(img, [](const QColor& c) { return qGray(c.rgb()) < 200; });
}

// writes a JSON document (a sweep file) to `path`
bool writeJson(const QString& path, const nlohmann::json& doc) {
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly)) return false;
  f.write(QByteArray::fromStdString(doc.dump()));
  return true;
}

// MEGNO over 5 x 4 Henon-Heiles starts (map.0, map.1 in [-0.2, 0.2]) to t = 100: a sweep file's document
nlohmann::json hhMegnoSweep() {
  return {{"scene", defaultScenePath("henon_heiles")},
          {"axes",
           {{{"id", "map.0"}, {"min", -0.2}, {"max", 0.2}, {"count", 5}},
            {{"id", "map.1"}, {"min", -0.2}, {"max", 0.2}, {"count", 4}}}},
          {"quantity", "megno"},
          {"set", {{"megno.time", 100}}}};
}

// a pixel of a sweep window's view over grid point `index`, or (-1, -1)
QPoint pixelOver(const SweepWindow& w, long index) {
  for (int y = 0; y < w.view()->height(); y += 3)
    for (int x = 0; x < w.view()->width(); x += 3)
      if (w.pointUnder(QPointF(x, y)) == index) return {x, y};
  return {-1, -1};
}

// a window's screenshot kept as a test artifact; true when it is a real picture (not one flat colour: the
// widgets' text and the views' drawings give dozens of colours at least)
bool keep(const QImage& img, const QString& name) {
  const QByteArray dir = qgetenv("ROLLVIZ_TEST_OUTPUT");
  if (!dir.isEmpty()) img.save(QString::fromUtf8(dir) + "/" + name, "PNG");
  std::set<QRgb> colours;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x)
      colours.insert(img.pixel(x, y));
  if (colours.size() < 40) qWarning("%s: %zu colours", qPrintable(name), colours.size());
  return colours.size() >= 40;
}
// waits until trajectories `ids` of the map have finished and `points` points of each are drawn
bool finishDrawing(MapPanel* map, const std::vector<int>& ids, std::size_t points) {
  QElapsedTimer clock;
  clock.start();
  while (clock.elapsed() < 120000) { // a generous deadline: the machine may be busy
    map->drain();
    bool done = true;
    for (int id : ids)
      done = done && map->trajectories().points(id).first.size() >= points &&
             map->jobs().find(id)->status() == Job::Status::Finished;
    if (done) {
      for (int id : ids)
        if (map->trajectories().points(id).first.size() != points) return false;
      return true;
    }
    QTest::qWait(20);
  }
  return false;
}
// answers the next modal question box (opened by what the caller does next) with `b`: polls until the box
// is up, however long the machine takes to open it (a fixed delay could fire before it, and the test hang)
void answerNextQuestion(QMessageBox::StandardButton b) {
  auto* poll = new QTimer(qApp);
  auto* clock = new QElapsedTimer;
  clock->start();
  QObject::connect(poll, &QTimer::timeout, [poll, clock, b] {
    auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
    if (!box && clock->elapsed() < 60000) return;
    poll->stop();
    poll->deleteLater();
    delete clock;
    if (box) box->button(b)->click();
  });
  poll->start(20);
}
// counts the paint events a widget receives: "the view has painted again" as a condition to wait for
class PaintCounter : public QObject {
public:
  explicit PaintCounter(QWidget* w) { w->installEventFilter(this); }
  long paints() const { return paints_; }

protected:
  bool eventFilter(QObject*, QEvent* e) override {
    if (e->type() == QEvent::Paint) ++paints_;
    return false;
  }

private:
  long paints_ = 0;
};
int framesOf(const QString& path) {
  const std::string cmd = "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                          "stream=nb_read_frames -of csv=p=0 '" +
                          path.toStdString() + "'";
  FILE* f = popen(cmd.c_str(), "r");
  int n = -1;
  if (f && std::fscanf(f, "%d", &n) != 1) n = -1;
  if (f) pclose(f);
  return n;
}
// the last frame of a video as a picture (ffmpeg decodes it); null when it cannot be read
QImage lastFrame(const QString& video) {
  const QString png = video + ".last.png";
  const std::string cmd =
      "ffmpeg -v error -y -sseof -0.5 -i '" + video.toStdString() + "' -update 1 '" + png.toStdString() + "'";
  if (std::system(cmd.c_str()) != 0) return {};
  return QImage(png);
}
} // namespace

class MainWindowTest : public QObject {
  Q_OBJECT
  MainWindow* window_ = nullptr;
  QTemporaryDir dir_;

  // whether a new top-level window leaves the main window's menu and toolbars free
  bool belowTheToolbars(const QWidget* w) const {
    int bottom = window_->menuBar()->mapToGlobal(QPoint(0, window_->menuBar()->height())).y();
    for (const QToolBar* bar : window_->findChildren<QToolBar*>())
      if (bar->isVisible() && bar->window() == window_)
        bottom = std::max(bottom, bar->mapToGlobal(QPoint(0, bar->height())).y());
    const bool below = w->frameGeometry().top() >= bottom;
    if (!below)
      qWarning("window %s at %d, the toolbars end at %d", qPrintable(w->windowTitle()),
               w->frameGeometry().top(), bottom);
    return below;
  }

  // sets the control panel's continuation tab as a user does: the parameter chosen, the end value typed, the
  // step and the method set (Apply is the caller's)
  void setUpContinuation(const QString& parameter, const QString& to, double step, const QString& method) {
    ControlPanel* panel = window_->controlPanel();
    auto* choice = panel->findChild<QComboBox*>("continuation_parameter");
    auto* end = panel->findChild<QLineEdit*>("continuation_to");
    auto* stepBox = qobject_cast<QDoubleSpinBox*>(panel->form("continuation")->editor("step"));
    auto* methodBox = qobject_cast<QComboBox*>(panel->form("continuation")->editor("method"));
    QVERIFY(choice && end && stepBox && methodBox);
    choice->setCurrentIndex(choice->findText(parameter));
    QVERIFY(choice->currentIndex() > 0);
    emit choice->activated(choice->currentIndex());
    end->clear();
    QTest::keyClicks(end, to);
    stepBox->setValue(step);
    methodBox->setCurrentIndex(methodBox->findText(method));
    QVERIFY(methodBox->currentIndex() >= 0);
    QVERIFY(panel->pending());
  }
  // Shift+click at (gx, gy): the search finds the point (px, py); the map's context menu on it continues it.
  // The family's job once it has ended; nullptr (a failed check) otherwise.
  Job* continueAShiftClickedPoint(double gx, double gy, double px, double py) {
    MapPanel* map = window_->mapPanel();
    const int found = map->fixedPointsFound();
    map->searchFixedPointAt(gx, gy);
    const int search = map->jobs().jobs().back()->id();
    if (!QTest::qWaitFor([&] { return map->fixedPointsFound() == found + 1; }, 60000)) return nullptr;
    // Fit first: the axes the click held show what was drawn before, which need not reach the point
    if (!QTest::qWaitForWindowExposed(map->window())) return nullptr;
    map->drain();
    map->findChild<QPushButton*>("fit_map")->click();
    double x = 0, y = 0; // the point's pixel, once the chart has laid out in a frame
    if (!QTest::qWaitFor([&] { return map->chart().toPixels(px, py, x, y); }, 60000)) return nullptr;
    const double dpr = map->view()->devicePixelRatioF();
    const QPoint at(static_cast<int>(std::lround(x / dpr)),
                    map->view()->height() - static_cast<int>(std::lround(y / dpr)));
    if (map->fixedPointAt(at) != search) return nullptr;
    QContextMenuEvent menuEvent(QContextMenuEvent::Mouse, at, map->view()->mapToGlobal(at));
    QApplication::sendEvent(map->view(), &menuEvent);
    auto* menu = map->findChild<QMenu*>("fixed_point_menu");
    if (!menu || menu->actions().isEmpty() ||
        !menu->actions().front()->text().contains(QString("tool #%1").arg(search)))
      return nullptr;
    menu->actions().front()->trigger();
    menu->close();
    Job* family = map->jobs().jobs().back();
    if (family->task().name() != "Continuation") return nullptr;
    if (!QTest::qWaitFor([&] { return !family->running(); }, 60000)) return nullptr;
    return family;
  }

private slots:
  void initTestCase() {
    registerBuiltinTools(); // as the application does at start (scenes/ModuleLoader.h)
    window_ = new MainWindow;
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_));
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("chaplygin_ball"))));
    QTRY_VERIFY_WITH_TIMEOUT(window_->shownTime() > 0.1, 60000); // it plays
    QVERIFY(keep(window_->grab().toImage(), "window_main.png"));
  }

  void settingsRecolourTheBallInTheNextFrame() {
    window_->togglePlay(); // paused: only the colour changes between the two frames
    QTRY_VERIFY_WITH_TIMEOUT(window_->caughtUp(), 60000); // the frames asked for before the pause are in
    const QImage before = window_->view()->grabFramebuffer();
    PaintCounter painted(window_->view());
    window_->settings()->selectObject("ball");
    window_->settings()->pickColour({1.0, 0.0, 0.0});
    QTRY_VERIFY_WITH_TIMEOUT(painted.paints() > 0, 60000); // the next frame
    const QImage after = window_->view()->grabFramebuffer();
    QVERIFY(keep(after, "window_main_red_ball.png"));
    QVERIFY2(redPixels(after) > redPixels(before) + 2000,
             qPrintable(QString("red pixels %1 -> %2").arg(redPixels(before)).arg(redPixels(after))));
    // the edit is kept when the scene runs again
    window_->restart();
    QVERIFY(window_->visual()->options().object("ball").colour == Rgb({1.0, 0.0, 0.0}));
    window_->togglePlay();
  }

  void stepGoesOneFrameWhilePaused() {
    window_->togglePlay(); // pause, and wait until it holds still
    QTRY_VERIFY_WITH_TIMEOUT(window_->caughtUp(), 60000);
    const double t0 = window_->shownTime();
    window_->stepFrame();
    // caught up again: the step is shown and nothing more is on its way (it goes no further)
    QTRY_VERIFY_WITH_TIMEOUT(window_->caughtUp() && window_->shownTime() > t0, 60000);
    QVERIFY(std::abs(window_->shownTime() - t0 - 1.0 / 25) < 1e-9); // speed 1: 1/25 s of simulation
    window_->togglePlay();
  }

  // File > Snapshot: the view holds still while the dialog is open, so the proposed name's time is the
  // picture's; playing goes on afterwards
  void snapshotHoldsTheViewStillWhileItsDialogIsOpen() {
    if (!window_->playing()) window_->togglePlay();
    QTRY_VERIFY_WITH_TIMEOUT(window_->shownTime() > 0.2, 60000);
    bool stillWhileOpen = false;
    double timeWhileOpen = -1;
    QString proposed;
    QTimer::singleShot(0, this, [&] {
      QTRY_VERIFY_WITH_TIMEOUT(qobject_cast<QFileDialog*>(QApplication::activeModalWidget()), 60000);
      auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
      stillWhileOpen = !window_->playing();
      timeWhileOpen = window_->shownTime();
      proposed = dialog->selectedFiles().value(0);
      dialog->selectFile(dir_.filePath(QFileInfo(proposed).fileName()));
      static_cast<QDialog*>(dialog)->accept(); // QDialog::accept is public; QFileDialog overrides it
    });
    window_->snapshot();
    QVERIFY(stillWhileOpen);
    QVERIFY(window_->playing());
    const QString name = QFileInfo(proposed).fileName();
    // the name says the time the view showed (and still shows) while the dialog was open
    QVERIFY2(name.endsWith(QString("-t%1.png").arg(timeWhileOpen, 0, 'f', 2)), qPrintable(name));
    QVERIFY(QFile::exists(dir_.filePath(name)));
  }

  // Save dialogs propose the user's folders, never the working directory: a shipped scene is saved to the
  // documents folder, a user's scene beside itself
  void saveDialogsProposeTheUsersFolders() {
    const auto proposedBy = [&](auto open) {
      QString proposed;
      QTimer::singleShot(0, this, [&] {
        QTRY_VERIFY_WITH_TIMEOUT(qobject_cast<QFileDialog*>(QApplication::activeModalWidget()), 60000);
        auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
        proposed = dialog->selectedFiles().value(0);
        dialog->reject();
      });
      open();
      return proposed;
    };
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("henon_heiles"))));
    QCOMPARE(proposedBy([&] { window_->saveDialog(); }),
             proposedPath(QStandardPaths::DocumentsLocation, "henon_heiles.json"));
    const QString mine = dir_.filePath("mine.json");
    QVERIFY(window_->saveSceneTo(mine));
    QVERIFY(window_->openScene(mine));
    QCOMPARE(proposedBy([&] { window_->saveDialog(); }), mine);
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("chaplygin_ball")))); // for the next
  }

  void snapshotWritesAPng() {
    const QString path = dir_.filePath("snap.png");
    QVERIFY(window_->snapshotTo(path));
    QVERIFY(window_->results().contains("snapshot written: " + path)); // said, and kept
    const QImage img(path);
    QCOMPARE(img.size(), window_->view()->grabFramebuffer().size());
    QVERIFY(varied(img));
  }

  // Issue 43, item 7: pictures for papers, at File > Picture size, rendered offscreen whatever the window's
  // size: a 1920 x 1080 snapshot of a smaller view, the map exported at twice its size
  void picturesAtAChosenSizeAreRenderedOffscreen() {
    const QSize shown = window_->view()->grabFramebuffer().size();
    QVERIFY(shown.width() < 1920 && shown.height() < 1080);
    PictureSize::setCurrent("1920x1080");
    const QString path = dir_.filePath("big.png");
    QVERIFY(window_->snapshotTo(path));
    const QImage big(path);
    QCOMPARE(big.size(), QSize(1920, 1080));
    QVERIFY(varied(big));
    QVERIFY(keep(big, "snapshot_1920x1080.png"));
    // its time line grows with the picture (the whole number of times the view fits): about scale^2 as many
    // dark pixels in the bottom left corner as on the screen
    const double scale = std::max(1L, std::lround(std::min(1920.0 / shown.width(), 1080.0 / shown.height())));
    const auto textInk = [](const QImage& img, int band) {
      return countPixels(img.copy(0, img.height() - band, img.width() * 45 / 100, band),
                         [](const QColor& c) { return c.lightness() < 60; });
    };
    const double textRatio =
        static_cast<double>(textInk(big, static_cast<int>(40 * scale))) /
        static_cast<double>(std::max(1L, textInk(window_->view()->grabFramebuffer(), 40)));
    qInfo("time line ink x%f at scale %f", textRatio, scale);
    QVERIFY2(textRatio > 0.6 * scale * scale,
             qPrintable(QString("time line ink x%1 at scale %2").arg(textRatio).arg(scale)));
    QCOMPARE(window_->view()->grabFramebuffer().size(), shown); // the window keeps its size and picture
    QVERIFY(varied(window_->view()->grabFramebuffer()));
    PictureSize::setCurrent("x2");
    const QString map = dir_.filePath("map2.png");
    QString why;
    QVERIFY2(saveChartFigure(window_->mapPanel()->view(), map, &why), qPrintable(why));
    const QImage onScreen = window_->mapPanel()->view()->grabFramebuffer();
    QCOMPARE(QImage(map).size(), onScreen.size() * 2);
    QVERIFY(keep(QImage(map), "map_x2.png"));
    // the same figure, finer: type, pens and points twice as large, so four times the ink or more (the same
    // type and pens on twice the pixels would give about twice)
    const auto ink = [](const QImage& img) {
      return countPixels(img, [](const QColor& c) { return c.lightness() < 110; });
    };
    const double ratio = static_cast<double>(ink(QImage(map))) / static_cast<double>(ink(onScreen));
    qInfo("ink ratio %f", ratio);
    QVERIFY2(ratio > 3 && ratio < 10, qPrintable(QString("ink x%1").arg(ratio))); // (small type is grey)
    PictureSize::setCurrent("view");
    QVERIFY(!PictureSize::valid("10x10") && !PictureSize::valid("abc") && PictureSize::valid("2400x1600"));
  }

  // Record takes what the view shows from now on (the run goes on; it does not restart), and the video lasts
  // as long as the recording did (how late the event loop is meanwhile is a figure: bench_gui)
  void recordingKeepsWhatIsOnScreenForAsLongAsItRan() {
    const QString path = dir_.filePath("rec.mp4");
    if (!window_->playing()) window_->togglePlay();
    // it pauses the run: playing again however it ends, so that the next tests find the run going
    const auto replay = qScopeGuard([this] {
      if (!window_->playing()) window_->togglePlay();
    });
    QTRY_VERIFY_WITH_TIMEOUT(window_->shownTime() > 0, 60000);
    const double t0 = window_->shownTime();
    QSignalSpy done(window_, &MainWindow::recordingFinished);
    PaintCounter painted(window_->view());
    // the recording's length lies between these two clocks' (the outer one started before startRecording and
    // read after stopRecording, the inner one inside those calls), however long the calls take
    QElapsedTimer outer, inner;
    outer.start();
    QVERIFY(window_->startRecording(path, 10));
    inner.start();
    QVERIFY(window_->recording());
    // the run plays on while recording: a second of simulation (speed 1), many frames painted
    QTRY_VERIFY_WITH_TIMEOUT(window_->shownTime() > t0 + 1.0 && painted.paints() > 10, 60000);
    window_->togglePlay(); // a pause is part of the video too: a frame painted while paused
    QTRY_VERIFY_WITH_TIMEOUT(window_->caughtUp(), 60000);
    const long pausedAt = painted.paints();
    window_->view()->update();
    QTRY_VERIFY_WITH_TIMEOUT(painted.paints() > pausedAt, 60000);
    const double shortest = inner.elapsed() / 1000.0;
    window_->stopRecording();
    const double longest = outer.elapsed() / 1000.0;
    QVERIFY(!window_->recording());
    QVERIFY(done.wait(60000));
    QVERIFY2(done.first().at(0).toBool(), qPrintable(window_->results()));
    QVERIFY(window_->shownTime() > t0); // the run went on while recording
    const int frames = framesOf(path);
    // ScreenRecorder::finish writes up to the recording's length and at least one frame past those written
    // (the last picture shown): round(10 s) <= frames <= floor(10 s) + 2
    QVERIFY2(
        frames >= shortest * 10 - 0.5 && frames <= longest * 10 + 2,
        qPrintable(QString("%1 frames for %2 to %3 s at 10 fps").arg(frames).arg(shortest).arg(longest)));
    QVERIFY(window_->results().contains("wrote " + path));
    // its pictures are the view's, the paused picture last
    const QImage picture = lastFrame(path), shown = window_->view()->grabFramebuffer();
    QVERIFY(keep(picture, "window_recording_last_frame.png"));
    QCOMPARE(picture.size(), QSize(shown.width() & ~1, shown.height() & ~1)); // made even for the encoder
  }

  // Issue 43, item 7: Record at File > Picture size -- each frame rendered offscreen at that size (here
  // 1280 x 720, not the view's), the window keeping its own
  void aRecordingAtAChosenSizeHasThatSize() {
    if (!window_->playing()) window_->togglePlay();
    const QSize shown = window_->view()->grabFramebuffer().size();
    QVERIFY(shown != QSize(1280, 720));
    PictureSize::setCurrent("1280x720");
    const auto back = qScopeGuard([] { PictureSize::setCurrent("view"); });
    const QString path = dir_.filePath("rec720.mp4");
    QSignalSpy done(window_, &MainWindow::recordingFinished);
    QVERIFY(window_->startRecording(path, 10));
    QVERIFY(window_->results().contains("at 1280x720"));
    const double t0 = window_->shownTime();
    // a few frames at 10 fps: the video's length is wall-clock time (and the run must go on meanwhile)
    QElapsedTimer recorded;
    recorded.start();
    QTRY_VERIFY_WITH_TIMEOUT(recorded.elapsed() > 800 && window_->shownTime() > t0, 60000);
    window_->stopRecording();
    QVERIFY(done.wait(60000));
    QVERIFY2(done.first().at(0).toBool(), qPrintable(window_->results()));
    QVERIFY(framesOf(path) >= 2);
    const QImage picture = lastFrame(path);
    QCOMPARE(picture.size(), QSize(1280, 720));
    QVERIFY(varied(picture));
    QVERIFY(keep(picture, "window_recording_1280x720.png"));
    QCOMPARE(window_->view()->grabFramebuffer().size(), shown);
    QVERIFY(varied(window_->view()->grabFramebuffer()));
  }

  void aRecordingThatCannotBeWrittenSaysWhy() {
    QVERIFY(!window_->startRecording("/nonexistent-folder/rec.mp4"));
    QVERIFY(!window_->recording());
    QVERIFY2(window_->results().contains("Cannot record: "), qPrintable(window_->results()));
  }

  void chartWindowDrawsItsView() {
    ChartWindow* chart = window_->openChart("bifurcation");
    QVERIFY(chart);
    QSignalSpy finished(chart, &ChartWindow::finished);
    QVERIFY(finished.wait(60000));
    QVERIFY2(chart->ready(), qPrintable(chart->failure()));
    QVERIFY(QTest::qWaitForWindowExposed(chart->window()));
    const auto nonWhite = [&] {
      return countPixels(chart->view()->grabFramebuffer(),
                         [](const QColor& c) { return c.lightness() < 200; });
    };
    QTRY_VERIFY2_WITH_TIMEOUT(nonWhite() > 1000, qPrintable(QString("dark pixels %1").arg(nonWhite())),
                              60000);
    const QImage img = chart->view()->grabFramebuffer();
    QVERIFY(keep(chart->grab().toImage(), "window_chart_bifurcation.png"));
    QVERIFY(varied(img) || img.width() > 0);
    // its data as CSV: a header and the branches' points
    const QString csv = dir_.filePath("bifurcation.csv");
    QVERIFY(chart->saveCsv(csv));
    const QStringList lines = csvRows(csv);
    QVERIFY(!lines.isEmpty() && lines.first().startsWith("series,"));
    QVERIFY2(lines.size() > 50, qPrintable(QString("%1 lines").arg(lines.size())));
    chart->close();
  }

  // long work shows progress and can be cancelled: a Lyapunov run of 10^7 time units stops before its end and
  // draws what it has (how fast it stops is a figure, not asserted here)
  void chartWindowCancels() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_heiles")).document;
    doc["lyapunov"] = {{"time", 1e7}};
    QVERIFY(window_->runDocument(doc));
    ChartWindow* chart = window_->openChart("lyapunov");
    QSignalSpy finished(chart, &ChartWindow::finished);
    Job* job = chart->job();
    QVERIFY(job);
    // under way: some progress made, the chart not ready
    QTRY_VERIFY_WITH_TIMEOUT(job->progress() > 0, 60000);
    QVERIFY(!chart->ready());
    chart->cancel();
    QVERIFY(finished.wait(60000));
    QVERIFY2(job->progress() < 1, "stopped before its end");
    QVERIFY2(chart->ready() || chart->failure() == "stopped", qPrintable(chart->failure()));
    chart->close();
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("chaplygin_ball")))); // for the next
  }

  // chart windows open cascaded, not on one spot
  void chartWindowsOpenCascaded() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_heiles")).document;
    doc["lyapunov"] = {{"time", 20}, {"output_period", 2}};
    QVERIFY(window_->runDocument(doc));
    ChartWindow* first = window_->openChart("lyapunov");
    ChartWindow* second = window_->openChart("lyapunov");
    QTRY_VERIFY_WITH_TIMEOUT(first->ready() && second->ready(), 60000);
    QCOMPARE(second->pos() - first->pos(), QPoint(32, 32));
    QPointer<ChartWindow> a(first), b(second);
    first->close();
    second->close();
    QTRY_VERIFY_WITH_TIMEOUT(!a && !b, 60000); // gone, with their jobs, before the next test
  }

  // every chart is a job of the tool manager (issue: one path for every long computation): a surface
  // computation is listed with its progress, stops, continues and ends with the chart of an uninterrupted run
  void chartComputationsAreJobsOfTheToolManager() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_heiles")).document;
    doc["grid"] = {{"x_min", -0.4}, {"x_max", 0.4},   {"y_min", -0.4},
                   {"y_max", 0.4},  {"step_x", 0.01}, {"step_y", 0.01}};
    QVERIFY(window_->runDocument(doc));
    ChartWindow* whole = window_->openChart("surface");
    QTRY_VERIFY_WITH_TIMEOUT(whole->ready() && whole->job()->status() == Job::Status::Finished, 120000);
    const QString a = dir_.filePath("surface_whole.csv"), b = dir_.filePath("surface_continued.csv");
    QVERIFY(whole->saveCsv(a));
    whole->close();

    window_->mapPanel()->jobs().pauseNextAt(0.02); // the stop lands mid-run whatever the machine's speed
    ChartWindow* chart = window_->openChart("surface");
    Job* job = chart->job();
    QVERIFY(job);
    ToolManager* tools = window_->toolManager();
    tools->refresh();
    tools->select(job->id());
    QCOMPARE(tools->selected(), job);
    QTRY_VERIFY_WITH_TIMEOUT(job->status() != Job::Status::Running, 60000);
    tools->stopSelected();
    QCOMPARE(job->status(), Job::Status::Stopped);
    const double stoppedAt = job->progress();
    QVERIFY2(stoppedAt < 1, "stopped before its end");
    tools->continueSelected();
    QTRY_VERIFY_WITH_TIMEOUT(job->status() == Job::Status::Finished, 120000);
    QTRY_VERIFY_WITH_TIMEOUT(chart->ready() && chart->failure().isEmpty(), 60000);
    QVERIFY(chart->saveCsv(b));
    QCOMPARE(csvRows(b), csvRows(a));
    QVERIFY(keep(chart->grab().toImage(), "window_chart_surface_job.png"));
    // closing the window deletes its job
    const int id = job->id();
    chart->close();
    QTRY_VERIFY_WITH_TIMEOUT(!window_->mapPanel()->jobs().find(id), 60000);
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("chaplygin_ball"))));
  }

  // a sweep runs as a job of the tool manager, its window fills in, and a click on a cell opens that grid
  // point's scene (its initial point on the section) in the main window
  void sweepWindowFillsInAndOpensAPointsScene() {
    const QString path = dir_.filePath("hh_sweep.json");
    QVERIFY(writeJson(path, hhMegnoSweep()));
    SweepWindow* w = window_->openSweep(path);
    QVERIFY(w);
    QVERIFY(QTest::qWaitForWindowExposed(w));
    QVERIFY(belowTheToolbars(w)); // issue 61 (6): it opened over them
    Job* job = w->job();
    QVERIFY(job);
    ToolManager* tools = window_->toolManager();
    tools->refresh();
    tools->select(job->id());
    QCOMPARE(tools->selected(), job);
    QTRY_VERIFY_WITH_TIMEOUT(job->status() == Job::Status::Finished, 60000);
    QTRY_COMPARE_WITH_TIMEOUT(w->done(), 20L, 60000);
    QVERIFY(QTest::qWaitForWindowExposed(w->window()));
    QTRY_VERIFY_WITH_TIMEOUT(varied(w->view()->grabFramebuffer()), 60000);
    QVERIFY(keep(w->grab().toImage(), "window_sweep.png"));
    // Save figure as vectors: the cells as shapes (a PDF of a picture would be a single image)
    for (const char* name : {"sweep.svg", "sweep.pdf"}) {
      QVERIFY2(w->saveFigure(dir_.filePath(name)), name);
      QVERIFY(QFileInfo(dir_.filePath(name)).size() > 1000);
    }
    QFile svg(dir_.filePath("sweep.svg"));
    QVERIFY(svg.open(QIODevice::ReadOnly));
    QVERIFY(svg.readAll().count("<polygon") >= 20); // two triangles a run of cells: at least one run a row
    // the position of grid point 13 = (map.0, map.1) = (0.1, 0.0667)
    const QPoint at = pixelOver(*w, 13);
    QVERIFY2(at.x() >= 0, "no pixel over grid point 13");
    QTest::mouseClick(w->view(), Qt::LeftButton, {}, at);
    QTRY_VERIFY_WITH_TIMEOUT(window_->scene() && window_->scene()->model->info().id == "henon_heiles", 60000);
    // the title names the sweep's point and its problem, not the scene open before
    QVERIFY2(window_->windowTitle() == "rollviz — a point of hh_sweep.json (henon_heiles)",
             qPrintable(window_->windowTitle()));
    // and so does the status bar (issue 61 (5): it kept the old scene's file)
    QVERIFY2(window_->statusText().startsWith("a point of hh_sweep.json"), qPrintable(window_->statusText()));
    const auto point = window_->scene()->document["initial"]["map"];
    QCOMPARE(point.size(), std::size_t(2));
    QCOMPARE(point[0].get<double>(), w->spec().axisValues(13)[0]);
    QCOMPARE(point[1].get<double>(), w->spec().axisValues(13)[1]);

    // Zoom and a rectangle dragged from grid point 6 to grid point 18: that window, a child job, at the same
    // counts; its points are a fresh sweep's over the window
    auto* zoom = w->findChild<QPushButton*>("zoom");
    QVERIFY(zoom);
    zoom->click();
    const QPoint from = pixelOver(*w, 6), to = pixelOver(*w, 18);
    QVERIFY(from.x() >= 0 && to.x() >= 0);
    QTest::mousePress(w->view(), Qt::LeftButton, {}, from);
    QTest::mouseMove(w->view(), to);
    QTest::mouseRelease(w->view(), Qt::LeftButton, {}, to);
    QCOMPARE(w->zooms(), std::size_t(2));
    QCOMPARE(w->zoomLevel(), std::size_t(1));
    QVERIFY(!zoom->isChecked());
    Job* zoomed = w->job();
    QVERIFY(zoomed && zoomed != job && zoomed->parent() == job);
    const SweepSpec& z = w->spec();
    QCOMPARE(z.axes[0].count, 5);
    QCOMPARE(z.axes[1].count, 4);
    QVERIFY(z.axes[0].min > -0.2 && z.axes[0].max < 0.2 && z.axes[0].min < z.axes[0].max);
    QTRY_VERIFY_WITH_TIMEOUT(zoomed->status() == Job::Status::Finished, 60000);
    QTRY_COMPARE_WITH_TIMEOUT(w->done(), 20L, 60000);
    const auto& store = static_cast<const SweepTask&>(zoomed->task()).store();
    for (long i : {0L, 7L, 19L})
      QCOMPARE(
          store.read(i).values,
          evaluateSweepPoint(zoomSweep(loadSweep(path.toStdString()),
                                       {z.axes[0].min, z.axes[0].max, z.axes[1].min, z.axes[1].max}, "test"),
                             i, {})
              .values);
    QVERIFY(w->back());
    QCOMPARE(w->spec().axes[0].min, -0.2);
    QCOMPARE(w->job(), job);
    QVERIFY(!w->back());
    QVERIFY(w->forward());
    QCOMPARE(w->job(), zoomed);
    QVERIFY(w->back());
    // the jobs are the window's: another scene leaves them, closing the window deletes them (zooms too)
    const int id = job->id(), zoomId = zoomed->id();
    QVERIFY(window_->mapPanel()->jobs().find(id));
    w->close();
    QTRY_VERIFY_WITH_TIMEOUT(!window_->mapPanel()->jobs().find(id), 60000);
    QVERIFY(!window_->mapPanel()->jobs().find(zoomId));
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("chaplygin_ball"))));
  }

  // Zoom, then a rectangle dragged while new points arrive: the chart was drawn again under the drag (which
  // replaced the view and deleted the rubber band it owned -- a crash, 3 of 3 times by hand); the drag now
  // keeps its view until released, and the zoom it made is computed. Without Zoom a drag opens no cell, and a
  // cell whose scene the main window declines says so.
  void sweepZoomDraggedWhilePointsArriveDoesNotCrash() {
    const QString path = dir_.filePath("hh_zoom_sweep.json");
    QVERIFY(writeJson(path, hhMegnoSweep()));
    SweepWindow* w = window_->openSweep(path);
    QVERIFY(w);
    Job* job = w->job();
    QTRY_VERIFY_WITH_TIMEOUT(job->status() == Job::Status::Finished, 60000);
    QTRY_COMPARE_WITH_TIMEOUT(w->done(), 20L, 60000);
    QVERIFY(QTest::qWaitForWindowExposed(w->window()));
    auto* zoom = w->findChild<QPushButton*>("zoom");
    QVERIFY(zoom);
    zoom->click();
    QPoint from, to; // where the chart, once drawn, places grid points 6 and 18
    QTRY_VERIFY_WITH_TIMEOUT((from = pixelOver(*w, 6)).x() >= 0 && (to = pixelOver(*w, 18)).x() >= 0, 60000);
    QtVtkWidget* dragged = w->view();
    QTest::mousePress(dragged, Qt::LeftButton, {}, from);
    QTest::mouseMove(dragged, (from + to) / 2);
    // the sweep computed again while the button is held (Restart in the tool manager): its points come anew
    // and the window wants to draw them -- it has seen them (its store read afresh: done() -1) but keeps the
    // view the drag is on until the release
    const int generation = static_cast<const SweepTask&>(job->task()).generation();
    job->restart();
    QTRY_VERIFY_WITH_TIMEOUT(static_cast<const SweepTask&>(job->task()).generation() != generation &&
                                 job->status() == Job::Status::Finished,
                             60000);
    QTRY_COMPARE_WITH_TIMEOUT(w->done(), -1L, 60000);
    QCOMPARE(w->view(), dragged);
    QTest::mouseMove(w->view(), to);
    QTest::mouseRelease(w->view(), Qt::LeftButton, {}, to);
    QCOMPARE(w->zooms(), std::size_t(2));
    QCOMPARE(w->zoomLevel(), std::size_t(1));
    Job* zoomed = w->job();
    QVERIFY(zoomed && zoomed != job);
    QTRY_VERIFY_WITH_TIMEOUT(zoomed->status() == Job::Status::Finished, 60000);
    QTRY_COMPARE_WITH_TIMEOUT(w->done(), 20L, 60000);
    QVERIFY(varied(w->view()->grabFramebuffer()));

    // without Zoom: a drag is no click, a click is; a declined scene is not called opened
    int offered = 0;
    w->setSceneOpener([&offered](const nlohmann::json&) {
      ++offered;
      return false;
    });
    QPoint a, b;
    QTRY_VERIFY_WITH_TIMEOUT((a = pixelOver(*w, 6)).x() >= 0 && (b = pixelOver(*w, 18)).x() >= 0, 60000);
    QTest::mousePress(w->view(), Qt::LeftButton, {}, a);
    QTest::mouseMove(w->view(), b);
    QTest::mouseRelease(w->view(), Qt::LeftButton, {}, b);
    QCOMPARE(offered, 0);
    QTest::mouseClick(w->view(), Qt::LeftButton, {}, a);
    QCOMPARE(offered, 1);
    QVERIFY2(w->status().startsWith("not opened"), qPrintable(w->status()));
    w->close();
  }

  // a chart of regimes over two parameters: "Bifurcation curve" and a click on a cell follow that point's
  // period doubling in the chart's plane as a job and draw the curve over the chart (Henon: a = 3 (1 - b)^2 /
  // 4)
  void sweepWindowDrawsABifurcationCurveOverItsChart() {
    const QString path = dir_.filePath("henon_types.json");
    QVERIFY(writeJson(path, nlohmann::json{{"scene", defaultScenePath("henon_map")},
                                           {"axes",
                                            {{{"id", "a"}, {"min", 0.0}, {"max", 1.5}, {"count", 6}},
                                             {{"id", "b"}, {"min", -0.5}, {"max", 0.5}, {"count", 5}}}},
                                           {"quantity", "fixedpoint.type"},
                                           {"set",
                                            {{"fixedpoint.guess", {0.63, 0.19}},
                                             {"bifurcation_curve.kind", "period_doubling"}}}}));
    SweepWindow* w = window_->openSweep(path);
    QVERIFY(w);
    QTRY_VERIFY_WITH_TIMEOUT(w->job()->status() == Job::Status::Finished, 60000);
    QTRY_COMPARE_WITH_TIMEOUT(w->done(), 30L, 60000);
    auto* button = w->findChild<QPushButton*>("bifurcationCurve");
    QVERIFY(button);
    button->click();
    QVERIFY(button->isChecked());
    // grid point 20 = (a, b) = (0.6, 0.25): up in a there is no doubling, down there is one at a = 0.421875;
    // found once the chart is drawn (its plot area laid out)
    const auto over20 = [&] {
      (void)w->view()->grabFramebuffer();
      return pixelOver(*w, 20);
    };
    QTRY_VERIFY2_WITH_TIMEOUT(over20().x() >= 0, "no pixel over grid point 20", 60000);
    const QPoint at = over20();
    QTest::mouseClick(w->view(), Qt::LeftButton, {}, at);
    QVERIFY(!button->isChecked());
    QVERIFY(w->curveJob());
    QTRY_COMPARE_WITH_TIMEOUT(w->overlays().size(), std::size_t(1), 60000);
    QVERIFY(!w->curveJob()); // taken and removed from the tool manager
    const SweepOverlay& curve = w->overlays()[0];
    QVERIFY(curve.x.size() > 10);
    for (std::size_t i = 0; i < curve.x.size(); ++i) {
      QVERIFY(std::abs(curve.x[i] - 0.75 * (1 - curve.y[i]) * (1 - curve.y[i])) < 1e-8);
      QVERIFY(curve.x[i] >= -1e-12 && curve.x[i] <= 1.5 + 1e-12 && curve.y[i] >= -0.5 - 1e-12 &&
              curve.y[i] <= 0.5 + 1e-12);
    }
    QTRY_VERIFY_WITH_TIMEOUT(varied(w->view()->grabFramebuffer()), 60000);
    QVERIFY(keep(w->grab().toImage(), "window_sweep_curve.png"));
    w->close();
  }

  void apexWindowShowsTheApexes() {
    if (!window_->playing()) window_->togglePlay(); // it needs the 3D view's run going
    QWidget* w = window_->openApexWindow();
    QVERIFY(w && window_->apex().visual());
    QVERIFY(window_->apex().visual()->find("apex_z"));
    QTRY_VERIFY_WITH_TIMEOUT(window_->apex().time() > 0.1, 60000); // it has drawn the run for a while
    auto* view = w->findChild<QtVtkWidget*>();
    QVERIFY(view);
    const QImage img = view->grabFramebuffer();
    QVERIFY(keep(img, "window_apex.png"));
    QVERIFY(varied(img));
    QCOMPARE(window_->apex().source(), -1); // the 3D view's run
    // manual §2.4.5: the Poincaré map outputs into it -- selecting a map trajectory in the tool manager makes
    // the apex window follow that job's integration (far ahead of the 3D view's real-time run), on its level
    MapPanel* map = window_->mapPanel();
    QVERIFY(map->startAt(0.3, 0.2));
    const int id = map->jobs().jobs().back()->id();
    // the Results dock numbers it as the tool manager does
    QTRY_VERIFY_WITH_TIMEOUT(window_->results().contains(QString("trajectory #%1 started").arg(id)), 60000);
    window_->toolManager()->refresh();
    window_->toolManager()->select(id);
    QCOMPARE(window_->apex().source(), id);
    QTRY_VERIFY_WITH_TIMEOUT(window_->apex().time() > window_->shownTime() + 20, 60000);
    map->removeJob(*map->jobs().find(id)); // the apex window goes back to the 3D view's run
    QCOMPARE(window_->apex().source(), -1);
  }

  // the manual's workflow: a problem, a click on the map starts a trajectory whose points arrive; stop it,
  // edit the energy in the control panel, Edit + Continue: it goes on from its stop point at the new energy;
  // delete it
  void mapWorkflowStopEditContinueDelete_data() {
    QTest::addColumn<QString>("problem");
    QTest::newRow("ellipsoid_on_plane") << "ellipsoid_on_plane"; // the issue's case: a 3D map
    QTest::newRow("henon_heiles") << "henon_heiles";
  }

  void mapWorkflowStopEditContinueDelete() {
    QFETCH(QString, problem);
    nlohmann::json doc = loadScene(defaultScenePath(problem.toStdString())).document;
    if (problem == "ellipsoid_on_plane") {
      // map points completed at E = 5, where all of (l, L/G) at H/G = 0.2 is allowed (a click anywhere works)
      doc["parameters"]["energy"] = 5.0;
      doc["initial"] = {{"map", {0.5, 0.3, 0.2}}};
    }
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    // Tools tab: Create a Poincare map (a trajectory from the scene's initial point)
    const int created = map->trajectories().count();
    window_->controlPanel()->selectTool("poincare");
    QTest::mouseClick(window_->controlPanel()->findChild<QPushButton*>("create"), Qt::LeftButton);
    QCOMPARE(map->trajectories().count(), created + 1);
    QTRY_VERIFY_WITH_TIMEOUT(map->points() > 20, 60000); // the chart's ranges follow the points
    auto* mapView = map->findChild<QtVtkWidget*>();
    QVERIFY(mapView);
    mapView->grabFramebuffer(); // a frame drawn with those points: the click below lands in their ranges
    const int before = map->trajectories().count();
    // Ctrl+click in the middle of the map (Henon-Heiles: (y, py) near (0, 0), inside the region at E = 1/12)
    // (a plain click in the default mode; Ctrl+click in any mode)
    QTest::mouseClick(mapView, Qt::LeftButton,
                      problem == "henon_heiles" ? Qt::ControlModifier : Qt::NoModifier,
                      mapView->rect().center());
    QTRY_COMPARE_WITH_TIMEOUT(map->trajectories().count(), before + 1, 60000);
    Job* job = map->jobs().jobs().back();
    QTRY_VERIFY_WITH_TIMEOUT(dynamic_cast<PoincareTask&>(job->task()).points().total() > 5, 60000);
    ToolManager* tools = window_->toolManager();
    tools->refresh();
    tools->select(job->id());
    QCOMPARE(tools->selected(), job);
    tools->stopSelected();
    QCOMPARE(job->status(), Job::Status::Stopped);
    const double oldEnergy = dynamic_cast<PoincareTask&>(job->task()).spec().modelParameters["energy"];
    const double newEnergy = oldEnergy * 1.2;
    auto* energy = qobject_cast<QDoubleSpinBox*>(window_->controlPanel()->form("problem")->editor("energy"));
    QVERIFY(energy);
    energy->setValue(newEnergy);
    tools->editSelected();
    auto& task = dynamic_cast<PoincareTask&>(job->task());
    QCOMPARE(task.spec().modelParameters["energy"], newEnergy);
    const long pointsBefore = task.points().total();
    tools->continueSelected();
    // this trajectory's own points
    QTRY_VERIFY_WITH_TIMEOUT(task.points().total() > pointsBefore + 10, 60000);
    tools->stopSelected();
    // the trajectory's state is now on the new energy level
    const auto model = task.spec().makeModel();
    const double e = model->integrals(task.lastState().data())[0];
    QVERIFY2(
        std::abs(e - newEnergy) < 1e-9,
        qPrintable(
            QString("energy %1, expected %2 (was %3)").arg(e, 0, 'g', 17).arg(newEnergy).arg(oldEnergy)));
    QVERIFY(keep(window_->grab().toImage(), "window_main_" + problem + ".png"));
    // colour of output and Set range act on what the map draws of this trajectory
    const auto green = [](const QImage& img) { // pure green: no series has it by default
      return countPixels(img,
                         [](const QColor& c) { return c.green() > 200 && c.red() < 60 && c.blue() < 60; });
    };
    QCOMPARE(green(mapView->grabFramebuffer()), 0L);
    tools->colourSelected(Rgb{0.0, 1.0, 0.0});
    QTRY_VERIFY_WITH_TIMEOUT(green(mapView->grabFramebuffer()) > 20, 60000);
    tools->rangeSelected(5, 10);
    QCOMPARE(map->trajectories().shownPoints(job->id()), 6L);
    tools->rangeSelected(3, 0);
    QVERIFY(map->trajectories().shownPoints(job->id()) > 6);
    // File > Export map: its points as CSV (a header, a row per point shown)
    const QString csv = dir_.filePath("map_" + problem + ".csv");
    QVERIFY(saveChartCsv(map->chart(), csv));
    const QStringList rows = csvRows(csv);
    QVERIFY(!rows.isEmpty() && rows.first().startsWith("series,"));
    QVERIFY2(rows.size() > 20, qPrintable(QString("%1 rows").arg(rows.size())));
    tools->deleteSelected();
    QCOMPARE(map->trajectories().count(), before);
    // the click modes: pan / zoom starts nothing, fixed points searches from the point
    map->setClickMode(MapPanel::ClickMode::Navigate);
    QTest::mouseClick(mapView, Qt::LeftButton, Qt::NoModifier, mapView->rect().center());
    QCOMPARE(map->trajectories().count(), before);
    const int searches = map->searches();
    map->setClickMode(MapPanel::ClickMode::FixedPoint);
    QTest::mouseClick(mapView, Qt::LeftButton, Qt::NoModifier, mapView->rect().center());
    QCOMPARE(map->searches(), searches + 1);
    QCOMPARE(map->trajectories().count(), before);
    map->setClickMode(MapPanel::ClickMode::Trajectory);
  }

  // the control panel's Tools tab: Create on a map tool starts its job, on a chart tool opens its window
  void toolsTabCreatesTools() {
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("chaplygin_ball"))));
    ControlPanel* panel = window_->controlPanel();
    auto* create = panel->findChild<QPushButton*>("create");
    QVERIFY(create);
    const int searches = window_->mapPanel()->searches();
    panel->selectTool("fixedpoint");
    QTest::mouseClick(create, Qt::LeftButton);
    QCOMPARE(window_->mapPanel()->searches(), searches + 1);
    QTRY_COMPARE_WITH_TIMEOUT(window_->mapPanel()->fixedPointsFound(), 1, 60000);
    const auto before = window_->findChildren<ChartWindow*>().size();
    panel->selectTool("diagram");
    QTest::mouseClick(create, Qt::LeftButton);
    const auto charts = window_->findChildren<ChartWindow*>();
    QCOMPARE(charts.size(), before + 1);
    ChartWindow* chart = charts.back();
    QCOMPARE(chart->viewName(), std::string("bifurcation"));
    QSignalSpy finished(chart, &ChartWindow::finished);
    QVERIFY(chart->ready() || finished.wait(60000));
    QVERIFY(chart->ready());
    chart->close();
  }

  // the live 2D plot: the 3D view's running trajectory's states become points whenever the condition (the
  // time here) has moved by the period
  void livePlotIsFedByTheRun() {
    if (!window_->playing()) window_->togglePlay(); // it needs the 3D view's run going
    nlohmann::json doc = loadScene(defaultScenePath("chaplygin_ball")).document;
    doc["plot"] = {{"x", "t"}, {"y", "M1"}, {"period", 0.05}};
    QVERIFY(window_->runDocument(doc));
    PlotWindow* plot = window_->openPlotWindow(window_->scene()->plot);
    QVERIFY(plot);
    QCOMPARE(plot->dimensions(), 2);
    QTRY_VERIFY_WITH_TIMEOUT(plot->points(PlotWindow::kViewRun) > 10, 60000);
    const auto& t = plot->values(PlotWindow::kViewRun, 0);
    for (std::size_t k = 1; k < t.size(); ++k)
      QVERIFY(t[k] - t[k - 1] >= 0.05 - 1e-12); // the period, in time
    QVERIFY(QTest::qWaitForWindowExposed(plot->window()));
    QVERIFY(keep(plot->grab().toImage(), "window_plot.png"));
    const QImage img = plot->view()->grabFramebuffer();
    QVERIFY(img.width() > 0);
    window_->restart(); // a new run: the plot starts again
    QVERIFY(plot->points(PlotWindow::kViewRun) <= 1);
    plot->close();
  }

  // manual §2.4: a filter adds a window the base tools output into — every trajectory of the map feeds an
  // open 2D and 3D plot, each its own series, sampled on its own thread at exact multiples of the period
  void plotFiltersAreFedByEveryMapTrajectory() {
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("henon_heiles"))));
    const double energy = window_->scene()->model->parameters()["energy"];
    PlotView two = window_->scene()->plot;
    two.settings = {.axes = {"t", "x"}, .condition = "t", .period = 0.1, .maxPoints = 300};
    PlotView three = two;
    three.settings.axes = {"x", "y", "E"};
    PlotWindow* plot2 = window_->openPlotWindow(two);
    PlotWindow* plot3 = window_->openPlotWindow(three);
    QVERIFY(plot2 && plot3);
    QCOMPARE(plot3->dimensions(), 3);
    MapPanel* map = window_->mapPanel();
    // two trajectories started with the filters open (the scene's own may have finished before they opened:
    // a filter gets what the tools compute while it is open)
    QVERIFY(map->startAt(0.05, 0.1));
    QVERIFY(map->startAt(-0.1, 0.05));
    QCOMPARE(map->trajectories().count(), 3);
    std::vector<int> ids;
    for (Job* j : map->jobs().jobs())
      ids.push_back(j->id());
    ids.erase(ids.begin()); // the scene's own
    for (int id : ids) {
      QTRY_VERIFY_WITH_TIMEOUT(plot2->points(id) >= 300 && plot3->points(id) >= 300, 60000);
      QCOMPARE(plot2->points(id), 300L); // max points per trajectory
      const auto& t = plot2->values(id, 0);
      for (std::size_t k = 1; k < t.size(); ++k)
        QVERIFY(std::abs(t[k] - t[k - 1] - 0.1) < 1e-9); // exact multiples of the period
      for (double e : plot3->values(id, 2))
        QVERIFY(std::abs(e - energy) < 1e-9); // every point on its trajectory's energy level
    }
    QVERIFY(QTest::qWaitForWindowExposed(plot3->window()));
    QTRY_VERIFY2_WITH_TIMEOUT(inked(plot3->view()->grabFramebuffer()) > 400, "the 3D plot draws the points",
                              60000);
    QVERIFY(keep(plot3->grab().toImage(), "window_plot3d.png"));
    // selecting a trajectory in the tool manager emphasises it in the filters too (its points twice as big)
    const long plain = inked(plot2->view()->grabFramebuffer());
    window_->toolManager()->refresh();
    window_->toolManager()->select(ids.front());
    const auto emphasised = [&] { return inked(plot2->view()->grabFramebuffer()); };
    QTRY_VERIFY2_WITH_TIMEOUT(emphasised() > plain + 500, // 300 points drawn twice as big (many overlap)
                              qPrintable(QString("%1 -> %2 dark pixels").arg(plain).arg(emphasised())),
                              60000);
    map->removeJob(*map->jobs().jobs().back()); // its series goes from the filters
    QCOMPARE(plot2->points(ids.back()), 0L);
    QCOMPARE(plot2->points(ids.front()), 300L);
    plot2->close();
    plot3->close();
  }

  // issue 13: the map window colours each trajectory by its MEGNO <Y> (a MEGNO job under the trajectory's).
  // The standard map at K = 1.5: an orbit of the KAM island around the elliptic point (pi, 0) is
  // quasi-periodic
  // (<Y> -> 2, blue); one by the hyperbolic point (0, 0) is chaotic (<Y> ~ lambda N / 2, red).
  void mapColoursTrajectoriesByMegno() {
    nlohmann::json doc = loadScene(defaultScenePath("standard_map")).document;
    doc["parameters"]["K"] = 1.5;
    doc["initial"] = {{"map", {3.4415926535897931, 0.0}}};
    doc["megno"] = {{"time", 20000}};
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    QVERIFY(map->startAt(0.1, 0.1));
    std::vector<int> ids;
    for (Job* j : map->jobs().jobs())
      if (!j->parent() && dynamic_cast<PoincareTask*>(&j->task())) ids.push_back(j->id());
    QCOMPARE(ids.size(), std::size_t(2));
    const Rgb own = map->trajectories().shownColour(ids[1]);
    auto* box = map->findChild<QCheckBox*>("colour_by_megno");
    QVERIFY(box);
    box->click();
    QVERIFY(map->colourByMegno());
    for (int id : ids) // one MEGNO job under each trajectory, listed in the tool manager
      QCOMPARE(map->jobs().children(*map->jobs().find(id)).size(), std::size_t(1));
    QTRY_VERIFY_WITH_TIMEOUT(map->trajectories().megno(ids[0]) && map->trajectories().megno(ids[1]), 60000);
    const double torus = *map->trajectories().megno(ids[0]), chaos = *map->trajectories().megno(ids[1]);
    // each <Y> is said in the Results dock with its trajectory's number
    const int megnoJob = map->jobs().children(*map->jobs().find(ids[0])).front()->id();
    QVERIFY2(window_->results().contains(QString("MEGNO (tool #%1) of trajectory #%2: <Y> = %3")
                                             .arg(megnoJob)
                                             .arg(ids[0])
                                             .arg(torus, 0, 'g', 6)),
             qPrintable(window_->results()));
    QVERIFY2(std::abs(torus - 2) < 0.1, qPrintable(QString::number(torus)));
    QVERIFY2(chaos > 50, qPrintable(QString::number(chaos)));
    const Rgb blue = map->trajectories().shownColour(ids[0]), red = map->trajectories().shownColour(ids[1]);
    QVERIFY(blue == MapTrajectories::megnoColour(torus) && blue[2] > 2 * blue[0]);
    QVERIFY(red == MapTrajectories::megnoColour(chaos) && red[0] > 2 * red[2]);
    QVERIFY(QTest::qWaitForWindowExposed(map->window()));
    QVERIFY(keep(map->grab().toImage(), "window_map_megno.png"));
    // deleting a MEGNO job gives its trajectory back its own colour; so does switching the colouring off
    map->removeJob(*map->jobs().children(*map->jobs().find(ids[1])).front());
    QVERIFY(!map->trajectories().megno(ids[1]));
    QVERIFY(map->trajectories().shownColour(ids[1]) == own);
    box->click();
    QVERIFY(!map->colourByMegno());
    QVERIFY(map->trajectories().shownColour(ids[0]) != blue);
  }

  // The map holds still while the user clicks: a new trajectory does not rescale the axes (Fit does); the
  // cursor's map coordinates show beside the chart, and nothing of the cursor is drawn into it (or into an
  // export of it: File > Export map writes the framebuffer).
  void mapHoldsStillWhileClicking() {
    nlohmann::json doc = loadScene(defaultScenePath("standard_map")).document;
    doc["parameters"]["K"] = 1.5;
    doc["initial"] = {{"map", {3.4415926535897931, 0.0}}}; // an island round the elliptic point (pi, 0)
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    QtVtkWidget* view = map->view();
    QTRY_VERIFY_WITH_TIMEOUT(map->points() >= 300, 60000); // drained: in the chart's series
    view->grabFramebuffer(); // a frame: until the first click the axes follow the data
    const auto island = map->chart().ranges();
    QVERIFY2(island[1] - island[0] < 2, qPrintable(QString::number(island[1] - island[0])));
    QVERIFY(map->startAt(0.1, 0.1)); // the chaotic sea, all over the torus
    const long before = map->points();
    QTRY_VERIFY_WITH_TIMEOUT(map->points() >= before + 1500, 60000);
    view->grabFramebuffer(); // the frame that would rescale to the new points: it must not
    QVERIFY(map->chart().ranges() == island);
    auto* fit = map->findChild<QPushButton*>("fit_map");
    QVERIFY(fit);
    fit->click();
    view->grabFramebuffer();
    const auto all = map->chart().ranges();
    QVERIFY2(all[1] - all[0] > 5, qPrintable(QString::number(all[1] - all[0])));
    // the chaotic sea covers the torus: p over all of [0, 2 pi) (the island's p wraps too, so its automatic
    // axis may be as tall, with nice numbers, as the fitted one)
    QVERIFY2(all[2] < 0.05 && all[3] > 6.25, qPrintable(QString("p from %1 to %2").arg(all[2]).arg(all[3])));
    // the cursor over the chaotic trajectory's first point: its coordinates beside the chart, none in it
    map->stopAll();
    const auto running = [&] {
      const std::vector<Job*> jobs = map->jobs().jobs();
      return std::any_of(jobs.begin(), jobs.end(), [](const Job* j) { return j->running(); });
    };
    QTRY_VERIFY_WITH_TIMEOUT(!running(), 60000);
    while (map->drain()) { // a drain takes what a few milliseconds allow
    }
    const QImage still = view->grabFramebuffer(); // everything drawn: nothing more comes
    const double dpr = view->devicePixelRatioF();
    const QPoint c = view->rect().center();
    double x0, y0, x1, y1; // toChart is linear: two pixels give the point's
    QVERIFY(map->chart().toChart(c.x() * dpr, (view->height() - c.y()) * dpr, x0, y0));
    QVERIFY(map->chart().toChart((c.x() + 20) * dpr, (view->height() - c.y() + 20) * dpr, x1, y1));
    const QPoint onPoint(qRound(c.x() + 20 * (0.1 - x0) / (x1 - x0)),
                         qRound(c.y() - 20 * (0.1 - y0) / (y1 - y0)));
    QVERIFY(view->rect().contains(onPoint));
    QTest::mouseMove(view, onPoint);
    auto* label = map->findChild<QLabel*>("cursor_position");
    QVERIFY(label);
    // the move has been handled (the label says where), so a cursor drawn into the chart would be in its
    // frame
    QTRY_VERIFY2_WITH_TIMEOUT(label->text().contains(" = 0.1") || label->text().contains(" = 0.09"),
                              qPrintable(label->text()), 60000);
    QVERIFY(view->grabFramebuffer() == still);
    QVERIFY(keep(map->grab().toImage(), "window_map_held.png"));
    // the wheel zooms in, and the zoom stays
    QWheelEvent wheel(QPointF(onPoint), view->mapToGlobal(QPointF(onPoint)), QPoint(), QPoint(0, 120),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(view, &wheel);
    view->grabFramebuffer();
    const auto zoomed = map->chart().ranges();
    QVERIFY2(zoomed[1] - zoomed[0] < 0.95 * (all[1] - all[0]),
             qPrintable(QString::number(zoomed[1] - zoomed[0])));
    map->drain();
    view->grabFramebuffer();
    QVERIFY(map->chart().ranges() == zoomed);
  }

  // A tool's result stays in the Results dock when the status bar's message is gone; Clear empties it.
  void resultsAreKept() {
    nlohmann::json doc = loadScene(defaultScenePath("standard_map")).document;
    doc["parameters"]["K"] = 1.5;
    QVERIFY(window_->runDocument(doc));
    auto* pane = window_->findChild<QDockWidget*>("results_dock");
    QVERIFY(pane && pane->isVisible());
    window_->mapPanel()->searchFixedPointAt(3.1, 0.05);
    QTRY_VERIFY_WITH_TIMEOUT(window_->results().contains("fixed point ("), 60000);
    window_->statusBar()->clearMessage();
    // the message is gone, and whatever reacts to that (queued) has run
    QTRY_VERIFY_WITH_TIMEOUT(window_->statusBar()->currentMessage().isEmpty(), 60000);
    QCoreApplication::sendPostedEvents();
    QVERIFY2(window_->results().contains("elliptic; multipliers"), qPrintable(window_->results()));
    QVERIFY(keep(window_->grab().toImage(), "window_results.png"));
    window_->findChild<QPushButton*>("clear_results")->click();
    QVERIFY(window_->results().isEmpty());
  }

  // The tool manager's rows tell trajectories apart (start point, colour swatch), its buttons are enabled
  // only when they apply, Delete asks first, and the Windows menu shows a closed dock again.
  void toolManagerRowsButtonsAndDelete() {
    nlohmann::json doc = loadScene(defaultScenePath("standard_map")).document;
    doc["parameters"]["K"] = 1.5;
    doc["poincare"] = {{"points", 1e12}}; // runs until stopped
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    QVERIFY(map->startAt(0.25, 0.5));
    ToolManager* tools = window_->toolManager();
    const int id = map->jobs().jobs().back()->id();
    tools->refresh();
    tools->select(id);
    QTreeWidgetItem* row = tools->tree()->currentItem();
    QVERIFY(row);
    QCOMPARE(row->text(4), QString("(0.25, 0.5)"));
    QVERIFY(!row->icon(1).isNull());
    const auto button = [&](const char* name) { return tools->findChild<QPushButton*>(name); };
    QVERIFY(button("stop")->isEnabled());
    QVERIFY(!button("start")->isEnabled());
    QVERIFY(!button("edit")->isEnabled());
    QVERIFY(!button("find parent")->isEnabled());
    QVERIFY(button("colour…")->isEnabled());
    tools->stopSelected();
    QVERIFY(!button("stop")->isEnabled());
    QVERIFY(button("start")->isEnabled() && button("edit")->isEnabled());
    QVERIFY(button("stop")->toolTip().contains("not running"));
    // Delete asks: No keeps the tool, Yes deletes it
    answerNextQuestion(QMessageBox::No);
    button("delete")->click();
    QVERIFY(map->jobs().find(id));
    answerNextQuestion(QMessageBox::Yes);
    button("delete")->click();
    QVERIFY(!map->jobs().find(id));
    tools->refresh();
    QVERIFY(!tools->selected() && !button("delete")->isEnabled());
    // a closed dock comes back from the Windows menu
    auto* dock = window_->findChild<QDockWidget*>("tools");
    dock->close();
    QVERIFY(!dock->isVisible());
    QMenu* windows = nullptr;
    for (QAction* a : window_->menuBar()->actions())
      if (a->text() == "&Windows") windows = a->menu();
    QVERIFY(windows);
    QAction* reopen = nullptr;
    for (QAction* a : windows->actions())
      if (a->text() == "Tool manager") reopen = a;
    QVERIFY(reopen);
    reopen->trigger();
    QVERIFY(dock->isVisible());
  }

  // Help lists the shortcuts of every action and leads to the guide; the File menu shows its keys
  void helpListsTheShortcutsAndTheGuide() {
    QMenu *help = nullptr, *file = nullptr;
    for (QAction* a : window_->menuBar()->actions()) {
      if (a->text() == "&Help") help = a->menu();
      if (a->text() == "&File") file = a->menu();
    }
    QVERIFY(help && file);
    QStringList items;
    for (QAction* a : help->actions())
      items << a->text();
    QVERIFY2(items.contains("Guide") && items.contains("Keyboard shortcuts…"), qPrintable(items.join(", ")));
    const QString keys = window_->shortcutsText();
    for (const char* expected :
         {"Ctrl+O\tOpen scene…", "Space\t", "Ctrl+Shift+S\tSave scene as…", "Ctrl+Shift+R\t"})
      QVERIFY2(keys.contains(expected), qPrintable(keys));
    for (QAction* a : file->actions())
      if (a->text() == "Open scene…") QCOMPARE(a->shortcut(), QKeySequence("Ctrl+O"));
    QVERIFY(QFileInfo::exists(MainWindow::guideLocation()));
  }

  // Help > About names the window's GL renderer at once and the headless one when `rollviz info` answers
  // (a process of its own), without blocking the window meanwhile
  void aboutNamesTheRenderers() {
    QMenu* help = nullptr;
    for (QAction* a : window_->menuBar()->actions())
      if (a->text() == "&Help") help = a->menu();
    QVERIFY(help);
    QVERIFY(!help->actions().isEmpty());
    help->actions().first()->trigger();
    auto* about = window_->findChild<AboutDialog*>("about");
    QVERIFY(about && about->isVisible());
    auto* label = about->findChild<QLabel*>();
    QVERIFY(label);
    window_->view()->makeCurrent();
    const QString screen =
        QString::fromLatin1(
            reinterpret_cast<const char*>(window_->view()->context()->functions()->glGetString(GL_RENDERER)))
            .toHtmlEscaped();
    window_->view()->doneCurrent();
    QVERIFY2(label->text().contains(screen), qPrintable(screen));
    QVERIFY(label->text().contains("GL_RENDERER"));
    if (!qEnvironmentVariableIsEmpty("ROLLVIZ_EXE")) {
      QTRY_VERIFY_WITH_TIMEOUT(label->text().contains("backend"), 60000);
      QVERIFY2(label->text().contains("egl"), qPrintable(label->text()));
      if (screen.contains("llvmpipe")) {
        QVERIFY(label->text().contains("rendering on the CPU"));
      }
    }
    QVERIFY(keep(about->grab().toImage(), "window_about.png"));
    about->close();
    QTRY_VERIFY_WITH_TIMEOUT(!window_->findChild<AboutDialog*>("about"), 60000);
  }

  // VTK's windows ask for 8x multisampling, which makes a chart's frame about 5x dearer on a CPU rasteriser:
  // there the GUI's charts draw without it (on a GPU they keep VTK's default), while the 3D view has what
  // the scene asks for (view.multisamples)
  void multisamplingFollowsTheRenderer() {
    window_->view()->makeCurrent();
    const std::string renderer =
        reinterpret_cast<const char*>(window_->view()->context()->functions()->glGetString(GL_RENDERER));
    window_->view()->doneCurrent();
    const int chart = window_->mapPanel()->view()->renderWindow()->GetMultiSamples();
    QCOMPARE(chart, isSoftwareRenderer(renderer)
                        ? 0
                        : vtkOpenGLRenderWindow::GetGlobalMaximumNumberOfMultiSamples());
    nlohmann::json doc = loadScene(defaultScenePath("ellipsoid_on_plane")).document;
    doc["view"]["multisamples"] = 4;
    QVERIFY(window_->runDocument(doc));
    QCOMPARE(window_->view()->renderWindow()->GetMultiSamples(), 4);
  }

  // manual §2.4.3: a running continuation feeds the multipliers filter, a point whenever its parameter moved
  // by the period. The standard map's point (pi, 0) has the trace 2 - K: multipliers on the unit circle with
  // real part (2 - K) / 2 while K < 4.
  void multipliersFilterFollowsAContinuation() {
    nlohmann::json doc = loadScene(defaultScenePath("standard_map")).document;
    doc["parameters"]["K"] = 1.5;
    doc["fixedpoint"] = {{"guess", {3.1, 0.05}}};
    doc["continuation"] = {{"parameter", "K"}, {"to", 3.5}, {"step", 0.05}};
    QVERIFY(window_->runDocument(doc));
    MultipliersWindow* w = window_->openMultipliersWindow();
    w->setPeriod(0.2);
    MapPanel* map = window_->mapPanel();
    map->startContinuation();
    Job* job = map->jobs().jobs().back();
    QTRY_VERIFY_WITH_TIMEOUT(!job->running(), 60000);
    map->drain();
    const auto& outputs = w->outputs(job->id());
    const auto& parameters = w->parameters(job->id());
    QCOMPARE(outputs.size(), std::size_t(11)); // K = 1.5, 1.7, ..., 3.5
    for (std::size_t k = 0; k < outputs.size(); ++k) {
      QCOMPARE(outputs[k].size(), std::size_t(2));
      const double K = parameters[k];
      QVERIFY(std::abs(K - (1.5 + 0.2 * static_cast<double>(k))) < 1e-9); // steps of 0.05, every fourth
      for (const auto& m : outputs[k]) {
        QVERIFY(std::abs(std::abs(m) - 1) < 1e-8);
        QVERIFY(std::abs(m.real() - (2 - K) / 2) < 1e-7);
      }
    }
    // a window opened later gets the family computed so far
    MultipliersWindow* later = window_->openMultipliersWindow();
    QCOMPARE(later->points(), 2L * 41); // period 0: every point, K = 1.5, 1.55, ..., 3.5
    // its outcome reaches the Results dock: how many points, over which range of the parameter
    map->drain();
    const QString ended =
        QString("Continuation (tool #%1) ended: 41 points, K from 1.5 to 3.5").arg(job->id());
    QTRY_VERIFY2_WITH_TIMEOUT(window_->results().contains(ended), qPrintable(window_->results()), 60000);
    QVERIFY(QTest::qWaitForWindowExposed(w->window()));
    QTRY_VERIFY_WITH_TIMEOUT(inked(w->view()->grabFramebuffer()) > 2000, 60000); // axes, unit circle, points
    QVERIFY(keep(w->grab().toImage(), "window_multipliers.png"));
    // Edit properties of the stopped continuation (tool manager): a larger step from the control panel; it
    // starts again with it, its old output gone from the filter
    auto* step = qobject_cast<QDoubleSpinBox*>(window_->controlPanel()->form("continuation")->editor("step"));
    QVERIFY(step);
    step->setValue(0.25);
    ToolManager* tools = window_->toolManager();
    tools->refresh();
    tools->select(job->id());
    tools->editSelected();
    QCOMPARE(w->outputs(job->id()).size(), std::size_t(0));
    tools->continueSelected();
    QTRY_VERIFY_WITH_TIMEOUT(!job->running(), 60000);
    map->drain();
    QCOMPARE(w->outputs(job->id()).size(), std::size_t(9)); // K = 1.5, 1.75, ..., 3.5
    QVERIFY(std::abs(w->parameters(job->id()).back() - 3.5) < 1e-12);
    map->removeJob(*job);
    QCOMPARE(w->points(), 0L);
    w->close();
    later->close();
  }

  // Branch switching in the GUI (issue 41): Tools > Follow the doubled family lists the period doublings the
  // last continuation located; an entry continues the 2-cycle born there as a new job. The Henon map
  // x' = 1 - a x^2 + y, y' = b x doubles at a = 3 (1 - b)^2 / 4, and its 2-cycle's x solve
  // a x^2 - (1 - b) x + (1 - b)^2 / a - 1 = 0.
  void toolsMenuFollowsTheDoubledFamilyFromALocatedDoubling() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_map")).document;
    doc["parameters"]["a"] = 0.2;
    doc["fixedpoint"] = {{"guess", {1.09, 0.33}}};
    doc["continuation"] = {{"parameter", "a"}, {"to", 0.6}, {"step", 0.02}};
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    QMenu* menu = nullptr;
    for (QMenu* m : window_->findChildren<QMenu*>())
      if (m->title() == "Follow the doubled family") menu = m;
    QVERIFY(menu);
    emit menu->aboutToShow(); // nothing located yet: one disabled entry saying why
    QCOMPARE(menu->actions().size(), qsizetype(1));
    QVERIFY(!menu->actions()[0]->isEnabled());
    map->startContinuation();
    Job* parent = map->jobs().jobs().back();
    QTRY_VERIFY_WITH_TIMEOUT(!parent->running(), 60000);
    map->drain();
    const double b = 0.3, doubling = 3 * (1 - b) * (1 - b) / 4;
    QCOMPARE(map->locatedDoublings().size(), std::size_t(1));
    QVERIFY(std::abs(map->locatedDoublings()[0].section('=', 1).trimmed().toDouble() - doubling) < 1e-8);
    emit menu->aboutToShow();
    QCOMPARE(menu->actions().size(), qsizetype(1));
    QVERIFY(menu->actions()[0]->isEnabled());
    QVERIFY(menu->actions()[0]->text().contains(map->locatedDoublings()[0]));
    menu->actions()[0]->trigger();
    Job* doubled = map->jobs().jobs().back();
    QVERIFY(doubled != parent);
    QTRY_VERIFY_WITH_TIMEOUT(!doubled->running(), 60000);
    map->drain();
    const auto points = map->toolPoints(doubled->id());
    QVERIFY(points.size() > 2);
    // the family ends at continuation.to: a point of the closed-form 2-cycle at a = 0.6, not the fixed point
    const double a = 0.6, root = std::sqrt(4 * a - 3 * (1 - b) * (1 - b));
    const double x = points.back().first;
    QVERIFY(std::min(std::abs(x - (1 - b + root) / (2 * a)), std::abs(x - (1 - b - root) / (2 * a))) < 1e-8);
    // y1 = b x2, and the cycle's two x sum to (1 - b) / a
    QVERIFY(std::abs(points.back().second - b * ((1 - b) / a - x)) < 1e-8);
  }

  // manual §2.4.4: on the bifurcation diagram each trajectory of the map is a point of the plane of first
  // integrals ((n, h) for the Chaplygin ball), following an edit of its energy
  void diagramWindowMarksTheTrajectories() {
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("chaplygin_ball"))));
    ChartWindow* chart = window_->openChart("bifurcation");
    QTRY_VERIFY_WITH_TIMEOUT(chart->ready(), 60000);
    MapPanel* map = window_->mapPanel();
    QVERIFY(map->startAt(0.3, 0.2));
    map->drain();
    QCOMPARE(chart->marks().size(), std::size_t(2));
    const Model& model = *window_->scene()->model;
    const auto integrals = model.integrals(window_->scene()->initialState.data()); // E, H, geometric, n
    QVERIFY(std::abs(chart->marks()[0].x - integrals[3]) < 1e-12);
    QVERIFY(std::abs(chart->marks()[0].y - integrals[0]) < 1e-12);
    QVERIFY(std::abs(chart->marks()[1].y - integrals[0]) < 1e-9); // the same energy, another n
    // the second trajectory edited to another energy: its mark moves to it
    Job* second = map->jobs().jobs().back();
    second->edit([&](Task& t) {
      auto& p = static_cast<PoincareTask&>(t);
      RunSpec s = p.spec();
      s.modelParameters.set("energy", 0.6);
      p.edit(s, p.settings());
    });
    map->drain();
    QVERIFY(std::abs(chart->marks()[1].y - 0.6) < 1e-9);
    QVERIFY(QTest::qWaitForWindowExposed(chart->window()));
    QTRY_VERIFY_WITH_TIMEOUT(inked(chart->view()->grabFramebuffer()) > 2000, 60000); // branches and marks
    QVERIFY(keep(chart->grab().toImage(), "window_diagram_marks.png"));
    // the other diagram of the problem (Diagram name): the plane (c, h), the area constant c = 0.3 of the
    // scene for both trajectories
    ChartWindow* ch = window_->openChart("bifurcation", "ch");
    QTRY_VERIFY_WITH_TIMEOUT(ch->ready(), 60000);
    QCOMPARE(ch->marks().size(), std::size_t(2));
    QVERIFY(std::abs(ch->marks()[0].x - 0.3) < 1e-9 && std::abs(ch->marks()[1].x - 0.3) < 1e-9);
    QVERIFY(std::abs(ch->marks()[1].y - 0.6) < 1e-9);
    ch->close();
    map->removeJob(*second);
    map->drain();
    QCOMPARE(chart->marks().size(), std::size_t(1));
    chart->close();
  }

  // a 3D map shows Map (its projection, the map window) and Map3D (a window fed with the same points)
  void map3DWindowFollowsTheTrajectories() {
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("ellipsoid_on_plane"))));
    QWidget* w = window_->mapPanel()->openMap3D();
    QVERIFY(w);
    QTRY_VERIFY_WITH_TIMEOUT(window_->mapPanel()->map3DPoints() > 10, 60000);
    QVERIFY(QTest::qWaitForWindowExposed(w->window()));
    auto* view = w->findChild<QtVtkWidget*>();
    QVERIFY(view);
    const auto dark = [&] {
      return countPixels(view->grabFramebuffer(), [](const QColor& c) { return c.lightness() < 200; });
    };
    QTRY_VERIFY2_WITH_TIMEOUT(dark() > 300, qPrintable(QString("dark pixels %1").arg(dark())), 60000);
    QVERIFY(keep(view->grabFramebuffer(), "window_map3d.png"));
    w->close();
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("henon_heiles"))));
    QVERIFY(!window_->mapPanel()->openMap3D()); // a 2D map has no Map3D window
  }

  void runningTrajectoriesAreSavedOnCloseAndContinuedAtTheNextStart() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_heiles")).document;
    doc["poincare"]["points"] = 1000000; // still running when the window closes
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("henon_heiles"))));
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    QVERIFY(map->startAt(0.05, 0.1));
    QTRY_VERIFY_WITH_TIMEOUT(map->points() > 100, 60000);
    QFile::remove(MainWindow::savedJobsPath());
    window_->close(); // closeEvent saves what runs
    QVERIFY(QFile::exists(MainWindow::savedJobsPath()));
    map->drain();
    const long shown = map->points();
    for (Job* j : map->jobs().jobs())
      QVERIFY(!j->running());
    // the next start: another scene first, then the saved trajectories under their own
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("chaplygin_ball"))));
    window_->show();
    QCOMPARE(window_->resumeSavedJobs(), 2);
    QVERIFY(!QFile::exists(MainWindow::savedJobsPath())); // offered once
    QCOMPARE(window_->scene()->model->info().id, std::string("henon_heiles"));
    QCOMPARE(map->trajectories().count(),
             2); // the two continued (the scene's own among them: not started twice)
    map->drain();
    QVERIFY2(map->points() >= shown, qPrintable(QString("%1 < %2").arg(map->points()).arg(shown)));
    QTRY_VERIFY_WITH_TIMEOUT(map->points() > shown + 100, 60000); // they go on
    int running = 0;
    for (Job* j : map->jobs().jobs())
      running += j->running();
    QCOMPARE(running, 2);
    QCOMPARE(window_->resumeSavedJobs(), 0); // nothing left
    map->stopAll();
  }

  // A fixed point found by a Shift+click shows in the Multipliers window (also one opened later), with its
  // type and multipliers under the chart. The standard map's point (pi, 0) at K = 1.5 is elliptic with the
  // trace 2 - K: multipliers on the unit circle with real part (2 - K) / 2 = 0.25.
  void aFixedPointFoundShowsInTheMultipliersWindow() {
    nlohmann::json doc = loadScene(defaultScenePath("standard_map")).document;
    doc["parameters"]["K"] = 1.5;
    QVERIFY(window_->runDocument(doc));
    MultipliersWindow* w = window_->openMultipliersWindow();
    MapPanel* map = window_->mapPanel();
    map->searchFixedPointAt(3.1, 0.05);
    Job* search = map->jobs().jobs().back();
    QTRY_VERIFY_WITH_TIMEOUT(!search->running(), 60000);
    map->drain();
    const auto check = [&](MultipliersWindow* window) {
      const auto& outputs = window->outputs(search->id());
      QCOMPARE(outputs.size(), std::size_t(1));
      QCOMPARE(outputs[0].size(), std::size_t(2));
      for (const auto& m : outputs[0]) {
        QVERIFY(std::abs(std::abs(m) - 1) < 1e-8);
        QVERIFY(std::abs(m.real() - 0.25) < 1e-7);
      }
      QVERIFY2(window->caption().contains("elliptic"), qPrintable(window->caption()));
    };
    check(w);
    // on the map the point found has a marker of its own: one large cross at (pi, 0)
    int crosses = 0;
    vtkChartXY* xy = map->chart().chart();
    for (vtkIdType i = 0; i < xy->GetNumberOfPlots(); ++i)
      if (auto* p = vtkPlotPoints::SafeDownCast(xy->GetPlot(i));
          p && p->GetMarkerStyle() == vtkPlotPoints::CROSS && p->GetInput() &&
          p->GetInput()->GetNumberOfRows() == 1) {
        ++crosses;
        QVERIFY(std::abs(p->GetInput()->GetValue(0, 0).ToDouble() - M_PI) < 1e-8);
        QVERIFY(std::abs(p->GetInput()->GetValue(0, 1).ToDouble()) < 1e-8);
      }
    QCOMPARE(crosses, 1);
    MultipliersWindow* later = window_->openMultipliersWindow();
    check(later);
    QVERIFY(QTest::qWaitForWindowExposed(w->window()));
    QTRY_VERIFY_WITH_TIMEOUT(inked(w->view()->grabFramebuffer()) > 1500, 60000);
    QVERIFY(keep(w->grab().toImage(), "window_multipliers_fixed_point.png"));
    // deleting the search takes its point away
    map->removeJob(*search);
    QCOMPARE(w->points(), 0L);
    w->close();
    later->close();
  }

  // The Results dock goes into the saved scene ("results": its lines) and comes back when it is opened.
  void resultsAreSavedWithTheScene() {
    nlohmann::json doc = loadScene(defaultScenePath("standard_map")).document;
    doc["parameters"]["K"] = 1.5;
    QVERIFY(window_->runDocument(doc));
    window_->findChild<QPushButton*>("clear_results")->click();
    window_->mapPanel()->searchFixedPointAt(3.1, 0.05);
    QTRY_VERIFY_WITH_TIMEOUT(window_->results().contains("fixed point ("), 60000);
    const QString path = dir_.filePath("with-results.json");
    QVERIFY(window_->saveSceneTo(path));
    const Scene saved = loadScene(path.toStdString());
    QVERIFY(saved.document.contains("results"));
    bool found = false;
    for (const auto& line : saved.document["results"])
      found = found || line.get<std::string>().find("elliptic; multipliers") != std::string::npos;
    QVERIFY(found);
    window_->findChild<QPushButton*>("clear_results")->click();
    QVERIFY(window_->openScene(path));
    QVERIFY2(window_->results().contains("elliptic; multipliers"), qPrintable(window_->results()));
  }

  // The toolbar and the settings panel show the same view settings after each edit, a colour change keeps
  // the toolbar's style, and a new scene shows its own; the transparency slider says its number.
  void toolbarAndSettingsAgree() {
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("chaplygin_ball"))));
    auto* style = window_->findChild<QComboBox*>("surface_style");
    auto* axes = window_->findChild<QComboBox*>("axes_style");
    QVERIFY(style && axes);
    VisualizerSettings* settings = window_->settings();
    QCOMPARE(axes->currentIndex(), settings->axesStyleBox()->currentIndex());
    axes->setCurrentIndex(2); // box axes from the toolbar
    QCOMPARE(settings->axesStyleBox()->currentIndex(), 2);
    QVERIFY(window_->visual()->options().axes.style == AxesOptions::Style::Box);
    settings->axesStyleBox()->setCurrentIndex(1); // normal from the settings
    QCOMPARE(axes->currentIndex(), 1);
    style->setCurrentIndex(1); // grid
    settings->selectObject("ball");
    settings->pickColour({0.2, 0.8, 0.2}); // a colour edit keeps the style the toolbar set
    QVERIFY(window_->visual()->options().object("ball").style == SurfaceStyle::Grid);
    QCOMPARE(style->currentIndex(), 1);
    QCOMPARE(axes->currentIndex(), 1);
    settings->transparencySlider()->setValue(30);
    auto* percent = settings->findChild<QLabel*>("transparency_value");
    QVERIFY(percent);
    QCOMPARE(percent->text(), QString("30 %"));
    QVERIFY(QTest::qWaitForWindowExposed(window_));
    QVERIFY(keep(window_->grab().toImage(), "window_grid_style.png"));
    // another scene: its own appearance, shown alike
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("chaplygin_ball"))));
    QCOMPARE(style->currentIndex(), 0);
    QCOMPARE(axes->currentIndex(), 0);
    QCOMPARE(settings->axesStyleBox()->currentIndex(), 0);
  }

  // Issue 43, item 1: Apply keeps the map when nothing that defines it changed (a new number of points counts
  // for the next trajectories only); a change of the map asks first (No keeps everything), and Edit > Undo
  // brings the replaced map back, every trajectory with its points.
  void applyKeepsTheMapAndUndoBringsItBack() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_heiles")).document;
    doc["poincare"]["points"] = 300;
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    QVERIFY(map->startAt(0.05, 0.1));
    QVERIFY(map->startAt(0.1, -0.1));
    const std::vector<int> ids = map->sceneJobs();
    QCOMPARE(ids.size(), 3u);
    QVERIFY(finishDrawing(map, ids, 300));
    const auto first = map->trajectories().points(ids[1]);
    // Apply with nothing changed: the same jobs, nothing asked
    QVERIFY(window_->applyDocument(window_->controlPanel()->editedDocument()));
    QCOMPARE(map->sceneJobs(), ids);
    // another number of points: the map stays, the next click makes that many
    doc["poincare"]["points"] = 100;
    QVERIFY(window_->applyDocument(doc));
    QCOMPARE(map->sceneJobs(), ids);
    QVERIFY(map->startAt(0.0, 0.05));
    const int fourth = map->sceneJobs().back();
    QVERIFY(finishDrawing(map, {fourth}, 100));
    // another energy replaces the map: asked first
    doc["parameters"]["energy"] = 0.1;
    answerNextQuestion(QMessageBox::No);
    QVERIFY(!window_->applyDocument(doc));
    QCOMPARE(map->trajectories().count(), 4);
    QCOMPARE(window_->scene()->model->parameters()["energy"], 0.125);
    answerNextQuestion(QMessageBox::Yes);
    QVERIFY(window_->applyDocument(doc));
    QCOMPARE(map->trajectories().count(), 1);
    QCOMPARE(window_->scene()->model->parameters()["energy"], 0.1);
    QVERIFY2(window_->undoText().contains("4 trajectories"), qPrintable(window_->undoText()));
    // Undo (the Edit menu's action, Ctrl+Z): the energy and the four trajectories with their points
    auto* undo = window_->findChild<QAction*>("undo");
    QVERIFY(undo && undo->isEnabled());
    QCOMPARE(undo->shortcut(), QKeySequence(QKeySequence::Undo));
    undo->trigger();
    QCOMPARE(window_->scene()->model->parameters()["energy"], 0.125);
    QCOMPARE(map->trajectories().count(), 4);
    const std::vector<int> back = map->sceneJobs();
    QVERIFY(map->trajectories().points(back[1]) == first);
    QCOMPARE(map->trajectories().points(back[3]).first.size(), 100u);
    // a deleted trajectory comes back too (Delete in the tool manager)
    ToolManager* tools = window_->toolManager();
    tools->refresh();
    tools->select(back[1]);
    tools->deleteSelected();
    QCOMPARE(map->trajectories().count(), 3);
    QVERIFY2(window_->undoText().contains("1 trajectory"), qPrintable(window_->undoText()));
    QVERIFY(window_->undo());
    QCOMPARE(map->trajectories().count(), 4);
    QVERIFY(map->trajectories().points(back[1]) == first); // under its number (issue 61 (3))
    // Redo (Edit > Redo, Ctrl+Shift+Z) deletes it again, Undo brings it back once more
    auto* redo = window_->findChild<QAction*>("redo");
    QVERIFY(redo && redo->isEnabled());
    QCOMPARE(redo->shortcut(), QKeySequence(QKeySequence::Redo));
    QVERIFY2(window_->redoText().contains("1 trajectory"), qPrintable(window_->redoText()));
    redo->trigger();
    QCOMPARE(map->trajectories().count(), 3);
    QVERIFY(!redo->isEnabled());
    QVERIFY(window_->undo());
    QCOMPARE(map->trajectories().count(), 4);
    QVERIFY(map->trajectories().points(back[1]) == first); // under its number (issue 61 (3))
    QVERIFY(redo->isEnabled());                            // the delete, to do again
    // a new change forgets what was undone
    tools->refresh();
    tools->select(map->sceneJobs().front());
    tools->deleteSelected();
    QVERIFY(!redo->isEnabled());
    QVERIFY(!window_->redo());
  }

  // Issue 61 (4): a click on the map of a flow without map coordinates (Lorenz) starts a trajectory on the
  // section at the point clicked (the map's axes and the section's variable set, the rest the scene's state)
  // and says so -- it used to fail with "lorenz has no map coordinates".
  void aClickOnLorenzsMapStartsATrajectoryOnTheSection() {
    nlohmann::json doc = loadScene(defaultScenePath("lorenz")).document;
    doc["poincare"]["points"] = 30;
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    const int before = map->trajectories().count();
    QVERIFY(map->startAt(-6.5, 3.25));
    QCOMPARE(map->trajectories().count(), before + 1);
    const int id = map->sceneJobs().back();
    QVERIFY2(window_->results().contains("x = -6.5, y = 3.25, z = 27 (the section)"),
             qPrintable(window_->results()));
    QVERIFY(finishDrawing(map, {id}, 30)); // it crosses the section: its points are drawn
    const auto points = map->trajectories().points(id);
    QCOMPARE(points.first.size(), std::size_t(30));
  }

  // Issue 61 (4): Apply with nothing changed leaves the camera the user turned where it is; a change of the
  // view's own settings places it anew.
  void applyLeavesTheUsersCameraWhereItIs() {
    nlohmann::json doc = loadScene(defaultScenePath("chaplygin_ball")).document;
    doc["view"]["camera"]["follow"] = false;
    QVERIFY(window_->runDocument(doc));
    vtkCamera* cam = window_->visual()->renderer()->GetActiveCamera();
    cam->Azimuth(40);
    cam->Elevation(15);
    cam->OrthogonalizeViewUp();
    std::array<double, 6> turned{};
    cam->GetPosition(&turned[0]);
    cam->GetFocalPoint(&turned[3]);
    QVERIFY(window_->applyDocument(window_->scene()->document)); // nothing changed
    vtkCamera* now = window_->visual()->renderer()->GetActiveCamera();
    std::array<double, 6> kept{};
    now->GetPosition(&kept[0]);
    now->GetFocalPoint(&kept[3]);
    QVERIFY(kept == turned);
    nlohmann::json other = window_->scene()->document;
    other["view"]["camera"]["azimuth"] = 75; // the view's settings changed: the camera placed as they say
    QVERIFY(window_->applyDocument(other));
    now = window_->visual()->renderer()->GetActiveCamera();
    now->GetPosition(&kept[0]);
    QVERIFY(std::abs(kept[0] - turned[0]) + std::abs(kept[1] - turned[1]) > 1e-6);
  }

  // Issue 61 (4): Undo (and Redo) bring the map back with the user's zoom.
  void undoKeepsTheMapsZoom() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_heiles")).document;
    doc["poincare"]["points"] = 50;
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    const std::array<double, 4> zoom{-0.11, 0.13, -0.07, 0.09};
    map->setMapRanges(zoom);
    QVERIFY(map->chart().rangesHeld());
    doc["parameters"]["energy"] = 0.1;
    QVERIFY(window_->applyDocument(doc)); // another energy: another map, its axes following its points
    QVERIFY(!map->chart().rangesHeld());
    QVERIFY(window_->undo());
    QVERIFY(map->chart().rangesHeld());
    QVERIFY(map->chart().ranges() == zoom);
    QVERIFY(window_->redo()); // the other energy's map, not zoomed
    QVERIFY(!map->chart().rangesHeld());
  }

  // Issue 63: File > Export web page writes the motion and the map as a self-contained page, off the GUI
  // thread (a job of the tool manager), and says so in the Results dock.
  void theMotionAndTheMapExportAsAWebPage() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_heiles")).document;
    doc["poincare"]["points"] = 100;
    doc["video"] = {{"duration", 1}, {"fps", 10}};
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    QVERIFY(finishDrawing(map, map->sceneJobs(), 100));
    QAction* item = nullptr;
    for (QAction* a : window_->findChildren<QAction*>())
      if (a->text() == "Export web page…") item = a;
    QVERIFY(item); // the menu's entry (its dialog asks for the file, then calls exportPageTo)
    const QString path = dir_.filePath("motion.html");
    const int id = window_->exportPageTo(path);
    QVERIFY(id >= 0);
    QVERIFY(map->jobs().find(id)); // listed in the tool manager
    QTRY_VERIFY2_WITH_TIMEOUT(window_->results().contains("wrote the web page"),
                              qPrintable(window_->results()), 60000);
    QFile file(path);
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QString page = QString::fromUtf8(file.readAll());
    const auto begin = page.indexOf("id=\"rollviz-data\">") + 18, end = page.indexOf("</script>", begin);
    const auto data = nlohmann::json::parse(page.mid(begin, end - begin).toStdString());
    QCOMPARE(data["frames"].get<int>(), 11);
    QCOMPARE(data["map"]["series"].size(), std::size_t(1));         // the scene's trajectory on the map
    QVERIFY(QFileInfo(path).dir().entryList({"*.tmp*"}).isEmpty()); // nothing half-written beside it
  }

  // Issue 43, sessions: a session saved and opened (over another scene) gives the same trajectories, point
  // for point, and the Results log; a finished trajectory then goes on with Start, bit for bit the run of the
  // longer length; the session file is also a scene for the command line.
  void aSessionSavedAndOpenedGoesOnBitForBit() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_heiles")).document;
    doc["poincare"]["points"] = 300;
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    QVERIFY(map->startAt(0.05, 0.1));
    const std::vector<int> ids = map->sceneJobs();
    QVERIFY(finishDrawing(map, ids, 300));
    std::vector<std::pair<std::vector<double>, std::vector<double>>> saved;
    for (int id : ids)
      saved.push_back(map->trajectories().points(id));
    window_->report("a line the session keeps");
    ChartWindow* chart = window_->openChart("poincare"); // an open chart window is part of the session
    QVERIFY(chart);
    const nlohmann::json chartDocument = chart->document();
    const QString path = dir_.filePath("hh-session.json");
    QVERIFY(window_->saveSessionTo(path));
    chart->close();
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("chaplygin_ball"))));
    window_->findChild<QPushButton*>("clear_results")->click();
    QVERIFY(window_->openScene(path)); // File > Open scene takes a session too
    QCOMPARE(window_->scene()->model->info().id, std::string("henon_heiles"));
    QVERIFY(window_->results().contains("a line the session keeps"));
    QCOMPARE(map->chart().selected(), -1); // nothing selected, none emphasised (issue 61 (6): the last was)
    ChartWindow* again = nullptr;
    for (ChartWindow* w : window_->findChildren<ChartWindow*>())
      if (w->isVisible() && w->viewName() == "poincare") again = w;
    QVERIFY(again);
    QCOMPARE(again->document(), chartDocument);
    QSignalSpy drawn(again, &ChartWindow::finished);
    QVERIFY(again->ready() || drawn.wait(60000));
    QVERIFY(again->ready());
    again->close();
    const std::vector<int> opened = map->sceneJobs();
    QCOMPARE(opened.size(), saved.size());
    for (std::size_t k = 0; k < saved.size(); ++k)
      QVERIFY(map->trajectories().points(opened[k]) == saved[k]);
    // Start on the finished trajectory: 300 more points
    ToolManager* tools = window_->toolManager();
    QTRY_VERIFY_WITH_TIMEOUT(map->jobs().find(opened[1])->status() == Job::Status::Finished, 60000);
    tools->refresh();
    tools->select(opened[1]);
    auto* start = tools->findChild<QPushButton*>("start");
    QVERIFY2(start->isEnabled(), qPrintable(start->toolTip()));
    start->click();
    QVERIFY(finishDrawing(map, {opened[1]}, 600));
    const auto continued = map->trajectories().points(opened[1]);
    // the reference: one run of 600 points from the same click
    doc["poincare"]["points"] = 600;
    QVERIFY(window_->runDocument(doc));
    QVERIFY(map->startAt(0.05, 0.1));
    QVERIFY(finishDrawing(map, {map->sceneJobs().back()}, 600));
    QVERIFY(map->trajectories().points(map->sceneJobs().back()) == continued);
  }

  // Issue 43: the fixed points and families found on the map are kept -- a session saved and opened draws
  // them again as they were (points, the found point's cross, the family's multipliers for the filters),
  // without computing, and Undo brings back a deleted one.
  void fixedPointsAndFamiliesAreKeptBySessionsAndUndo() {
    nlohmann::json doc = loadScene(defaultScenePath("standard_map")).document;
    doc["parameters"]["K"] = 1.5;
    doc["poincare"]["points"] = 300;
    doc["fixedpoint"] = {{"guess", {3.1, 0.05}}};
    doc["continuation"] = {{"parameter", "K"}, {"to", 2.0}, {"step", 0.05}};
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    map->searchFixedPointAt(3.1, 0.05);
    const Job* search = map->jobs().jobs().back();
    map->startContinuation();
    const Job* family = map->jobs().jobs().back();
    QTRY_VERIFY_WITH_TIMEOUT(!search->running() && !family->running(), 60000);
    QTRY_COMPARE_WITH_TIMEOUT(map->toolPoints(family->id()).size(), std::size_t(11), 60000); // K 1.5..2
    QTRY_COMPARE_WITH_TIMEOUT(map->fixedPointsFound(), 1, 60000);
    const auto familyPoints = map->toolPoints(family->id());
    const QString path = dir_.filePath("sm-session.json");
    QVERIFY(window_->saveSessionTo(path));
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("henon_heiles"))));
    QCOMPARE(map->fixedPointsFound(), 0);
    QVERIFY(window_->openScene(path));
    QCOMPARE(map->fixedPointsFound(), 1);
    QCOMPARE(map->toolJobs(), 1);
    int restored = -1;
    for (int id : map->sceneJobs())
      if (!map->toolPoints(id).empty()) restored = id;
    QVERIFY(restored >= 0);
    QVERIFY(map->toolPoints(restored) == familyPoints);
    // a record: nothing computed, its job finishes at once (on its own thread: waited for, a busy machine)
    QTRY_COMPARE_WITH_TIMEOUT(map->jobs().find(restored)->status(), Job::Status::Finished, 60000);
    // the filters get the restored family's multipliers: on the unit circle, real part (2 - K) / 2
    MultipliersWindow* w = window_->openMultipliersWindow();
    const auto& parameters = w->parameters(restored);
    QCOMPARE(parameters.size(), std::size_t(11));
    for (std::size_t k = 0; k < parameters.size(); ++k)
      for (const auto& m : w->outputs(restored)[k])
        QVERIFY(std::abs(m.real() - (2 - parameters[k]) / 2) < 1e-7);
    w->close();
    // deleted (tool manager) and undone: the family is back, point for point
    ToolManager* tools = window_->toolManager();
    tools->refresh();
    tools->select(restored);
    tools->deleteSelected();
    QCOMPARE(map->toolJobs(), 0);
    QVERIFY2(window_->undoText().contains("1 tool output"), qPrintable(window_->undoText()));
    QVERIFY(window_->undo());
    QCOMPARE(map->toolJobs(), 1);
    int back = -1;
    for (int id : map->sceneJobs())
      if (!map->toolPoints(id).empty()) back = id;
    QVERIFY(back >= 0 && map->toolPoints(back) == familyPoints);
    QCOMPARE(map->fixedPointsFound(), 1);
  }

  // Issue 61 (3): one numbering -- trajectories and tools keep their numbers after Undo (a delete, a replaced
  // map) and after a session is saved and opened; a MEGNO or Lyapunov result in the Results dock carries its
  // tool's number; a failed tool comes back from a session as failed (not "finished 100 %") and is not said
  // failed a second time; a Lyapunov spectrum is listed largest first, and says so.
  void oneNumberingThroughUndoAndSessions() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_heiles")).document;
    doc["poincare"]["points"] = 100;
    doc["megno"] = {{"time", 200}};
    doc.erase("continuation"); // no parameter to continue in: a continuation fails
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    ToolManager* tools = window_->toolManager();
    QVERIFY(map->startAt(0.05, 0.1));
    QVERIFY(map->startAt(0.1, -0.1));
    const std::vector<int> ids = map->sceneJobs();
    QCOMPARE(ids.size(), 3u);
    QVERIFY(finishDrawing(map, ids, 100));
    const auto second = map->trajectories().points(ids[1]);
    // a failing tool: the failure said once, with its number
    map->startContinuation();
    const int failed = map->jobs().jobs().back()->id();
    QTRY_COMPARE_WITH_TIMEOUT(map->jobs().find(failed)->status(), Job::Status::Failed, 60000);
    tools->refresh();
    const QString failedLine = QString("tool %1 (Continuation) failed").arg(failed);
    QCOMPARE(window_->results().count(failedLine), 1);
    // MEGNO of the first trajectory: its <Y> in the Results dock with the MEGNO job's number and the
    // trajectory's
    map->setColourByMegno(true);
    const int megno = map->jobs().children(*map->jobs().find(ids[0])).front()->id();
    QTRY_VERIFY_WITH_TIMEOUT(map->trajectories().megno(ids[0]).has_value(), 60000);
    QVERIFY2(window_->results().contains(
                 QString("MEGNO (tool #%1) of trajectory #%2: <Y> = ").arg(megno).arg(ids[0])),
             qPrintable(window_->results()));
    map->setColourByMegno(false);
    // a deleted trajectory comes back under its number, in its row
    tools->refresh();
    tools->select(ids[1]);
    tools->deleteSelected();
    QVERIFY(!map->jobs().find(ids[1]));
    QVERIFY(window_->undo());
    QCOMPARE(map->sceneJobs().size(), 4u);
    QVERIFY(map->jobs().find(ids[1]) && map->trajectories().contains(ids[1]));
    QVERIFY(map->trajectories().points(ids[1]) == second);
    tools->refresh();
    std::vector<int> rows; // listed where it was: the tool manager's rows by number
    for (int i = 0; i < tools->tree()->topLevelItemCount(); ++i)
      rows.push_back(tools->tree()->topLevelItem(i)->text(0).toInt());
    QVERIFY(std::is_sorted(rows.begin(), rows.end()));
    QVERIFY(std::ranges::count(rows, ids[1]) == 1);
    // a replaced map comes back with every number
    const std::vector<int> before = map->sceneJobs();
    doc["parameters"]["energy"] = 0.1;
    answerNextQuestion(QMessageBox::Yes);
    QVERIFY(window_->applyDocument(doc));
    QVERIFY(window_->undo());
    QCOMPARE(map->sceneJobs(), before);
    QVERIFY(map->trajectories().points(ids[1]) == second);
    // the failed record stays failed (its own thread decides: waited for), and is not said failed again
    QTRY_COMPARE_WITH_TIMEOUT(map->jobs().find(failed)->status(), Job::Status::Failed, 60000);
    tools->refresh();
    QCOMPARE(window_->results().count(failedLine), 1);
    // a session saved and opened over another scene: the same numbers, the failure still a failure
    const QString path = dir_.filePath("numbers-session.json");
    QVERIFY(window_->saveSessionTo(path));
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("standard_map"))));
    QVERIFY(map->startAt(1.0, 1.0)); // numbers taken in between
    QVERIFY(window_->openScene(path));
    QCOMPARE(map->sceneJobs(), before);
    QVERIFY(map->trajectories().points(ids[1]) == second);
    QTRY_COMPARE_WITH_TIMEOUT(map->jobs().find(failed)->status(), Job::Status::Failed, 60000);
    QCOMPARE(map->jobs().find(failed)->task().name(), std::string("Continuation"));
    tools->refresh();
    QCOMPARE(window_->results().count(failedLine), 1);
    for (int i = 0; i < tools->tree()->topLevelItemCount(); ++i)
      if (tools->tree()->topLevelItem(i)->text(0) == QString::number(failed))
        QVERIFY2(tools->tree()->topLevelItem(i)->text(2).startsWith("failed"),
                 qPrintable(tools->tree()->topLevelItem(i)->text(2)));
    // a new tool takes a new number
    QVERIFY(map->startAt(0.0, 0.05));
    QVERIFY(map->sceneJobs().back() > *std::max_element(before.begin(), before.end()));
    // the Lyapunov spectrum: its tool's number, largest first, and said so
    doc["lyapunov"] = {{"time", 200}, {"output_period", 2}};
    doc["parameters"]["energy"] = 0.125;
    ChartWindow* chart = window_->openChartOf(doc, "lyapunov");
    QVERIFY(chart);
    QSignalSpy done(chart, &ChartWindow::finished);
    QVERIFY(chart->ready() || done.wait(60000));
    QVERIFY2(chart->ready(), qPrintable(chart->failure()));
    const QString head = QString("Lyapunov exponents (tool #%1): largest first: ").arg(chart->jobId());
    QTRY_VERIFY2_WITH_TIMEOUT(window_->results().contains(head), qPrintable(window_->results()), 60000);
    const QString results = window_->results();
    const QString line = results.mid(results.indexOf(head) + head.size()).section('\n', 0, 0);
    std::vector<double> values;
    for (const QString& named : line.split(", "))
      values.push_back(named.section(" = ", 1).toDouble());
    QCOMPARE(values.size(), std::size_t(4));
    QVERIFY2(std::is_sorted(values.rbegin(), values.rend()), qPrintable(line));
    chart->close();
  }

  // Issue 61 (2): a continuation set up entirely from the GUI -- the continuation tab's fields (the
  // parameter, chosen among the problem's; its end value; the step; the method) -- continues a fixed point
  // found by a Shift+click, from the map's context menu on it, on a scene that holds no continuation settings
  // (it used to fail: "give the parameter to continue in"). Henon-Heiles: the straight-line orbit's point is
  // (0, sqrt(E/2)) at every energy.
  void aContinuationIsSetUpFromTheGui() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_heiles")).document;
    doc["poincare"]["points"] = 50;
    doc.erase("continuation");
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    const std::vector<int> kept = map->sceneJobs();
    ControlPanel* panel = window_->controlPanel();
    auto* parameter = panel->findChild<QComboBox*>("continuation_parameter");
    auto* to = panel->findChild<QLineEdit*>("continuation_to");
    QVERIFY(parameter && to);
    QCOMPARE(parameter->currentText(), QString()); // the scene's: none
    QVERIFY(to->text().isEmpty());
    QVERIFY(parameter->findText("energy") >= 0); // the problem's parameters, from its table
    setUpContinuation("energy", "0.1", -0.005, "natural");
    if (QTest::currentTestFailed()) return;
    const nlohmann::json edited = panel->editedDocument();
    QCOMPARE(edited["continuation"]["parameter"].get<std::string>(), std::string("energy"));
    QCOMPARE(edited["continuation"]["to"].get<double>(), 0.1);
    QCOMPARE(edited["continuation"]["step"].get<double>(), -0.005);
    QVERIFY(window_->applyDocument(edited)); // Apply: the map stays (nothing that defines it changed)
    QCOMPARE(map->sceneJobs(), kept);
    QCOMPARE(panel->findChild<QComboBox*>("continuation_parameter")->currentText(), QString("energy"));
    Job* family = continueAShiftClickedPoint(0.02, 0.23, 0.0, std::sqrt(0.125 / 2));
    QVERIFY(family);
    QVERIFY2(family->status() == Job::Status::Finished, family->error().c_str());
    // the family, drawn as it came: energy 0.125 down to 0.1 by 0.005, the point at (0, sqrt(E/2))
    QTRY_COMPARE_WITH_TIMEOUT(map->toolPoints(family->id()).size(), std::size_t(6), 60000);
    const auto points = map->toolPoints(family->id());
    QVERIFY(std::abs(points.back().first) < 1e-8);
    QVERIFY2(std::abs(points.back().second - std::sqrt(0.1 / 2)) < 1e-8,
             qPrintable(QString::number(points.back().second, 'g', 12)));
    QTRY_VERIFY2_WITH_TIMEOUT(window_->results().contains(QString("(tool #%1) ended: 6 points, energy from "
                                                                  "0.125 to 0.1")
                                                              .arg(family->id())),
                              qPrintable(window_->results()), 60000);
    QVERIFY(!window_->results().contains(QString("tool %1 (Continuation) failed").arg(family->id())));
  }

  // Issue 61 (6): the tool manager's "start" of the scene's own trajectory is the scene's initial.map, not
  // the first map point (one iteration later); a trajectory clicked on the map starts where it was clicked
  void theScenesTrajectoryStartsAtItsInitialMapPoint() {
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("standard_map"))));
    MapPanel* map = window_->mapPanel();
    QCOMPARE(map->trajectories().origin(map->sceneJobs().front()), QString("(3, 1.9)"));
    QVERIFY(map->startAt(1.5, 0.25));
    QCOMPARE(map->trajectories().origin(map->sceneJobs().back()), QString("(1.5, 0.25)"));
  }

  // Issue 62: Shift+click on a map of four coordinates (the rolling disk's M1, M2, M3, gamma2) searches from
  // the two clicked and the rest of the scene's initial map point (it gave two coordinates, and the search
  // failed): the disk's steady motion is found near the scene's
  void aShiftClickOnAFourCoordinateMapSearchesFromAFullPoint() {
    QVERIFY(window_->openScene(QString(qgetenv("ROLLVIZ_SOURCE_DIR")) +
                               "/examples/rolling/disk_steady.scene.json"));
    MapPanel* map = window_->mapPanel();
    const int found = map->fixedPointsFound();
    map->searchFixedPointAt(0.025, -0.025);
    QTRY_COMPARE_WITH_TIMEOUT(map->fixedPointsFound(), found + 1, 120000);
    const QString results = window_->results();
    const QString head = "fixed point (";
    const int at = static_cast<int>(results.lastIndexOf(head));
    QVERIFY2(at >= 0, qPrintable(results));
    const int from = at + static_cast<int>(head.size());
    const QStringList coordinates = results.mid(from, results.indexOf(')', from) - from).split(", ");
    QCOMPARE(coordinates.size(), 4);
    QVERIFY2(std::abs(coordinates[2].toDouble() - 2.03) < 0.1, qPrintable(coordinates.join(", "))); // M3
  }

  // Issue 61 (6): the Chaplygin sleigh's map stayed empty ("running 0 %") with no word why: its spin dies out
  // and never crosses the section omega = 0. The map says so, once.
  void aMapWhoseOrbitNeverCrossesTheSectionSaysSo() {
    QVERIFY(window_->openScene(QString(qgetenv("ROLLVIZ_SOURCE_DIR")) +
                               "/examples/models/chaplygin_sleigh.scene.json"));
    const QString said = QString("trajectory #%1 has not crossed the section omega = 0 yet")
                             .arg(window_->mapPanel()->sceneJobs().front());
    QTRY_VERIFY2_WITH_TIMEOUT(window_->results().contains(said), qPrintable(window_->results()), 60000);
    QCOMPARE(window_->results().count(said), 1);
    QVERIFY(window_->mapPanel()->jobs().find(window_->mapPanel()->sceneJobs().front())->running());
    // its one map coordinate is drawn against the crossing time, titled so (a rotated "t" read as an arrow)
    QCOMPARE(window_->mapPanel()->chart().chart()->GetAxis(vtkAxis::LEFT)->GetTitle(), vtkStdString("time"));
  }

  // Issue 61 (2), the rest: Tools > Continue the fixed point continues the point found last (not the scene's
  // guess -- this scene has none), and the continuation tab's edits count without Apply (a map tool runs with
  // its tabs as shown; the map stays the scene's).
  void toolsContinueTakesTheFoundPointAndTheTabAsShown() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_heiles")).document;
    doc["poincare"]["points"] = 50;
    doc.erase("continuation");
    QVERIFY(!doc.contains("fixedpoint"));
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    const std::vector<int> kept = map->sceneJobs();
    setUpContinuation("energy", "0.1", -0.005, "natural");
    if (QTest::currentTestFailed()) return;
    const int found = map->fixedPointsFound();
    map->searchFixedPointAt(0.02, 0.23);
    QVERIFY(window_->controlPanel()->pending()); // not applied: still shown as waiting
    QCOMPARE(map->sceneJobs().front(), kept.front());
    QTRY_COMPARE_WITH_TIMEOUT(map->fixedPointsFound(), found + 1, 60000);
    QAction* cont = nullptr;
    for (QAction* a : window_->findChildren<QAction*>())
      if (a->text() == "Continue the fixed point") cont = a;
    QVERIFY(cont);
    cont->trigger();
    Job* family = map->jobs().jobs().back();
    QCOMPARE(QString::fromStdString(family->task().name()), QString("Continuation"));
    QTRY_VERIFY_WITH_TIMEOUT(!family->running(), 60000);
    QVERIFY2(family->status() == Job::Status::Finished, family->error().c_str());
    QTRY_COMPARE_WITH_TIMEOUT(map->toolPoints(family->id()).size(), std::size_t(6), 60000);
    const auto points = map->toolPoints(family->id());
    QVERIFY(std::abs(points.front().second - std::sqrt(0.125 / 2)) < 1e-8);
    QVERIFY(std::abs(points.back().second - std::sqrt(0.1 / 2)) < 1e-8);
  }

  // Issue 61 (2), two parameters: the Bifurcation curve tab set up from the GUI alone (its second parameter
  // chosen among the problem's, the kind and the box typed; the continuation tab's parameter and end) on a
  // scene that holds neither, then Tools > Create: the Henon map's period-doubling curve a = 3 (1 - b)^2 / 4.
  void aBifurcationCurveIsSetUpFromTheGui() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_map")).document;
    doc["fixedpoint"]["guess"] = {0.63, 0.19};
    doc.erase("continuation"), doc.erase("bifurcation_curve");
    QVERIFY(window_->runDocument(doc));
    setUpContinuation("a", "0", -0.05, "natural");
    if (QTest::currentTestFailed()) return;
    ControlPanel* panel = window_->controlPanel();
    auto* second = panel->findChild<QComboBox*>("bifurcation_curve_second_parameter");
    QVERIFY(second);
    QCOMPARE(second->currentText(), QString());
    second->setCurrentIndex(second->findText("b"));
    QVERIFY(second->currentIndex() > 0);
    emit second->activated(second->currentIndex());
    ParameterForm* form = panel->form("bifurcation_curve");
    QVERIFY(form);
    auto* kind = qobject_cast<QComboBox*>(form->editor("kind"));
    QVERIFY(kind);
    kind->setCurrentIndex(kind->findText("period_doubling"));
    QVERIFY(kind->currentIndex() >= 0);
    for (const auto& [key, value] : {std::pair{"second_min", -0.5}, std::pair{"second_max", 0.5}}) {
      auto* box = qobject_cast<QDoubleSpinBox*>(form->editor(key));
      QVERIFY2(box, key);
      box->setValue(value);
    }
    const nlohmann::json edited = panel->editedDocument();
    QCOMPARE(edited["bifurcation_curve"]["second_parameter"].get<std::string>(), std::string("b"));
    QCOMPARE(edited["bifurcation_curve"]["second_max"].get<double>(), 0.5);
    const auto before = window_->findChildren<ChartWindow*>();
    window_->createTool("bifurcation_curve");
    ChartWindow* chart = nullptr;
    for (auto* w : window_->findChildren<ChartWindow*>())
      if (!before.contains(w)) chart = w;
    QVERIFY(chart);
    QTRY_VERIFY_WITH_TIMEOUT(chart->ready() || !chart->failure().isEmpty(), 120000);
    QVERIFY2(chart->ready(), qPrintable(chart->failure()));
    auto* plane = dynamic_cast<PoincareChart*>(chart->drawn().get());
    QVERIFY(plane && plane->chart()->GetNumberOfPlots() > 0);
    vtkTable* table = plane->chart()->GetPlot(0)->GetInput();
    QVERIFY(table && table->GetNumberOfRows() > 10);
    for (vtkIdType i = 0; i < table->GetNumberOfRows(); ++i) { // the chart's plane is (a, b)
      const double a = table->GetValue(i, 0).ToDouble(), b = table->GetValue(i, 1).ToDouble();
      QVERIFY2(std::abs(a - 0.75 * (1 - b) * (1 - b)) < 1e-8, qPrintable(QString("%1 %2").arg(a).arg(b)));
      QVERIFY(b >= -0.5 - 1e-12 && b <= 0.5 + 1e-12);
    }
    chart->close();
  }

  // Issue 61 (2): the Henon map's fixed point at a = 0 (x = 1/(1 - b)) followed by arclength through its fold
  // at a = -(1 - b)^2/4 = -0.1225 (x = 2/(1 - b) there) and back along the other branch, set up from the GUI
  // alone (docs/continuation.md gives the same run on the command line).
  void anArclengthContinuationFromTheGuiPassesTheFold() {
    nlohmann::json doc = loadScene(defaultScenePath("henon_map")).document;
    doc["parameters"] = {{"a", 0.0}, {"b", 0.3}};
    doc["poincare"]["points"] = 50;
    doc.erase("continuation");
    QVERIFY(window_->runDocument(doc));
    setUpContinuation("a", "-0.5", -0.01, "arclength");
    if (QTest::currentTestFailed()) return;
    auto* points = qobject_cast<QSpinBox*>(window_->controlPanel()->form("continuation")->editor("points"));
    QVERIFY(points);
    points->setValue(200);
    QVERIFY(window_->applyDocument(window_->controlPanel()->editedDocument()));
    Job* family = continueAShiftClickedPoint(1.43, 0.43, 1 / 0.7, 0.3 / 0.7);
    QVERIFY(family);
    QVERIFY2(family->status() == Job::Status::Finished, family->error().c_str());
    MapPanel* map = window_->mapPanel();
    QTRY_VERIFY_WITH_TIMEOUT(map->toolPoints(family->id()).size() >= 100, 60000);
    double widest = 0;
    for (const auto& [x, y] : map->toolPoints(family->id())) {
      QVERIFY2(std::abs(y - 0.3 * x) < 1e-8, qPrintable(QString("%1 %2").arg(x).arg(y))); // fixed: y = b x
      widest = std::max(widest, x);
    }
    QVERIFY2(widest > 2 / 0.7 + 0.1, qPrintable(QString::number(widest))); // past the fold's x = 2/(1 - b)
    QTRY_VERIFY2_WITH_TIMEOUT(window_->results().contains("fold at a = -0.1225"),
                              qPrintable(window_->results()), 60000);
  }

  // Issue 43, item 2: the map window's dock floated and docked again still draws its map (a floating dock is
  // a new top-level window: Qt gives its OpenGL widget a new context, and VTK's resources of the old one
  // must go with it) -- and a click on it still starts a trajectory that shows.
  void theMapDockFloatsAndDocksAndStillDraws() {
    nlohmann::json doc = loadScene(defaultScenePath("standard_map")).document;
    doc["poincare"]["points"] = 3000;
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    QVERIFY(finishDrawing(map, map->sceneJobs(), 3000));
    auto* dock = window_->findChild<QDockWidget*>("map");
    QVERIFY(dock);
    // the map's picture: its points' colour (the first series') covers a good part of it
    const Rgb c = map->trajectories().shownColour(map->sceneJobs().front());
    const auto pointsIn = [](const QImage& img, const Rgb& colour) { // pixels of the points' colour
      const QColor want = QColor::fromRgbF(static_cast<float>(colour[0]), static_cast<float>(colour[1]),
                                           static_cast<float>(colour[2]));
      long n = 0;
      for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
          const QColor p = img.pixelColor(x, y);
          n += std::abs(p.red() - want.red()) + std::abs(p.green() - want.green()) +
                   std::abs(p.blue() - want.blue()) <
               60;
        }
      return n;
    };
    const long docked = pointsIn(map->view()->grabFramebuffer(), c);
    QVERIFY2(docked > 200, qPrintable(QString::number(docked)));
    dock->setFloating(true);
    dock->resize(500, 500);
    QVERIFY(QTest::qWaitForWindowExposed(dock));
    QTRY_VERIFY_WITH_TIMEOUT(pointsIn(map->view()->grabFramebuffer(), c) > 200, 60000);
    const QImage floating = map->view()->grabFramebuffer();
    QVERIFY(keep(floating, "map_floating.png"));
    QVERIFY2(pointsIn(floating, c) > 200, qPrintable(QString::number(pointsIn(floating, c))));
    dock->setFloating(false);
    QVERIFY(QTest::qWaitForWindowExposed(window_));
    QTRY_VERIFY_WITH_TIMEOUT(pointsIn(map->view()->grabFramebuffer(), c) > 200, 60000);
    const QImage back = map->view()->grabFramebuffer();
    QVERIFY(keep(back, "map_docked_again.png"));
    QVERIFY2(pointsIn(back, c) > 200, qPrintable(QString::number(pointsIn(back, c))));
    // and it still works: a new trajectory shows in its own colour
    QVERIFY(map->startAt(1.0, 0.5));
    QVERIFY(finishDrawing(map, {map->sceneJobs().back()}, 3000));
    const Rgb d = map->trajectories().shownColour(map->sceneJobs().back());
    QVERIFY(d != c);
    const long shown = pointsIn(map->view()->grabFramebuffer(), d);
    QVERIFY2(shown > 50, qPrintable(QString::number(shown)));
  }

  // Choosing another problem asks before the map's own trajectories go; No keeps them and the problem.
  void aProblemSwitchAsksBeforeDroppingTrajectories() {
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("standard_map"))));
    MapPanel* map = window_->mapPanel();
    QVERIFY(window_->chooseProblem("henon_map")); // nothing added: no question
    QCOMPARE(window_->scene()->model->info().id, std::string("henon_map"));
    QVERIFY(map->startAt(0.2, 0.1));
    const int added = map->addedJobs().front();
    answerNextQuestion(QMessageBox::No);
    QVERIFY(!window_->chooseProblem("standard_map"));
    QCOMPARE(window_->scene()->model->info().id, std::string("henon_map"));
    QCOMPARE(window_->controlPanel()->findChild<QComboBox*>("problem_choice")->currentText(),
             QString("henon_map"));
    QVERIFY(map->jobs().find(added));
    answerNextQuestion(QMessageBox::Yes);
    QVERIFY(window_->chooseProblem("standard_map"));
    QCOMPARE(window_->scene()->model->info().id, std::string("standard_map"));
    QVERIFY(!map->jobs().find(added));
  }

  // An explicit map has no Method tab (nothing is integrated) and its tool rows do not name a method; Apply
  // on the Method tab of a flow stays there.
  void controlPanelTabs() {
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("standard_map"))));
    auto* tabs = window_->controlPanel()->findChild<QTabWidget*>("tabs");
    QVERIFY(tabs);
    const auto titles = [&] {
      QStringList t;
      for (int i = 0; i < tabs->count(); ++i)
        t << tabs->tabText(i);
      return t;
    };
    QVERIFY2(!titles().contains("Method"), qPrintable(titles().join(",")));
    QVERIFY(!QString::fromStdString(window_->mapPanel()->jobs().jobs().back()->task().describe())
                 .contains("rk4"));
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("chaplygin_ball"))));
    QVERIFY(titles().contains("Method"));
    tabs->setCurrentIndex(titles().indexOf("Method"));
    window_->controlPanel()->findChild<QPushButton*>("apply")->click();
    QCOMPARE(tabs->tabText(tabs->currentIndex()), QString("Method"));
    QVERIFY(keep(window_->controlPanel()->grab().toImage(), "window_control_panel.png"));
  }

  // Charts say what they are and read alone: a failure in the GUI's words on the page (not black) with
  // nothing to save; the Lyapunov chart's legend gives each exponent's final value; a heat map has its
  // colour bar.
  void chartsReadAlone() {
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("chaplygin_ball"))));
    ChartWindow* spectrum = window_->openChart("spectrum"); // the scene names no spectrum.function
    QSignalSpy failed(spectrum, &ChartWindow::finished);
    QVERIFY(failed.wait(60000));
    QVERIFY(!spectrum->ready());
    QVERIFY2(!spectrum->failure().contains("--view"), qPrintable(spectrum->failure()));
    QVERIFY2(spectrum->failure().contains("control panel"), qPrintable(spectrum->failure()));
    QVERIFY(spectrum->placeholder().contains(spectrum->failure()));
    // the failure and its reason reach the Results dock, numbered as in the tool manager
    QTRY_VERIFY_WITH_TIMEOUT(
        window_->results().contains("failed: ") && window_->results().contains(spectrum->failure()), 60000);
    QVERIFY(!spectrum->findChild<QPushButton*>("save_figure")->isEnabled());
    QVERIFY(!spectrum->findChild<QPushButton*>("save_csv")->isEnabled());
    QVERIFY(QTest::qWaitForWindowExposed(spectrum->window()));
    QVERIFY(keep(spectrum->grab().toImage(), "window_chart_failed.png"));
    spectrum->close();

    nlohmann::json doc = loadScene(defaultScenePath("henon_heiles")).document;
    doc["lyapunov"] = {{"time", 200}, {"output_period", 2}};
    QVERIFY(window_->runDocument(doc));
    ChartWindow* lyapunov = window_->openChart("lyapunov");
    QVERIFY(lyapunov->placeholder().startsWith("computing"));
    QSignalSpy done(lyapunov, &ChartWindow::finished);
    QVERIFY(done.wait(60000));
    QVERIFY2(lyapunov->ready(), qPrintable(lyapunov->failure()));
    QVERIFY(lyapunov->placeholder().isEmpty());
    QVERIFY(lyapunov->findChild<QPushButton*>("save_figure")->isEnabled());
    auto* plane = dynamic_cast<PoincareChart*>(lyapunov->drawn().get());
    QVERIFY(plane);
    QVERIFY(plane->chart()->GetShowLegend());
    QStringList labels;
    for (vtkIdType i = 0; i < plane->chart()->GetNumberOfPlots(); ++i)
      if (plane->chart()->GetPlot(i)->GetLegendVisibility())
        labels << QString::fromStdString(plane->chart()->GetPlot(i)->GetLabel());
    QCOMPARE(labels.size(), 4); // Henon-Heiles: four exponents
    // named as the history's columns, listed largest first (issue 61 (3))
    std::vector<double> listed;
    for (const QString& label : labels) {
      QVERIFY2(label.startsWith("L"), qPrintable(labels.join(" | ")));
      listed.push_back(label.section(" = ", 1).toDouble());
    }
    QVERIFY2(std::is_sorted(listed.rbegin(), listed.rend()), qPrintable(labels.join(" | ")));
    QCOMPARE(QString::fromStdString(plane->chart()->GetTitle()), QString("Lyapunov exponents"));
    // and the exponents, with their names, reach the Results dock
    QTRY_VERIFY_WITH_TIMEOUT(window_->results().contains(labels.front()), 60000);
    QVERIFY(QTest::qWaitForWindowExposed(lyapunov->window()));
    QVERIFY(keep(lyapunov->grab().toImage(), "window_chart_lyapunov.png"));
    // Save figure: SVG and PDF by the extension, the chart's text as text; another extension is refused
    QTemporaryDir figures;
    QVERIFY(lyapunov->saveFigure(figures.filePath("lyapunov.svg")));
    QFile svg(figures.filePath("lyapunov.svg"));
    QVERIFY(svg.open(QIODevice::ReadOnly));
    const QByteArray text = svg.readAll();
    QVERIFY(text.contains("<svg"));
    QVERIFY(text.contains("Lyapunov exponents"));
    QVERIFY(lyapunov->saveFigure(figures.filePath("lyapunov.pdf")));
    QFile pdf(figures.filePath("lyapunov.pdf"));
    QVERIFY(pdf.open(QIODevice::ReadOnly));
    QVERIFY(pdf.read(5) == "%PDF-");
    QVERIFY(!lyapunov->saveFigure(figures.filePath("lyapunov.jpg")));
    QVERIFY(!QFile::exists(figures.filePath("lyapunov.jpg")));
    QVERIFY(lyapunov->isVisible()); // and the window still draws
    QVERIFY(keep(lyapunov->grab().toImage(), "window_chart_lyapunov_after_export.png"));
    lyapunov->close();
  }

  // File > Recent scenes: two files of one name are told apart by their folders
  void recentScenesTellFilesOfOneNameApart() {
    const QString other = dir_.filePath("copy/henon_heiles.json");
    QVERIFY(QDir().mkpath(QFileInfo(other).absolutePath()));
    QFile::remove(other);
    QVERIFY(QFile::copy(QString::fromStdString(defaultScenePath("henon_heiles")), other));
    QVERIFY(window_->openScene(other));
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("henon_heiles"))));
    QStringList labels;
    for (auto* action : window_->menuBar()->actions())
      if (action->text() == "&File")
        for (auto* item : action->menu()->actions())
          if (item->menu() && item->text() == "Recent scenes")
            for (auto* recent : item->menu()->actions())
              labels << recent->text();
    QVERIFY2(labels.contains("copy/henon_heiles.json") && labels.contains("scenes/henon_heiles.json"),
             qPrintable(labels.join(" | ")));
  }

  // Issue 43, item 3: the camera is the user's in a body view, playing or not -- turned while playing, it
  // stays turned (only carried along with the body while Follow body is on: the same view of it), pause and
  // play do not reset it; Follow body off, the camera stays where it was put.
  void theCameraIsTheUsersAndFollowingIsAToggle() {
    QVERIFY(window_->runDocument(loadScene(defaultScenePath("chaplygin_ball")).document));
    if (!window_->playing()) window_->togglePlay();
    auto* follow = window_->findChild<QAction*>("follow");
    QVERIFY(follow && follow->isEnabled());
    QCOMPARE(follow->isChecked(), window_->scene()->view.camera.follow);
    vtkCamera* cam = window_->view()->renderWindow()->GetRenderers()->GetFirstRenderer()->GetActiveCamera();
    const auto state = [cam] {
      std::array<double, 6> s{};
      cam->GetPosition(&s[0]);
      cam->GetFocalPoint(&s[3]);
      return s;
    };
    const auto waitFrames = [this] {
      const double t0 = window_->shownTime();
      return QTest::qWaitFor([&] { return window_->shownTime() > t0 + 0.5; }, 60000);
    };
    if (!follow->isChecked()) follow->trigger();
    QVERIFY(waitFrames());
    cam->Azimuth(50); // the user turns it while playing
    cam->Elevation(10);
    cam->OrthogonalizeViewUp();
    const auto turned = state();
    QVERIFY(waitFrames());
    const auto carried = state(); // carried with the body: the same offset from what it looks at
    QVERIFY(carried != turned);   // (the ball rolled on)
    for (int i = 0; i < 3; ++i)
      QVERIFY(std::abs((carried[i] - carried[i + 3]) - (turned[i] - turned[i + 3])) < 1e-9);
    window_->togglePlay(); // pause and play: not reset
    window_->togglePlay();
    QVERIFY(waitFrames());
    const auto played = state();
    for (int i = 0; i < 3; ++i)
      QVERIFY(std::abs((played[i] - played[i + 3]) - (turned[i] - turned[i + 3])) < 1e-9);
    follow->trigger(); // off: the camera stays where it is
    QVERIFY(!follow->isChecked());
    const auto put = state();
    QVERIFY(waitFrames());
    QVERIFY(state() == put);
    const QString saved =
        dir_.filePath("nofollow.json"); // the toggle is a scene setting: Save scene keeps it
    QVERIFY(window_->saveSceneTo(saved));
    std::ifstream in(saved.toStdString());
    QCOMPARE(nlohmann::json::parse(in)["view"]["camera"]["follow"], nlohmann::json(false));
    follow->trigger();
  }

  // Issue 43: the control panel opens wide enough for its first tabs' whole titles (it read "Poincar..." with
  // scroll arrows over it)
  void theControlPanelShowsItsFirstTabsWhole() {
    QVERIFY(window_->runDocument(loadScene(defaultScenePath("henon_heiles")).document));
    auto* tabs = window_->controlPanel()->findChild<QTabWidget*>("tabs");
    QVERIFY(tabs);
    QTRY_VERIFY_WITH_TIMEOUT(tabs->isVisible() && tabs->tabBar()->width() > 0, 60000);
    QCOMPARE(tabs->tabText(3), QString("Poincaré map"));
    const QTabBar* bar = tabs->tabBar();
    const int arrows = 2 * bar->style()->pixelMetric(QStyle::PM_TabBarScrollButtonWidth, nullptr, bar);
    for (int i = 0; i < 4; ++i)
      QVERIFY2(bar->tabRect(i).right() <= bar->width() - arrows,
               qPrintable(
                   QString("tab %1 ends at %2 of %3").arg(i).arg(bar->tabRect(i).right()).arg(bar->width())));
  }

  // File > Gallery: every gallery scene with its thumbnail and what to watch; Open loads the chosen one
  void galleryOpensAFamousMotion() {
    bool inMenu = false;
    for (auto* action : window_->menuBar()->actions())
      if (action->text() == "&File")
        for (auto* item : action->menu()->actions())
          inMenu = inMenu || item->text() == "Gallery…";
    QVERIFY(inMenu);
    GalleryDialog gallery(window_, [this](const QString& path) { window_->openScene(path); });
    QListWidget* list = gallery.list();
    QVERIFY(list->count() >= 8);
    int rattleback = -1;
    for (int i = 0; i < list->count(); ++i) {
      QVERIFY2(!list->item(i)->icon().isNull(), qPrintable(list->item(i)->text())); // its thumbnail
      QVERIFY(list->item(i)->toolTip().size() > 80);
      if (list->item(i)->data(Qt::UserRole).toString().endsWith("/rattleback_reversal.json")) rattleback = i;
    }
    QVERIFY(rattleback >= 0);
    list->setCurrentRow(rattleback);
    QCOMPARE(gallery.findChild<QLabel*>("gallery_description")->text(), list->item(rattleback)->toolTip());
    gallery.show();
    QVERIFY(QTest::qWaitForWindowExposed(&gallery));
    QVERIFY(keep(gallery.grab().toImage(), "window_gallery.png"));
    QVERIFY(gallery.openSelected());
    QVERIFY2(window_->windowTitle().contains("rattleback_reversal.json"), qPrintable(window_->windowTitle()));
    QCOMPARE(window_->scene()->model->info().id, std::string("ellipsoid_on_plane"));
  }

  // the registry's generic test in the GUI: every tool that runs through scenes/ToolRunner.h, created from
  // the Tools tab on its example scene (scenes/tools/ID.json), draws its chart window as a job of the tool
  // manager, and its numbers reach the Results dock
  void everyToolWithARunnerDrawsItsChartFromTheToolsTab() {
    const QString tools = QString(qgetenv("ROLLVIZ_SOURCE_DIR")) + "/scenes/tools/";
    int tried = 0;
    for (const auto& tool : ToolRegistry::global().entries()) {
      const ToolRunner* runner = findToolRunner(tool.id);
      // the fixed-point family runs on the map window (MapTest)
      if (!runner || runner->window != ToolWindow::Chart || tool.chartView.empty() || !tool.origin.empty())
        continue;
      const QString scene = tools + QString::fromStdString(tool.id) + ".json";
      QVERIFY2(QFile::exists(scene), qPrintable("a built-in tool with a runner ships an example: " + scene));
      QVERIFY(window_->openScene(scene));
      const auto before = window_->findChildren<ChartWindow*>();
      window_->createTool(tool.id);
      ChartWindow* chart = nullptr;
      for (auto* w : window_->findChildren<ChartWindow*>())
        if (!before.contains(w)) chart = w;
      QVERIFY2(chart, tool.id.c_str());
      QVERIFY(belowTheToolbars(chart));
      QVERIFY(window_->findChild<ToolManager*>());
      QTRY_VERIFY_WITH_TIMEOUT(chart->ready() || !chart->failure().isEmpty(), 120000);
      QVERIFY2(chart->ready(), qPrintable(QString::fromStdString(tool.id) + ": " + chart->failure()));
      auto* plane = dynamic_cast<PoincareChart*>(chart->drawn().get());
      auto* space = dynamic_cast<Chart3D*>(chart->drawn().get()); // map3d: points in a box around them
      QVERIFY2((plane && plane->chart()->GetNumberOfPlots() > 0) ||
                   (space && space->bounds()[1] > space->bounds()[0]),
               tool.id.c_str());
      QVERIFY(chart->findChild<QPushButton*>("save_figure")->isEnabled());
      QVERIFY(keep(chart->grab().toImage(), QString::fromStdString("window_tool_" + tool.id + ".png")));
      chart->close();
      QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
      ++tried;
    }
    // spectrum, lyapunov, megno, map3d, multipliers, bifurcation_curve, surface, ram, diagram
    QVERIFY(tried >= 9);
  }

  // the rest of the registry's generic test in the GUI: a tool shown elsewhere than in a chart window
  // (ToolRunner::window: the map's points, the fixed-point family, the plot filter), created from the
  // Tools tab on its example scene, starts there -- jobs of the map window that draw and do not fail, or the
  // plot's live window
  void everyToolWithItsOwnWindowStartsThereFromTheToolsTab() {
    const QString tools = QString(qgetenv("ROLLVIZ_SOURCE_DIR")) + "/scenes/tools/";
    int tried = 0;
    for (const auto& tool : ToolRegistry::global().entries()) {
      const ToolRunner* runner = findToolRunner(tool.id);
      if (!runner || runner->window == ToolWindow::Chart || !tool.origin.empty()) continue;
      const QString scene = tools + QString::fromStdString(tool.id) + ".json";
      QVERIFY2(QFile::exists(scene), qPrintable("a built-in tool with a runner ships an example: " + scene));
      QVERIFY(window_->openScene(scene));
      MapPanel* map = window_->mapPanel();
      std::vector<int> before;
      for (Job* j : map->jobs().jobs())
        before.push_back(j->id());
      const auto plots = window_->findChildren<PlotWindow*>().size();
      window_->createTool(tool.id);
      ++tried;
      if (window_->findChildren<PlotWindow*>().size() > plots) continue; // the plot filter's live window
      std::vector<Job*> added;
      for (Job* j : map->jobs().jobs())
        if (std::find(before.begin(), before.end(), j->id()) == before.end()) added.push_back(j);
      QVERIFY2(!added.empty(), tool.id.c_str());
      for (Job* j : added) {
        const int id = j->id();
        if (map->trajectories().contains(id)) { // the map's points: it draws them as they come
          QTRY_VERIFY_WITH_TIMEOUT(j->status() == Job::Status::Failed ||
                                       !map->trajectories().save({id}, false, true).front().x.empty(),
                                   120000);
        } else { // a search, a family, a branch, a tree: it ends with what it drew (the frame timer drains
                 // it)
          const auto drew = [&] {
            const auto drawn = map->saveToolOutputs({id});
            return !drawn.empty() && (!drawn.front().x.empty() || !drawn.front().found.empty());
          };
          QTRY_VERIFY_WITH_TIMEOUT(
              j->status() == Job::Status::Failed || (j->status() == Job::Status::Finished && drew()), 120000);
        }
        QVERIFY2(j->status() != Job::Status::Failed,
                 qPrintable(QString::fromStdString(tool.id + ": " + j->error())));
      }
    }
    QVERIFY(tried >= 6); // poincare, plot, fixedpoint, continuation, separatrix, bifurcation_tree
  }

  // Tools > Separatrices of the fixed point: the separatrix tool's runner, one job per branch, drawn as they
  // grow -- the outgoing pair in one colour, the incoming in another. The standard map's saddle (0, 0) at K:
  // its branches leave along the eigenvectors (1, mu - 1 - K) of the multipliers mu = 1 + K/2 +- sqrt(K +
  // K^2/4) (the Jacobian there is ((1 + K, 1), (K, 1)))
  void separatricesGrowAsAJobPerBranch() {
    nlohmann::json doc = loadScene(defaultScenePath("standard_map")).document;
    const double K = 0.9;
    doc["parameters"]["K"] = K;
    doc["fixedpoint"] = {{"guess", {0.01, 0.01}}};
    QVERIFY(window_->runDocument(doc));
    MapPanel* map = window_->mapPanel();
    const int before = map->toolJobs();
    map->startSeparatrices();
    QCOMPARE(map->toolJobs(), before + 4);
    const std::vector<Job*> all = map->jobs().jobs();
    const std::vector<Job*> branches(all.end() - 4, all.end());
    for (Job* j : branches)
      QTRY_VERIFY_WITH_TIMEOUT(j->status() == Job::Status::Finished, 60000);
    QTRY_VERIFY_WITH_TIMEOUT(map->toolPoints(branches.back()->id()).size() > 10, 60000);
    std::vector<int> ids;
    for (Job* j : branches)
      ids.push_back(j->id());
    const auto saved = map->saveToolOutputs(ids);
    QCOMPARE(saved.size(), std::size_t(4));
    QVERIFY(saved[0].colour == saved[1].colour && saved[2].colour == saved[3].colour);
    QVERIFY(!(saved[0].colour == saved[2].colour));
    const double root = std::sqrt(K + K * K / 4);
    for (std::size_t b = 0; b < 4; ++b) {
      const auto points = map->toolPoints(ids[b]);
      QVERIFY2(points.size() > 10, qPrintable(QString("branch %1").arg(b + 1)));
      // the first point: on the branch's eigenvector, near the saddle (theta wraps at 2 pi)
      const double x = std::remainder(points.front().first, 2 * std::numbers::pi),
                   y = std::remainder(points.front().second, 2 * std::numbers::pi);
      const double mu = b < 2 ? 1 + K / 2 + root : 1 + K / 2 - root;
      QVERIFY(std::hypot(x, y) < 0.1);
      QVERIFY2(std::abs(y - (mu - 1 - K) * x) < 1e-6 * std::abs(x) + 1e-9,
               qPrintable(QString("branch %1: (%2, %3)").arg(b + 1).arg(x).arg(y)));
    }
    for (Job* j : branches)
      map->removeJob(*j);
  }

  // a tool from outside rollviz (as a module adds one) whose runner says ToolWindow::MapRows is drawn on the
  // map window as its rows come, with no GUI code of its own: Tools > Create runs it as a job of the map
  // window, each row a point where its columns named like the map's coordinates say, its notes and its end
  // in the Results dock, its output kept by Undo like a family's
  void aToolFromOutsideThatStreamsMapRowsIsDrawnOnTheMap() {
    if (!ToolRegistry::global().find("test_map_rows")) {
      ToolRegistry::mutableGlobal().add({.id = "test_map_rows",
                                         .title = "Ring",
                                         .description = "twelve points on a circle of the map",
                                         .outputs = {{"<map coordinates>", "the points"}},
                                         .origin = "a test's module"});
      addToolRunner("test_map_rows", {.run =
                                          [](const Scene& scene, const ToolControl& control) {
                                            ToolResult r;
                                            r.table.names = scene.model->info().mapCoordinates;
                                            r.table.values.assign(r.table.names.size(), {});
                                            for (int k = 0; k < 12; ++k) {
                                              const double a = 2 * std::numbers::pi * k / 12;
                                              addRow(r, control, {3 + 0.5 * std::cos(a), 0.5 * std::sin(a)});
                                            }
                                            addNote(r, control, "twelve points on a circle");
                                            return r;
                                          },
                                      .window = ToolWindow::MapRows});
    }
    QVERIFY(window_->openScene(QString::fromStdString(defaultScenePath("standard_map"))));
    MapPanel* map = window_->mapPanel();
    const int before = map->toolJobs();
    window_->createTool("test_map_rows");
    QCOMPARE(map->toolJobs(), before + 1);
    Job* job = map->jobs().jobs().back();
    QTRY_VERIFY_WITH_TIMEOUT(job->status() == Job::Status::Finished, 60000);
    QTRY_VERIFY_WITH_TIMEOUT(map->toolPoints(job->id()).size() == 12, 60000); // the frame timer drains it
    const auto points = map->toolPoints(job->id());
    for (int k = 0; k < 12; ++k) {
      const double a = 2 * std::numbers::pi * k / 12;
      QCOMPARE(points[static_cast<std::size_t>(k)].first, 3 + 0.5 * std::cos(a));
      QCOMPARE(points[static_cast<std::size_t>(k)].second, 0.5 * std::sin(a));
    }
    QTRY_VERIFY_WITH_TIMEOUT(window_->results().contains("twelve points on a circle"), 60000);
    const QString ended = QString("Ring (tool #%1) ended: 12 points").arg(job->id());
    QTRY_VERIFY2_WITH_TIMEOUT(window_->results().contains(ended), qPrintable(window_->results()), 60000);
    const auto saved = map->saveToolOutputs({job->id()});
    QCOMPARE(saved.size(), std::size_t(1));
    QCOMPARE(saved.front().x.size(), std::size_t(12));
    map->removeJob(*job);
    QCOMPARE(map->toolJobs(), before);
  }

  // File > Open model...: a model file runs at its own "initial", joins the problem list, and saving it while
  // it is open reloads it (a broken save keeps the model running and says why)
  // File > New rolling body: the tippe top described in the form (sphere, centre of mass off centre, sliding)
  // is written as a rolling model file and opened; its parameters are the form's numbers; a body that makes
  // no model says why in the dialog and writes nothing
  void aRollingBodyDescribedInTheFormOpens() {
    bool inMenu = false;
    for (auto* action : window_->menuBar()->actions())
      if (action->text() == "&File")
        for (auto* item : action->menu()->actions())
          inMenu = inMenu || item->text() == "New rolling body…";
    QVERIFY(inMenu);
    setModelCompilation(ModelCompilation::Off); // the compiled path has its own tests
    QString opened;
    RollingBodyDialog dialog(window_, [&](const QString& path) {
      opened = path;
      window_->openModel(path);
    });
    const auto box = [&](const char* name) { return dialog.findChild<QDoubleSpinBox*>(name); };
    dialog.findChild<QLineEdit*>("id")->setText("gui_tippe_top");
    dialog.findChild<QComboBox*>("shape")->setCurrentText("sphere");
    QVERIFY(box("size1")->isVisibleTo(&dialog)); // a sphere has a radius only
    QVERIFY(!box("size2")->isVisibleTo(&dialog));
    box("size1")->setValue(1);
    box("centre3")->setValue(0.3);
    box("I1")->setValue(0.35);
    box("I2")->setValue(0.35);
    box("I3")->setValue(0.4);
    dialog.findChild<QComboBox*>("contact")->setCurrentText("sliding");
    QVERIFY(box("friction")->isEnabled());
    box("friction")->setValue(1);
    dialog.findChild<QCheckBox*>("axis")->setChecked(true);
    // first a surface that names what does not exist: said in the dialog, nothing written
    dialog.findChild<QComboBox*>("shape")->setCurrentText("implicit");
    dialog.findChild<QLineEdit*>("F")->setText("x^2 + y^2 + w^2 - 1");
    const QString file = dir_.filePath("gui_tippe_top.json");
    dialog.findChild<QLineEdit*>("file")->setText(file);
    QVERIFY(!dialog.create());
    QVERIFY2(dialog.findChild<QLabel*>("error")->text().contains("body.F: unknown name 'w'"),
             qPrintable(dialog.findChild<QLabel*>("error")->text()));
    QVERIFY(!QFile::exists(file));
    dialog.findChild<QComboBox*>("shape")->setCurrentText("sphere");
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QVERIFY(keep(dialog.grab().toImage(), "window_new_rolling_body.png"));
    QVERIFY(dialog.create());
    QCOMPARE(opened, file);
    QVERIFY(QFile::exists(file));
    QCOMPARE(window_->scene()->model->info().id, std::string("gui_tippe_top"));
    const ParameterValues& p = window_->scene()->model->parameters();
    QCOMPARE(p["mu"], 1.0);
    QCOMPARE(p["c3"], 0.3);
    QVERIFY(window_->scene()->model->findObservable("jellett") >= 0);
    QVERIFY(window_->scene()->model->findObservable("axis_up") >= 0);
  }

  // File > New rolling body on a curved support: the fields follow the shape and the support chosen; a body
  // that cannot roll from its start is refused saying why; the model written has the body's profile, the
  // bowl's sizes as parameters, the contact (sliding, with its friction) and a title that names the bowl
  void aRollingBodyInABowlDescribedInTheFormOpens() {
    setModelCompilation(ModelCompilation::Off); // the compiled path has its own tests
    QString opened;
    RollingBodyDialog dialog(window_, [&](const QString& path) {
      opened = path;
      window_->openModel(path);
    });
    const auto box = [&](const char* name) { return dialog.findChild<QDoubleSpinBox*>(name); };
    const auto shown = [&](const char* name) {
      return dialog.findChild<QWidget*>(name)->isVisibleTo(&dialog);
    };
    auto* shape = dialog.findChild<QComboBox*>("shape");
    auto* support = dialog.findChild<QComboBox*>("support");
    auto* contact = dialog.findChild<QComboBox*>("contact");
    dialog.findChild<QLineEdit*>("id")->setText("gui_lens_in_a_bowl");
    shape->setCurrentText("superellipsoid");
    QVERIFY(shown("size3") && shown("exponent") && shown("bulge") && !shown("profile") && !shown("F"));
    shape->setCurrentText("revolution");
    QVERIFY(!shown("size1") && !shown("exponent") && shown("profile") && shown("profile_squared") &&
            shown("z_bottom") && shown("z_top"));
    QVERIFY(!shown("side") && !shown("support1")); // the plane has no sizes
    support->setCurrentText("sphere");
    QVERIFY(shown("side") && shown("support1") && !shown("support2"));
    // a brick in a spherical bowl: its faces are flatter than the bowl, so it cannot roll from its start --
    // said in the dialog, nothing written
    const QString file = dir_.filePath("gui_lens_in_a_bowl.json");
    dialog.findChild<QLineEdit*>("file")->setText(file);
    dialog.findChild<QComboBox*>("side")->setCurrentText("inside");
    shape->setCurrentText("superellipsoid");
    QVERIFY(!dialog.create());
    const QString why = dialog.findChild<QLabel*>("error")->text();
    QVERIFY2(why.contains("flatter than the bowl") && why.contains("definitions.flatter_than_the_support"),
             qPrintable(why));
    QVERIFY(!QFile::exists(file));
    shape->setCurrentText("revolution");
    QVERIFY(dialog.findChild<QLabel*>("error")->text().isEmpty()); // the reason was the brick's
    support->setCurrentText("ellipsoid");
    QVERIFY(shown("side") && shown("support1") && shown("support2") && shown("support3")); // a bowl too
    support->setCurrentText("implicit");
    QVERIFY(!shown("side") && shown("support_F") && shown("support1") && !shown("support2"));
    support->setCurrentText("paraboloid");
    QVERIFY(!shown("side") && !shown("support_F") && shown("support1") && shown("support2") &&
            !shown("support3"));
    box("support1")->setValue(6);
    contact->setCurrentText("sliding");
    QVERIFY(box("friction")->isEnabled());
    box("friction")->setValue(0.2);
    dialog.show();
    QVERIFY(QTest::qWaitForWindowExposed(&dialog));
    QVERIFY(keep(dialog.grab().toImage(), "window_new_rolling_body_in_a_bowl.png"));
    QVERIFY2(dialog.create(), qPrintable(dialog.findChild<QLabel*>("error")->text()));
    QCOMPARE(opened, file);
    std::ifstream in(file.toStdString());
    const nlohmann::json written = nlohmann::json::parse(in);
    QCOMPARE(written["title"].get<std::string>(),
             std::string("A body of revolution rolling in a paraboloid bowl (File > New rolling body)"));
    QCOMPARE(written["body"]["profile_squared"].get<std::string>(), RollingBodyForm{}.profile);
    QCOMPARE(written["body"]["heights"].get<std::string>(), std::string("[z_bottom, z_top]"));
    QCOMPARE(written["support"].dump(), std::string(R"({"p":"bowl_p","q":"bowl_q","surface":"paraboloid"})"));
    QCOMPARE(written["contact"].get<std::string>(), std::string("sliding"));
    QCOMPARE(window_->scene()->model->info().id, std::string("gui_lens_in_a_bowl"));
    const ParameterValues& p = window_->scene()->model->parameters();
    QCOMPARE(p["bowl_p"], 6.0);
    QCOMPARE(p["z_bottom"], -0.5);
    QCOMPARE(p["mu"], 0.2);
    QVERIFY(window_->scene()->model->findObservable("x1") >= 0); // the body's place on the bowl
  }

  void aModelFileOpensAndReloadsWhenSaved() {
    if (!window_->playing()) window_->togglePlay(); // it needs the 3D view's run going
    setModelCompilation(ModelCompilation::Off);     // the compiled path has its own tests
    const QString copy = dir_.filePath("lorenz_copy.json");
    QFile::remove(copy);
    QVERIFY(QFile::copy(QString(qgetenv("ROLLVIZ_SOURCE_DIR")) + "/examples/models/lorenz.json", copy));
    QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);
    QVERIFY(window_->openModel(copy));
    QVERIFY(window_->windowTitle().contains("lorenz_equations"));
    QCOMPARE(window_->scene()->initialState, Eigen::Vector3d(1, 1, 1));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete); // the old scene's panel goes
    auto* chooser = window_->findChild<QComboBox*>("problem_choice");
    QVERIFY(chooser && chooser->findText("lorenz_equations") >= 0);
    QTRY_VERIFY_WITH_TIMEOUT(window_->shownTime() > 0.1, 60000);
    const auto rewrite = [&](const QByteArray& from, const QByteArray& to) {
      QFile f(copy);
      QVERIFY(f.open(QIODevice::ReadOnly));
      QByteArray text = f.readAll();
      f.close();
      QVERIFY(text.contains(from));
      text.replace(from, to);
      QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
      f.write(text);
    };
    rewrite("\"default\": 28", "\"default\": 20");
    QTRY_VERIFY_WITH_TIMEOUT(window_->results().contains("lorenz_copy.json changed: the model was reloaded"),
                             60000);
    // with its time, as every line of the Results dock (issue 61 (6))
    QVERIFY(window_->results().contains(
        QRegularExpression("(^|\\n)\\d\\d:\\d\\d:\\d\\d  lorenz_copy.json changed: the model was reloaded")));
    QCOMPARE(window_->scene()->model->parameters()["rho"], 20.0);
    rewrite("sigma*(y - x)", "sigma*(y - x");
    QTRY_VERIFY_WITH_TIMEOUT(window_->results().contains("lorenz_copy.json changed but cannot be read"),
                             60000);
    QCOMPARE(window_->scene()->model->parameters()["rho"], 20.0); // the model before goes on
    setModelCompilation(ModelCompilation::OnFirstUse);
  }

  void cleanupTestCase() { delete window_; }
};

} // namespace rv

int main(int argc, char** argv) {
  qputenv("QT_XCB_GL_INTEGRATION", "xcb_glx"); // VTK 9.1's GLEW needs a GLX context (as in GuiMain)
  QSurfaceFormat::setDefaultFormat(rv::QtVtkWidget::defaultFormat());
  QStandardPaths::setTestModeEnabled(true); // QSettings of the test, not the user's
  QApplication app(argc, argv);
  QApplication::setOrganizationName("rollviz-test");
  rv::MainWindowTest t;
  return QTest::qExec(&t, argc, argv);
}
#include "WindowTest.moc"
