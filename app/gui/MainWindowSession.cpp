// MainWindowSession.cpp -- what the main window keeps of the user's work: scenes and sessions saved and
// opened, Edit > Undo of what replaced the map or deleted trajectories, and the trajectories saved at exit.
#include "app/gui/MainWindow.h"

#include "app/gui/ChartWindow.h"
#include "app/gui/FilterWindow.h"
#include "app/gui/MapPanel.h"
#include "app/gui/SweepWindow.h"
#include "dynamics/io/AtomicFile.h"
#include "scenes/ModelFile.h"
#include "scenes/SceneLoader.h"
#include "scenes/ScenePage.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QSaveFile>
#include <QSettings>
#include <QTimer>
#include <fstream>

namespace rv {

bool MainWindow::mayReplaceMap(const QString& action) {
  const std::size_t added = map_->addedJobs().size(); // (the scene's own trajectory comes back with it)
  if (added == 0) return true;
  return QMessageBox::question(
             this, "rollviz",
             QString("%1 replaces the map window: the %2 tool(s) added to it (trajectories, fixed points, "
                     "families) will be deleted.\nEdit > Undo brings them back. Go on?")
                 .arg(action)
                 .arg(added),
             QMessageBox::Yes | QMessageBox::No, QMessageBox::No) == QMessageBox::Yes;
}

void MainWindow::updateUndoActions() {
  if (!undoAction_) return; // (before the menus are built)
  const QString undo = history_.undoText(), redo = history_.redoText();
  undoAction_->setEnabled(!undo.isEmpty());
  undoAction_->setText(undo.isEmpty() ? QString("Undo") : "Undo " + undo);
  redoAction_->setEnabled(!redo.isEmpty());
  redoAction_->setText(redo.isEmpty() ? QString("Redo") : "Redo " + redo);
}

QString MainWindow::undoText() const {
  return history_.undoText();
}

QString MainWindow::redoText() const {
  return history_.redoText();
}

Session MainWindow::mapAsItStands(bool goOn) const {
  Session map;
  map.scene = scene_->document;
  map.scenePath = scenePath_.toStdString();
  map.origin = origin_.toStdString();
  map.trajectories = map_->trajectories().save({}, false, goOn);
  map.tools = map_->saveToolOutputs({});
  if (map_->chart().rangesHeld()) map.gui["map_ranges"] = map_->chart().ranges(); // the user's zoom
  return map;
}

void MainWindow::useMapOf(const Session& map) {
  useSession(map, QString::fromStdString(map.scenePath), false);
  if (const auto r = map.gui.find("map_ranges"); r != map.gui.end())
    map_->setMapRanges(r->get<std::array<double, 4>>());
}

void MainWindow::rememberMapForUndo() {
  Session map = mapAsItStands(false); // they stop: the map is replaced next
  QString what = QString("(back to %1 with %2 trajectories").arg(sceneName()).arg(map.trajectories.size());
  what += map.tools.empty() ? QString(")") : QString(" and %1 tool outputs)").arg(map.tools.size());
  history_.push({what, std::move(map), {}, {}});
}

void MainWindow::rememberDeletedForUndo(const std::vector<int>& roots) {
  std::vector<int> ids;
  for (int id : roots)
    if (Job* j = map_->jobs().find(id))
      for (const Job* k : map_->jobs().subtree(*j))
        ids.push_back(k->id());
  if (ids.empty()) return;
  auto deleted = map_->trajectories().save(ids, false, false);
  auto tools = map_->saveToolOutputs(ids);
  if (deleted.empty() && tools.empty()) return; // nothing drawn among them: nothing Undo could give back
  QStringList parts;
  if (!deleted.empty())
    parts << QString("%1 trajector%2").arg(deleted.size()).arg(deleted.size() > 1 ? "ies" : "y");
  if (!tools.empty()) parts << QString("%1 tool output%2").arg(tools.size()).arg(tools.size() > 1 ? "s" : "");
  history_.push(
      {"(delete of " + parts.join(" and ") + ")", std::nullopt, std::move(deleted), std::move(tools)});
}

bool MainWindow::undo() {
  if (!scene_) return false;
  std::optional<MapHistory::Step> step = history_.takeUndo();
  if (!step) return false;
  // Redo puts back the map as it stands now, whatever the step was (a replaced map, a delete); its running
  // trajectories go on (a delete's undo keeps the map)
  Session now = mapAsItStands(true);
  try {
    if (step->map)
      useMapOf(*step->map);
    else {
      map_->trajectories().restore(step->deleted);
      map_->restoreToolOutputs(step->deletedTools);
    }
  } catch (const std::exception& e) {
    report(QString("cannot undo %1: %2").arg(step->what, e.what()), 0);
    return false;
  }
  history_.undone(step->what, std::move(now));
  report("undone: " + step->what, 5000);
  return true;
}

bool MainWindow::redo() {
  if (!scene_) return false;
  std::optional<MapHistory::Step> step = history_.takeRedo();
  if (!step) return false;
  Session now = mapAsItStands(true);
  try {
    useMapOf(*step->map);
  } catch (const std::exception& e) {
    report(QString("cannot redo %1: %2").arg(step->what, e.what()), 0);
    return false;
  }
  // Undo again goes back to the map before this redo
  history_.redone(step->what, std::move(now));
  report("redone: " + step->what, 5000);
  return true;
}

void MainWindow::useSession(const Session& session, const QString& file, bool remember) {
  const std::string source = session.scenePath.empty() ? file.toStdString() : session.scenePath;
  auto scene = std::make_unique<Scene>(sceneFromJson(session.scene, source));
  if (remember && scene_) rememberMapForUndo();
  useScene(std::move(scene), QString::fromStdString(session.scenePath),
           QString::fromStdString(session.origin), MapUse::Restore);
  try {
    map_->replaceTrajectories(session.trajectories, session.tools);
  } catch (const std::exception&) {
    map_->startSceneTrajectory(); // the map is not left empty
    throw;
  }
}

Session MainWindow::currentSession() const {
  Session session;
  session.scene = documentWithEdits();
  session.scenePath = scenePath_.toStdString();
  session.origin = origin_.toStdString();
  session.trajectories = map_->trajectories().save({}, false, true); // running ones go on
  session.tools = map_->saveToolOutputs({});
  session.results = results().toStdString();
  return session;
}

bool MainWindow::saveSessionTo(const QString& path, QString* why) {
  if (!scene_) return false;
  Session session = currentSession();
  session.gui = {{"layout", saveState().toBase64().toStdString()}};
  // the chart and sweep windows open, to be opened again (a chart computes again with its document; a
  // sweep goes on from its store)
  nlohmann::json windows = nlohmann::json::array();
  for (const ChartWindow* w : findChildren<ChartWindow*>())
    if (w->isVisible())
      windows.push_back({{"chart", w->viewName()}, {"diagram", w->diagram()}, {"document", w->document()}});
  for (const SweepWindow* w : findChildren<SweepWindow*>())
    if (w->isVisible()) windows.push_back({{"sweep", w->spec().source}});
  session.gui["windows"] = windows;
  try {
    writeSession(session, path.toStdString());
  } catch (const std::exception& e) {
    report(QString("Cannot save the session: %1").arg(e.what()), 0);
    if (why) *why = e.what();
    return false;
  }
  rememberRecent(path);
  report(QString("saved the session (%1 trajectories) to %2").arg(session.trajectories.size()).arg(path),
         5000);
  return true;
}

int MainWindow::exportPageTo(const QString& path) {
  if (!scene_) return -1;
  Session session = currentSession(); // the motion of the scene shown, its map beside it
  nlohmann::json document = session.scene;
  Job& job = map_->jobs().add(std::make_unique<PageTask>(std::move(document), scene_->source,
                                                         std::move(session), path.toStdString()));
  job.start();
  report("writing the web page " + path + " (tool manager: its progress, Stop)", 5000);
  // its outcome in the Results dock once it ends (the job may be removed from the tool manager before)
  auto* watch = new QTimer(this);
  const int id = job.id();
  connect(watch, &QTimer::timeout, this, [this, watch, id, path] {
    const Job* j = map_->jobs().find(id);
    if (j && j->running()) return;
    watch->deleteLater();
    if (!j) return;
    if (j->status() == Job::Status::Finished)
      report("wrote the web page " + path + ": it plays, turns and scrubs in any browser, offline", 8000);
    else if (j->status() == Job::Status::Failed)
      report("Cannot write the web page: " + QString::fromStdString(j->error()), 0);
  });
  watch->start(200);
  return id;
}

void MainWindow::exportPageDialog() {
  const QString path =
      askWhereToWrite("Export web page", QStandardPaths::DocumentsLocation, "html", "Web page (*.html)");
  if (!path.isEmpty()) exportPageTo(path);
}

bool MainWindow::openSession(const QString& path) {
  try {
    const Session session = readSession(path.toStdString());
    useSession(session, path, true); // what was open goes to Undo
    results_->setPlainText(QString::fromStdString(session.results));
    if (const auto layout = session.gui.find("layout"); layout != session.gui.end() && layout->is_string())
      restoreState(QByteArray::fromBase64(QByteArray::fromStdString(layout->get<std::string>())));
    reopenWindows(session.gui);
    rememberRecent(QFileInfo(path).absoluteFilePath());
    report(QString("opened the session %1 (%2 trajectories)")
               .arg(QFileInfo(path).fileName())
               .arg(session.trajectories.size()),
           5000);
    return true;
  } catch (const std::exception& e) {
    QMessageBox::warning(this, "rollviz", QString("Cannot open the session:\n%1").arg(e.what()));
    return false;
  }
}

QString MainWindow::besideTheScene(const QString& name) const {
  // the scene's own folder when it is the user's (writable, not the shipped scenes); else their documents
  const QFileInfo folder(QFileInfo(scenePath_).absolutePath());
  const bool shipped =
      folder.absoluteFilePath() == QFileInfo(QString::fromStdString(scenesDirectory())).absoluteFilePath();
  if (!scenePath_.isEmpty() && folder.isDir() && folder.isWritable() && !shipped)
    return QDir(folder.absoluteFilePath()).filePath(name);
  return proposedPath(QStandardPaths::DocumentsLocation, name);
}

void MainWindow::reopenWindows(const nlohmann::json& gui) {
  const auto windows = gui.find("windows");
  if (windows == gui.end() || !windows->is_array()) return;
  for (const auto& w : *windows) {
    if (!w.is_object()) continue;
    if (w.contains("chart") && w["chart"].is_string() && w.contains("document") && w["document"].is_object())
      openChartOf(w["document"], w["chart"].get<std::string>(), w.value("diagram", std::string()));
    else if (w.contains("sweep") && w["sweep"].is_string())
      openSweep(QString::fromStdString(w["sweep"].get<std::string>())); // says why when it cannot
  }
}

void MainWindow::saveSessionDialog() {
  if (!scene_) return;
  const QString path = QFileDialog::getSaveFileName(
      this, "Save session", besideTheScene(QFileInfo(scenePath_).completeBaseName() + "-session.json"),
      "Sessions (*.json)");
  QString why;
  if (!path.isEmpty() && !saveSessionTo(path, &why))
    QMessageBox::warning(this, "rollviz", "Cannot save the session:\n" + why);
}

void MainWindow::openSessionDialog() {
  const QString path = QFileDialog::getOpenFileName(
      this, "Open session", QFileInfo(besideTheScene("x")).absolutePath(), "Sessions (*.json)");
  if (!path.isEmpty() && mayReplaceMap("Opening " + QFileInfo(path).fileName())) openSession(path);
}

void MainWindow::saveDialog() {
  if (!scene_) return;
  const QString path = QFileDialog::getSaveFileName(
      this, "Save scene", besideTheScene(QFileInfo(scenePath_).fileName()), "Scenes (*.json)");
  QString why;
  if (!path.isEmpty() && !saveSceneTo(path, &why))
    QMessageBox::warning(this, "rollviz", "Cannot save the scene:\n" + why);
}

bool MainWindow::saveSceneTo(const QString& path, QString* why) {
  if (!scene_) return false;
  const nlohmann::json doc = sceneMovedTo(documentWithEdits(), scene_->source, path.toStdString());
  try {
    AtomicFile file(path.toStdString(), "scene");
    std::ofstream out(file.tempPath());
    out << doc.dump(2) << "\n";
    out.close();
    if (!out) throw std::runtime_error("cannot write " + path.toStdString());
    file.commit();
  } catch (const std::exception& e) {
    report(QString("Cannot save the scene: %1").arg(e.what()), 0);
    if (why) *why = e.what();
    return false;
  }
  rememberRecent(path);
  report("saved " + path, 5000);
  return true;
}

QString MainWindow::savedJobsPath() {
  return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + "/running-jobs.json";
}

int MainWindow::saveRunningJobs() {
  if (!scene_) return 0;
  const nlohmann::json trajectories = map_->saveRunning();
  if (trajectories.empty()) {
    QFile::remove(savedJobsPath());
    return 0;
  }
  const nlohmann::json saved{
      {"scene", scenePath_.toStdString()}, {"document", scene_->document}, {"trajectories", trajectories}};
  QDir().mkpath(QFileInfo(savedJobsPath()).absolutePath());
  QSaveFile file(savedJobsPath()); // written whole, then renamed
  const std::string text = saved.dump();
  if (!file.open(QIODevice::WriteOnly) || file.write(text.data(), static_cast<qint64>(text.size())) < 0 ||
      !file.commit())
    return 0;
  return static_cast<int>(trajectories.size());
}

int MainWindow::resumeSavedJobs() {
  QFile file(savedJobsPath());
  if (!file.open(QIODevice::ReadOnly)) return 0;
  const QByteArray text = file.readAll();
  file.close();
  QFile::remove(savedJobsPath()); // offered once, whatever comes of it
  try {
    const nlohmann::json saved = nlohmann::json::parse(text.constData(), text.constData() + text.size());
    const QString path = QString::fromStdString(saved.at("scene").get<std::string>());
    // the saved trajectories in place of the scene's own (which is among them when it ran)
    useScene(std::make_unique<Scene>(sceneFromJson(saved.at("document"), path.toStdString())), path, {},
             MapUse::Restore);
    int n = 0;
    try {
      n = map_->resume(saved.at("trajectories"));
    } catch (const std::exception&) {
      map_->startSceneTrajectory(); // the map is not left empty
      throw;
    }
    report(QString("continued %1 trajectories from the last session").arg(n), 5000);
    return n;
  } catch (const std::exception& e) {
    QMessageBox::warning(this, "rollviz",
                         QString("Cannot continue the saved trajectories:\n%1").arg(e.what()));
    return 0;
  }
}

void MainWindow::offerSavedJobs() {
  QFile file(savedJobsPath());
  if (!file.open(QIODevice::ReadOnly)) return;
  const auto saved = nlohmann::json::parse(file.readAll().toStdString(), nullptr, false);
  file.close();
  const std::size_t n =
      saved.is_object() && saved.contains("trajectories") ? saved["trajectories"].size() : 0;
  const QString scene = saved.is_object() ? QString::fromStdString(saved.value("scene", std::string())) : "";
  if (n == 0 ||
      QMessageBox::question(this, "rollviz",
                            QString("%1 trajectories of %2 were running when rollviz closed.\nContinue them?")
                                .arg(n)
                                .arg(QFileInfo(scene).fileName())) != QMessageBox::Yes) {
    QFile::remove(savedJobsPath());
    return;
  }
  resumeSavedJobs();
}

} // namespace rv
