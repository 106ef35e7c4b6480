#include "app/gui/GuiMain.h"

#include "app/gui/MainWindow.h"
#include "app/gui/MapPanel.h"
#include "app/gui/QtVtkWidget.h"
#include "scenes/ModelFile.h"
#include "scenes/SceneLoader.h"

#include <QApplication>
#include <QFileInfo>
#include <QSaveFile>
#include <QSettings>
#include <QTimer>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace rv {

int runGui(int argc, char** argv, const GuiOptions& options) {
  const auto set = [](const char* name) { return std::getenv(name) && *std::getenv(name); };
  if (!set("DISPLAY") && !set("WAYLAND_DISPLAY")) {
    std::fprintf(stderr, "rollviz: no display to open a window on; headless work goes through "
                         "`rollviz render` and `rollviz video` (see rollviz --help)\n");
    return 1;
  }
  if (!options.scene.empty()) {
    try {
      loadScene(options.scene); // report a bad scene here, on stderr, rather than in a dialog
    } catch (const std::exception& e) {
      std::fprintf(stderr, "rollviz: %s\n", e.what());
      return 2;
    }
  }
  qputenv("QT_XCB_GL_INTEGRATION", "xcb_glx"); // VTK 9.1's GLEW needs a GLX context
  if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "xcb");
  QSurfaceFormat::setDefaultFormat(QtVtkWidget::defaultFormat());
  QApplication app(argc, argv);
  setModelCompilation(
      ModelCompilation::InBackground); // model files: the GUI thread never waits for a compiler
  QApplication::setOrganizationName("rollviz");
  QApplication::setApplicationName("rollviz");

  MainWindow window;
  window.show();
  // a model compiling in the background says so, and when it is ready, in the window (and on stderr)
  setModelCompilationNotes([&window](const std::string& note) {
    std::fprintf(stderr, "rollviz: %s\n", note.c_str());
    QMetaObject::invokeMethod(
        &window, [&window, text = QString::fromStdString(note)] { window.report(text, 8000); },
        Qt::QueuedConnection);
  });
  QString scene = QString::fromStdString(options.scene);
  if (scene.isEmpty()) {
    const QString last = QSettings().value("lastScene").toString();
    scene = !last.isEmpty() && QFileInfo::exists(last)
                ? last
                : QString::fromStdString(defaultScenePath("chaplygin_ball"));
  }
  window.openScene(scene);
  // trajectories saved when rollviz last closed: offered once the window shows (not in scripted runs)
  if (options.quitAfter <= 0) QTimer::singleShot(0, &window, [&window] { window.offerSavedJobs(); });

  // a scripted run: the summary of what the window holds (for tests), at the end and, with a status file,
  // all along
  const auto summary = [&window] {
    char line[512];
    std::snprintf(
        line, sizeof line,
        "shown t = %.6g, map trajectories = %d, map points = %ld, fixed point searches = %d, found = %d, "
        "tool jobs = %d, jobs in the tool manager = %d, playing = %s\n",
        window.shownTime(), window.mapPanel()->trajectories().count(), window.mapPanel()->points(),
        window.mapPanel()->searches(), window.mapPanel()->fixedPointsFound(), window.mapPanel()->toolJobs(),
        static_cast<int>(window.mapPanel()->jobs().jobs().size()), window.playing() ? "yes" : "no");
    return std::string(line);
  };
  bool finished = false;
  const auto finish = [&] {
    if (finished) return;
    finished = true;
    if (!options.screenshot.empty() && !window.grab().save(QString::fromStdString(options.screenshot), "PNG"))
      std::fprintf(stderr, "rollviz: cannot write %s\n", options.screenshot.c_str());
    std::fputs(summary().c_str(), stdout);
    std::fflush(stdout);
    app.quit();
  };
  if (options.quitAfter > 0) QTimer::singleShot(static_cast<int>(options.quitAfter * 1000), &app, finish);
  QTimer statusTimer;
  if (!options.statusFile.empty()) {
    const QString file = QString::fromStdString(options.statusFile);
    QObject::connect(&statusTimer, &QTimer::timeout, &app, [&, file] {
      if (QFileInfo::exists(file + ".quit")) return finish();
      QSaveFile out(file); // whole lines only: written, then renamed
      const std::string line = summary();
      if (out.open(QIODevice::WriteOnly)) {
        out.write(line.data(), static_cast<qint64>(line.size()));
        out.commit();
      }
    });
    statusTimer.start(200);
  }
  const int status = app.exec();
  setModelCompilationNotes({}); // stderr again: the window goes
  return status;
}

} // namespace rv
