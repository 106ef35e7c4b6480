// A monkey test that hunts crashes (issue 61), on a real X server (xvfb) and GL like WindowTest. For each
// seed (ROLLVIZ_MONKEY_SEEDS, e.g. "1,2,3"; default kDefaultSeeds) a fresh main window runs four phases: a
// flow (lorenz), a map (henon or standard map), a rolling body (the Chaplygin ball or the rattleback) and a
// sweep (a small sweep file written as WindowTest writes one). Each phase opens its scene, every window of
// the Windows menu and every dock, then sends ROLLVIZ_MONKEY_EVENTS / 4 random events drawn from a
// std::mt19937 seeded with the seed: clicks, double clicks, drags, wheel turns and key presses on random
// visible widgets of random visible windows, menu and toolbar actions, docks floated and docked, windows
// opened and closed. Modal dialogs never block it: a repeating timer (it runs in their nested event loops
// too) rejects or accepts them; file dialogs are always rejected, so nothing is written outside the test's
// temporary HOME. It fails on a crash or an ASan report (the process dies: a handler prints the seed and the
// last events first) and on a Qt warning about a deleted or destroyed object or a thread misuse (the seed and
// the last events in the failure). Events depend on timing too (jobs finish when they finish), so a replay
// with the same seed is close to, not always exactly, the failing run. ROLLVIZ_MONKEY_VERBOSE=1 prints every
// event.
#include "app/gui/MainWindow.h"
#include "app/gui/QtVtkWidget.h"
#include "app/gui/SweepWindow.h"
#include "scenes/BuiltinTools.h"
#include "scenes/ModelFile.h"
#include "scenes/SceneLoader.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QDialog>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QFileDialog>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTimer>
#include <QWheelEvent>
#include <QtTest>
#include <array>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <unistd.h>

// ASan calls this before it exits on a report (weak: absent without ASan)
extern "C" void __sanitizer_set_death_callback(void (*callback)(void)) __attribute__((weak));

namespace rv {

namespace {

// the list ./test runs: between them, both maps, both bodies and both sweeps (the choices a seed makes first)
const std::vector<unsigned> kDefaultSeeds = {1, 4, 19};
constexpr int kDefaultEvents = 100; // per seed, over the four phases: about 30 s a seed on a 2-core machine

// the last events, kept for the failure message and pre-rendered for the crash handler (which may only
// write(2) what is already there)
struct EventLog {
  static constexpr std::size_t kKeep = 30;
  std::array<std::string, kKeep> ring;
  std::size_t count = 0;
  unsigned seed = 0;
  int events = 0;
  bool verbose = false;
  char rendered[16384] = {0};
  QElapsedTimer clock; // since the seed began: a slow or hanging event shows
  void add(const QString& what) {
    char at[32];
    std::snprintf(at, sizeof at, " [%.1f s] ", clock.isValid() ? clock.elapsed() / 1000.0 : 0.0);
    const std::string line = "#" + std::to_string(count) + at + what.toStdString();
    ring[count % kKeep] = line;
    ++count;
    if (verbose) std::fprintf(stderr, "monkey: %s\n", line.c_str());
    render();
  }
  std::string text() const {
    std::string out = "monkey seed " + std::to_string(seed) +
                      " (replay: ROLLVIZ_MONKEY_SEEDS=" + std::to_string(seed) +
                      " ROLLVIZ_MONKEY_EVENTS=" + std::to_string(events) + "); the last events:\n";
    for (std::size_t i = count > kKeep ? count - kKeep : 0; i < count; ++i)
      out += "  " + ring[i % kKeep] + "\n";
    return out;
  }
  void render() {
    const std::string t = text();
    const std::size_t n = std::min(t.size(), sizeof rendered - 1);
    std::memcpy(rendered, t.data(), n);
    rendered[n] = 0;
  }
};
EventLog gLog;

void dumpLog() {
  const char head[] = "\n=== monkey: the process dies ===\n";
  (void)!write(2, head, sizeof head - 1);
  (void)!write(2, gLog.rendered, std::strlen(gLog.rendered));
}
void onFatalSignal(int sig) {
  dumpLog();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// Qt messages: every warning is counted (listed per seed); those that say an object was used after it went,
// or a thread misuse, fail the test
QtMessageHandler gPrevious = nullptr;
std::map<QString, int> gWarnings;
QStringList gBad;
bool isBad(const QString& m) {
  static const char* const patterns[] = {
      "deleted",        "destroyed",        "QObject::", "Recursive repaint",
      "another thread", "different thread", "dangling"};
  for (const char* p : patterns)
    if (m.contains(QLatin1String(p), Qt::CaseInsensitive)) return true;
  return false;
}
void onMessage(QtMsgType type, const QMessageLogContext& context, const QString& message) {
  if (type == QtWarningMsg || type == QtCriticalMsg || type == QtFatalMsg) {
    ++gWarnings[message.left(200)];
    if (isBad(message)) gBad << message;
    if (type == QtFatalMsg) dumpLog();
  }
  if (gPrevious) gPrevious(type, context, message);
}

// a widget in words: its class, name, text and window
QString describe(const QWidget* w) {
  if (!w) return "(none)";
  QString d = w->metaObject()->className();
  if (!w->objectName().isEmpty()) d += " '" + w->objectName() + "'";
  if (const auto* b = qobject_cast<const QAbstractButton*>(w); b && !b->text().isEmpty())
    d += " \"" + b->text() + "\"";
  if (w->window() != w)
    d += " in " + QString(w->window()->metaObject()->className()) + " \"" + w->window()->windowTitle() + "\"";
  else if (!w->windowTitle().isEmpty())
    d += " \"" + w->windowTitle() + "\"";
  return d;
}

bool writeJson(const QString& path, const nlohmann::json& doc) {
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly)) return false;
  f.write(QByteArray::fromStdString(doc.dump()));
  return true;
}

std::vector<unsigned> seedsFromEnv() {
  const QString s = qEnvironmentVariable("ROLLVIZ_MONKEY_SEEDS");
  if (s.trimmed().isEmpty()) return kDefaultSeeds;
  std::vector<unsigned> seeds;
  for (const QString& part : s.split(QRegularExpression("[,\\s]+"), Qt::SkipEmptyParts))
    seeds.push_back(part.toUInt());
  return seeds;
}
} // namespace

class MonkeyTest : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  QPointer<MainWindow> window_;
  std::mt19937 rng_;
  QTimer dialogs_;         // closes modal dialogs, from any event loop
  bool acceptAll_ = false; // while opening every window: the plot dialogs' settings accepted
  int eventsPerPhase_ = 0;
  QPointer<QWidget> focus_; // the window the phase is about (none: the main window)

  int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng_); }
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
  template <class T> T* any(const QList<T*>& list) {
    return list.isEmpty() ? nullptr : list[pick(list.size())];
  }

  // What a user would do with a modal dialog: a question gets its escape answer (No, Cancel), a file dialog
  // is cancelled (nothing written), any other dialog (settings, colour, gallery, ...) is accepted now and
  // then
  void closeModal() {
    closeStalePopup();
    QWidget* modal = QApplication::activeModalWidget();
    if (!modal) return;
    QString what;
    if (auto* box = qobject_cast<QMessageBox*>(modal)) {
      QAbstractButton* b = box->escapeButton();
      if (!b) b = box->button(QMessageBox::No);
      if (!b) b = box->button(QMessageBox::Cancel);
      if (!b) b = box->button(QMessageBox::Ok);
      what = "message box \"" + box->text().left(80) + "\": " + (b ? b->text() : QString("closed"));
      if (b)
        b->click();
      else
        box->reject();
    } else if (auto* file = qobject_cast<QFileDialog*>(modal)) {
      what = "file dialog \"" + file->windowTitle() + "\": cancelled";
      file->reject();
    } else if (auto* dialog = qobject_cast<QDialog*>(modal)) {
      const bool accept = acceptAll_ || chance(0.3);
      what = QString("dialog %1 \"%2\": %3")
                 .arg(dialog->metaObject()->className(), dialog->windowTitle(),
                      accept ? "accepted" : "rejected");
      if (accept)
        dialog->accept();
      else
        dialog->reject();
    } else {
      what = "modal " + describe(modal) + ": closed";
      modal->close();
    }
    gLog.add(what);
  }

  // A popup open for a few ticks goes: one opened by QMenu::exec (a tool button's menu, a context menu)
  // blocks the event the monkey sent until it closes
  QPointer<QWidget> popup_;
  int popupTicks_ = 0;
  void closeStalePopup() {
    QWidget* popup = QApplication::activePopupWidget();
    if (!popup || popup != popup_) {
      popup_ = popup;
      popupTicks_ = 0;
      return;
    }
    if (++popupTicks_ < 3) return;
    gLog.add("popup " + describe(popup) + ": closed after a while");
    popup->close();
  }

  // the visible top-level windows (popups too), the main window first
  QList<QWidget*> windows() const {
    QList<QWidget*> out;
    for (QWidget* w : QApplication::topLevelWidgets())
      if (w->isVisible() && !w->isMinimized() && w->width() > 0 && w->height() > 0) out << w;
    return out;
  }
  // a random visible widget of a random window (itself or one of its children) with room to click in
  QWidget* target() {
    QWidget* popup = QApplication::activePopupWidget();
    // the phase's own window (the main window, or the sweep's) half the time: it has the most to do
    QWidget* own = focus_ && focus_->isVisible() ? focus_.data() : window_.data();
    QWidget* top = popup ? popup : own && own->isVisible() && chance(0.5) ? own : any(windows());
    if (!top) return nullptr;
    QList<QWidget*> candidates{top};
    for (QWidget* c : top->findChildren<QWidget*>())
      if (c->isVisible() && c->width() > 1 && c->height() > 1 && c->window() == top) candidates << c;
    return any(candidates);
  }
  QPoint somewhere(const QWidget* w) { return {pick(w->width()), pick(w->height())}; }

  // the actions a user can reach in the menus and toolbars of the visible windows: enabled, not a submenu,
  // not Quit (the monkey stays in)
  QList<QAction*> actions() const {
    QList<QAction*> out;
    for (QWidget* top : windows())
      for (QAction* a : top->findChildren<QAction*>()) {
        if (!a->isEnabled() || a->isSeparator() || a->menu()) continue;
        const QString t = a->text();
        if (t.isEmpty() || t.contains("Quit") || t.contains("Exit")) continue;
        out << a;
      }
    return out;
  }

  void click(QWidget* w) {
    static const Qt::MouseButton buttons[] = {Qt::LeftButton, Qt::LeftButton, Qt::LeftButton, Qt::RightButton,
                                              Qt::MiddleButton};
    const Qt::MouseButton b = buttons[pick(5)];
    const QPoint at = somewhere(w);
    const bool twice = chance(0.15);
    gLog.add(QString("%1 %2 at (%3,%4) on %5")
                 .arg(twice ? "double-click" : "click")
                 .arg(b == Qt::LeftButton    ? "left"
                      : b == Qt::RightButton ? "right"
                                             : "middle")
                 .arg(at.x())
                 .arg(at.y())
                 .arg(describe(w)));
    if (twice)
      QTest::mouseDClick(w, b, {}, at);
    else
      QTest::mouseClick(w, b, {}, at);
  }
  void drag(QWidget* w) {
    const Qt::MouseButton b = chance(0.8) ? Qt::LeftButton : Qt::RightButton;
    const Qt::KeyboardModifiers mods = chance(0.2) ? Qt::ShiftModifier : Qt::NoModifier;
    QPoint at = somewhere(w);
    const int steps = 1 + pick(5);
    gLog.add(QString("drag %1 from (%2,%3) in %4 moves on %5")
                 .arg(b == Qt::LeftButton ? "left" : "right")
                 .arg(at.x())
                 .arg(at.y())
                 .arg(steps)
                 .arg(describe(w)));
    QPointer<QWidget> alive(w);
    QTest::mousePress(w, b, mods, at);
    for (int i = 0; i < steps && alive; ++i) {
      at = somewhere(w);
      // a move with the button held (QTest::mouseMove would send no buttons)
      QMouseEvent move(QEvent::MouseMove, at, w->mapToGlobal(at), Qt::NoButton, b, mods);
      QApplication::sendEvent(w, &move);
      QCoreApplication::processEvents();
    }
    if (alive) QTest::mouseRelease(w, b, mods, at);
  }
  void wheel(QWidget* w) {
    const QPoint at = somewhere(w);
    const int delta = (chance(0.5) ? 1 : -1) * 120 * (1 + pick(3));
    gLog.add(QString("wheel %1 at (%2,%3) on %4").arg(delta).arg(at.x()).arg(at.y()).arg(describe(w)));
    QWheelEvent e(at, w->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton, Qt::NoModifier,
                  Qt::NoScrollPhase, false);
    QApplication::sendEvent(w, &e);
  }
  void key(QWidget* fallback) {
    static const Qt::Key keys[] = {Qt::Key_Left,  Qt::Key_Right,  Qt::Key_Up,       Qt::Key_Down,
                                   Qt::Key_Space, Qt::Key_Escape, Qt::Key_Return,   Qt::Key_Tab,
                                   Qt::Key_Plus,  Qt::Key_Minus,  Qt::Key_Delete,   Qt::Key_Home,
                                   Qt::Key_End,   Qt::Key_PageUp, Qt::Key_PageDown, Qt::Key_0,
                                   Qt::Key_1,     Qt::Key_5,      Qt::Key_Period,   Qt::Key_Backspace};
    constexpr int kNamed = sizeof keys / sizeof keys[0];
    const int k = pick(kNamed + 26);
    const Qt::Key key = k < kNamed ? keys[k] : static_cast<Qt::Key>(Qt::Key_A + (k - kNamed));
    // Ctrl+Z (Undo) now and then; never Ctrl+Q
    const bool undo = chance(0.03);
    const Qt::KeyboardModifiers mods = undo          ? Qt::ControlModifier
                                       : chance(0.1) ? Qt::ShiftModifier
                                                     : Qt::NoModifier;
    QWidget* w = QApplication::focusWidget();
    if (!w || !w->isVisible() || chance(0.3)) w = fallback;
    if (!w) return;
    const Qt::Key sent = undo ? Qt::Key_Z : key;
    gLog.add(QString("key %1 on %2").arg(QKeySequence(int(mods) | sent).toString()).arg(describe(w)));
    QTest::keyClick(w, sent, mods);
  }
  void action() {
    QAction* a = any(actions());
    if (!a) return;
    gLog.add("action \"" + a->text() + "\"" +
             (a->parent() ? QString(" of ") + a->parent()->metaObject()->className() : QString()));
    a->trigger();
  }
  void dock() {
    if (!window_) return;
    QDockWidget* d = any(window_->findChildren<QDockWidget*>());
    if (!d) return;
    const int what = pick(3);
    gLog.add(QString("dock '%1': %2")
                 .arg(d->objectName(), what == 0   ? (d->isFloating() ? "docked" : "floated")
                                       : what == 1 ? (d->isVisible() ? "hidden" : "shown")
                                                   : "resized"));
    if (what == 0)
      d->setFloating(!d->isFloating());
    else if (what == 1)
      d->setVisible(!d->isVisible());
    else
      d->resize(100 + pick(600), 100 + pick(500));
  }
  void closeWindow() {
    QList<QWidget*> others;
    for (QWidget* w : windows())
      if (w != window_ && !qobject_cast<QMenu*>(w)) others << w;
    QWidget* w = any(others);
    if (!w) return;
    gLog.add("close " + describe(w));
    w->close();
  }
  // one window of the Windows menu (a chart, a plot, the apex, ...) or a dock shown again
  void openWindow() {
    const QList<QAction*> all = windowActions();
    if (all.isEmpty()) return;
    QAction* a = all[pick(all.size())];
    gLog.add("open window \"" + a->text() + "\"");
    if (a->isCheckable())
      a->setChecked(true);
    else
      a->trigger();
  }
  // the Windows menu's entries, with its Charts submenu's or without
  QList<QAction*> windowActions(bool withCharts = true) const {
    QList<QAction*> out;
    if (!window_) return out;
    for (QAction* m : window_->menuBar()->actions())
      if (m->menu() && m->text().remove('&') == "Windows")
        for (QAction* a : m->menu()->actions()) {
          if (a->menu() && withCharts)
            out << a->menu()->actions();
          else if (!a->menu() && !a->isSeparator())
            out << a;
        }
    return out;
  }
  QList<QAction*> chartActions() const {
    QList<QAction*> all = windowActions(true);
    for (QAction* a : windowActions(false))
      all.removeOne(a);
    return all;
  }
  void pause() {
    const int ms = 20 + pick(200);
    gLog.add(QString("wait %1 ms").arg(ms));
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms)
      QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
  }

  // one random event
  void event() {
    // an open popup (a menu, a combo box's list): now and then something in it is clicked, else it goes
    if (QWidget* popup = QApplication::activePopupWidget(); popup && chance(0.5)) {
      gLog.add("popup " + describe(popup) + ": closed");
      popup->close();
    }
    const int r = pick(100);
    QWidget* w = target();
    if (r < 28 && w)
      click(w);
    else if (r < 42 && w)
      drag(w);
    else if (r < 52 && w)
      wheel(w);
    else if (r < 66)
      key(w);
    else if (r < 80)
      action();
    else if (r < 87)
      dock();
    else if (r < 91)
      openWindow();
    else if (r < 95)
      closeWindow();
    else
      pause();
  }

  // Runs what the monkey does; an exception out of it (out of a slot or an event handler: in the application
  // it ends the process) fails the test, with what it was, the seed and the last events
  void guarded(const std::function<void()>& f) {
    try {
      f();
    } catch (const std::exception& e) {
      gBad << QString("exception out of the event: ") + e.what();
    }
  }

  // what failed, with the seed and the last events
  QByteArray failure(const QString& why) const {
    return (why + "\n" + QString::fromStdString(gLog.text())).toUtf8();
  }

  // opens every window of the Windows menu and every dock, their dialogs accepted; of the charts (a dozen,
  // each computed on a worker thread) three at random: the seed list covers them all
  void openEveryWindow() {
    acceptAll_ = true;
    QList<QAction*> all = windowActions(false);
    QList<QAction*> charts = chartActions();
    for (int i = 0; i < 3 && !charts.isEmpty(); ++i)
      all << charts.takeAt(pick(charts.size()));
    for (QAction* a : all) {
      gLog.add("open window \"" + a->text() + "\" (every window)");
      guarded([a] {
        if (a->isCheckable())
          a->setChecked(true);
        else
          a->trigger();
        QCoreApplication::processEvents();
      });
    }
    acceptAll_ = false;
  }

  // one phase: a scene (or a sweep over the open one), every window, then the random events
  bool phase(const QString& name, const std::function<bool()>& open) {
    QElapsedTimer clock;
    clock.start();
    gLog.add("phase " + name);
    if (!open()) {
      gLog.add("phase " + name + ": could not open");
      return false;
    }
    openEveryWindow();
    if (!gBad.isEmpty()) return false;
    for (int i = 0; i < eventsPerPhase_ && window_; ++i) {
      // an exception out of a slot or an event handler is a failure too (Qt does not promise to survive one);
      // said with what it was, the seed and the last events
      guarded([this] {
        closeModal();
        event();
        QCoreApplication::processEvents();
      });
      if (!gBad.isEmpty()) return false;
    }
    qInfo("seed %u, %s: %.1f s", gLog.seed, qPrintable(name), clock.elapsed() / 1000.0);
    return true;
  }

private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    gPrevious = qInstallMessageHandler(onMessage); // after QTest's own, which it chains to
    QTest::ignoreMessage(QtWarningMsg, "monkey: QObject:: the handler sees this");
    qWarning("monkey: QObject:: the handler sees this");
    QVERIFY2(gBad.size() == 1, "the message handler does not see Qt's warnings");
    gBad.clear();
    for (int sig : {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL})
      std::signal(sig, onFatalSignal);
    if (__sanitizer_set_death_callback) __sanitizer_set_death_callback(dumpLog);
    gLog.verbose = qEnvironmentVariableIntValue("ROLLVIZ_MONKEY_VERBOSE") != 0;
    registerBuiltinTools(); // as the application does at start (scenes/ModuleLoader.h)
    setModelCompilation(ModelCompilation::InBackground); // as the GUI: its thread never waits for a compiler
    connect(&dialogs_, &QTimer::timeout, this, &MonkeyTest::closeModal);
    dialogs_.start(30);
  }

  void monkey_data() {
    QTest::addColumn<unsigned>("seed");
    for (unsigned s : seedsFromEnv())
      QTest::newRow(qPrintable(QString("seed %1").arg(s))) << s;
  }

  void monkey() {
    QFETCH(unsigned, seed);
    const int events = qEnvironmentVariableIsSet("ROLLVIZ_MONKEY_EVENTS")
                           ? qEnvironmentVariableIntValue("ROLLVIZ_MONKEY_EVENTS")
                           : kDefaultEvents;
    eventsPerPhase_ = std::max(1, events / 4);
    rng_.seed(seed);
    gLog = EventLog{};
    gLog.verbose = qEnvironmentVariableIntValue("ROLLVIZ_MONKEY_VERBOSE") != 0;
    gLog.seed = seed;
    gLog.events = events;
    gLog.clock.start();
    gBad.clear();
    gWarnings.clear();
    QElapsedTimer clock;
    clock.start();

    window_ = new MainWindow;
    window_->resize(1400, 900);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_));
    const auto scene = [this](const std::string& path) {
      return [this, path] { return window_ && window_->openScene(QString::fromStdString(path)); };
    };
    const std::string map = chance(0.5) ? "henon_map" : "standard_map";
    const std::string body = chance(0.5) ? defaultScenePath("chaplygin_ball")
                                         : scenesDirectory() + "/gallery/rattleback_reversal.json";
    // a small sweep as WindowTest writes one: megno over Henon-Heiles' section, or the Henon map's fixed
    // point types over (a, b) (the latter has the "Bifurcation curve" button)
    const QString sweepPath = dir_.filePath(QString("sweep-%1.json").arg(seed));
    const nlohmann::json sweep =
        chance(0.5) ? nlohmann::json{{"scene", defaultScenePath("henon_heiles")},
                                     {"axes",
                                      {{{"id", "map.0"}, {"min", -0.2}, {"max", 0.2}, {"count", 4}},
                                       {{"id", "map.1"}, {"min", -0.2}, {"max", 0.2}, {"count", 3}}}},
                                     {"quantity", "megno"},
                                     {"set", {{"megno.time", 50}}}}
                    : nlohmann::json{{"scene", defaultScenePath("henon_map")},
                                     {"axes",
                                      {{{"id", "a"}, {"min", 0.0}, {"max", 1.5}, {"count", 6}},
                                       {{"id", "b"}, {"min", -0.5}, {"max", 0.5}, {"count", 5}}}},
                                     {"quantity", "fixedpoint.type"},
                                     {"set",
                                      {{"fixedpoint.guess", {0.63, 0.19}},
                                       {"bifurcation_curve.kind", "period_doubling"}}}};
    QVERIFY(writeJson(sweepPath, sweep));
    const std::vector<std::pair<QString, std::function<bool()>>> phases = {
        {"flow: lorenz", scene(defaultScenePath("lorenz"))},
        {"map: " + QString::fromStdString(map), scene(defaultScenePath(map))},
        {"rolling body: " + QFileInfo(QString::fromStdString(body)).baseName(), scene(body)},
        {"sweep: " + QString::fromStdString(sweep["quantity"].get<std::string>()),
         [this, sweepPath] { return window_ && (focus_ = window_->openSweep(sweepPath)); }}};
    for (const auto& [name, open] : phases) {
      const bool ok = phase(name, open);
      if (!gBad.isEmpty()) break;
      QVERIFY2(window_, failure("the main window went").constData());
      QVERIFY2(ok, failure("phase " + name + " could not start").constData());
    }
    const QStringList bad = gBad;
    gLog.add("the main window deleted");
    delete window_;                                    // its windows and jobs with it
    for (QWidget* w : QApplication::topLevelWidgets()) // what a user closes by hand
      if (w->isVisible()) w->close();
    QCoreApplication::processEvents();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    QVERIFY2(
        bad.isEmpty() && gBad.isEmpty(),
        failure("a Qt warning about a deleted object or a thread: " + (bad + gBad).join(" | ")).constData());
    QString summary;
    for (const auto& [text, n] : gWarnings)
      summary += QString("\n  %1 × %2").arg(n).arg(text);
    qInfo("seed %u: %d events in %.1f s; Qt warnings:%s", seed, events, clock.elapsed() / 1000.0,
          summary.isEmpty() ? " none" : qPrintable(summary));
  }

  void cleanupTestCase() {
    dialogs_.stop();
    qInstallMessageHandler(gPrevious);
  }
};

} // namespace rv

int main(int argc, char** argv) {
  // nothing the monkey does is written outside a temporary HOME (settings, recent scenes, saved jobs,
  // the pictures folder proposed by Snapshot)
  QTemporaryDir home;
  if (!home.isValid()) return 2;
  qputenv("HOME", home.path().toUtf8());
  for (const char* xdg : {"XDG_CONFIG_HOME", "XDG_DATA_HOME", "XDG_CACHE_HOME", "XDG_STATE_HOME"})
    qunsetenv(xdg);
  qputenv("QT_XCB_GL_INTEGRATION", "xcb_glx"); // VTK 9.1's GLEW needs a GLX context (as in GuiMain)
  QSurfaceFormat::setDefaultFormat(rv::QtVtkWidget::defaultFormat());
  QStandardPaths::setTestModeEnabled(true);
  QApplication::setAttribute(Qt::AA_DontUseNativeDialogs); // Qt's own dialogs, which the monkey can close
  QApplication app(argc, argv);
  QApplication::setOrganizationName("rollviz-monkey");
  rv::MonkeyTest t;
  return QTest::qExec(&t, argc, argv);
}
#include "MonkeyTest.moc"
