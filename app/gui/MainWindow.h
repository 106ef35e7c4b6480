// MainWindow.h -- the main window: the 3D view of a scene with play / pause, reset and speed, and the docks
// around it (control panel, map, tool manager, Results). The motion is integrated on a TrajectoryStream
// thread; the GUI thread only draws. Its rooms: MainWindow.cpp (the scene, its run, the windows it opens),
// MainWindowMenus.cpp (toolbars, menus and their dialogs), MainWindowSession.cpp (scenes and sessions saved
// and opened, Undo, the jobs kept at exit); and the classes it holds: ApexWindow (the apex motion window),
// MapHistory (Undo's and Redo's steps), ViewEdits (the user's appearance edits), ViewRecorder (Record…).
#pragma once
#include "app/gui/MapHistory.h"
#include "app/gui/ViewEdits.h"
#include "dynamics/jobs/PlotTap.h"
#include "dynamics/jobs/TrajectoryStream.h"
#include "render/view/VisualScene.h"
#include "scenes/Scene.h"
#include "scenes/Session.h"

#include <nlohmann/json.hpp>

#include <QElapsedTimer>
#include <QFileSystemWatcher>
#include <QMainWindow>
#include <QStandardPaths>
#include <QTimer>
#include <memory>
#include <optional>

class QAction;
class QCloseEvent;
class QComboBox;
class QDockWidget;
class QDragEnterEvent;
class QDropEvent;
class QMenu;
class QDoubleSpinBox;
class QLabel;
class QPlainTextEdit;

namespace rv {

class ApexWindow;
class ViewRecorder;
class QtVtkWidget;
class ChartWindow;
class SweepWindow;
class PlotWindow;
class MultipliersWindow;
class VisualizerSettings;
class MapPanel;
class ControlPanel;
class ToolManager;

class MainWindow : public QMainWindow {
  Q_OBJECT
public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;
  /// Loads a scene file and starts it; on failure shows why and keeps the current scene.
  bool openScene(const QString& path);
  /// Opens a model file (docs/models.md) at its own "initial"; its model joins the problem list, and saving
  /// the file while it is open reloads it (the old model's jobs are stopped; the Results dock says so).
  bool openModel(const QString& path);
  /// Another problem chosen in the control panel: opens its default scene, after asking when the map window's
  /// tools (which belong to the current problem) would be deleted. False when the user keeps the problem.
  bool chooseProblem(const std::string& id);
  /// Runs a scene document (the control panel's edits; a sweep's cell, `origin` naming it in the title);
  /// on failure shows why and keeps the current scene.
  bool runDocument(const nlohmann::json& document, const QString& origin = {});
  /// Apply in the control panel: runs the edited document. The map window stays as it is when the edits
  /// leave its map the same (sameMap: the same problem, parameters, method and section -- a new number of
  /// points counts for the trajectories to come, a new initial state adds its trajectory); otherwise it is
  /// replaced, after asking (mayReplaceMap). False when the document is refused or the user keeps the map.
  bool applyDocument(const nlohmann::json& document);
  /// Before a user's action (`action`: "Apply", "Open ...") replaces the map window: asks whether its tools
  /// may go when the user added any (Edit > Undo brings the trajectories back); true at once when not.
  bool mayReplaceMap(const QString& action);
  /// Edit > Undo (Ctrl+Z): brings back what the last destructive action took -- a replaced map (its scene and
  /// every trajectory, going on where they stood) or deleted trajectories. False when there is nothing.
  bool undo();
  /// What Undo would bring back, in words ("" when nothing).
  QString undoText() const;
  /// Edit > Redo (Ctrl+Shift+Z): puts back the map as it stood before the last Undo (a new change forgets
  /// what was undone). False when there is nothing.
  bool redo();
  /// What Redo would put back, in words ("" when nothing).
  QString redoText() const;
  /// File > Save session: the scene as shown, every trajectory of the map (points, colour, range, the state
  /// to go on from), the Results log and the window's layout, in one JSON file (scenes/Session.h) written
  /// whole; false (the reason in Results and `why`) when it cannot.
  bool saveSessionTo(const QString& path, QString* why = nullptr);
  /// File > Export web page: the scene's motion (its map beside it) as a self-contained page, written by a
  /// job of the tool manager (scenes/ScenePage.h PageTask). Returns the job's id (-1: no scene).
  int exportPageTo(const QString& path);
  /// Opens a session file: its scene, its trajectories in place of the map's (those that ran go on, bit for
  /// bit), its Results log and layout. On failure shows why and keeps what is open.
  bool openSession(const QString& path);
  /// Where the map window's running trajectories are saved when the window closes (the next start offers to
  /// continue them): running-jobs.json in the application's data folder.
  static QString savedJobsPath();
  /// Saves the running trajectories with the scene they run under (written whole, then renamed); with none
  /// running, removes an old file. Called by closeEvent. Returns how many were saved.
  int saveRunningJobs();
  /// Goes on with the trajectories saved when rollviz last closed, under their scene (opened first); returns
  /// how many (0, with a message, when there are none or the file cannot be used). The file is removed.
  int resumeSavedJobs();
  /// At start: when trajectories were saved, asks whether to continue them (or to discard them).
  void offerSavedJobs();
  /// Whether the 3D view's run plays (Space toggles it).
  bool playing() const { return playing_; }
  /// Every action's shortcut and name, a line each (Help > Keyboard shortcuts).
  QString shortcutsText() const;
  /// Where Help > Guide goes: the built guide's index.html, else the folder of its pages.
  static QString guideLocation();
  /// Simulation time shown in the last frame.
  double shownTime() const { return shownTime_; }
  /// Whether the view shows the time asked for and nothing more is on its way: paused, the picture then
  /// holds still (what a test waits for instead of a fixed delay).
  bool caughtUp() const { return stream_ && stream_->idle() && shownTime_ == requested_; }
  QtVtkWidget* view() const { return view_; }
  MapPanel* mapPanel() const { return map_; }
  ControlPanel* controlPanel() const { return control_; }
  ToolManager* toolManager() const { return tools_; }
  const Scene* scene() const { return scene_.get(); }
  /// Shows a message in the status bar for `timeoutMs` (0: until the next) and keeps it, with the time, in
  /// the Results dock: the tools' results (fixed points and their multipliers, ...) and the reasons of
  /// failures stay there, copyable, until cleared.
  void report(const QString& text, int timeoutMs = 8000);
  /// The Results dock's text.
  QString results() const;
  /// The scene's name as the title and the status bar say it: its file, or where it came from ("a point of
  /// SWEEP.json" for a sweep's cell).
  QString sceneName() const;
  /// The status bar's text (the scene, its time, the method).
  QString statusText() const;

  /// Saves the scene as shown -- the settings' edits and the Results dock's lines (`results`) written in --
  /// through a temporary name; false (the reason in Results) when it cannot.
  bool saveSceneTo(const QString& path, QString* why = nullptr);
  /// Writes the 3D view as drawn to a PNG; false when it cannot.
  bool snapshotTo(const QString& path);
  /// Starts recording what the 3D view shows, from now on, into an MP4 of `fps` frames a second (0: the
  /// scene's video.fps; its crf and preset too) at the view's size: the run as it plays, camera moves and
  /// pauses included, the video as long as the recording (`rollviz video` renders exact frames offline
  /// instead). False (the reason in Results) when it cannot.
  bool startRecording(const QString& path, int fps = 0);
  /// Ends a recording; the file is finished on a worker thread, then recordingFinished().
  void stopRecording();
  bool recording() const;
  /// Opens a filter window with a chart view of the scene (computed on a worker thread); `diagram` picks the
  /// bifurcation view's diagram (empty: the problem's first).
  ChartWindow* openChart(const std::string& view, const std::string& diagram = "");
  /// The same for a given scene document (a session's chart windows open again with theirs).
  ChartWindow* openChartOf(const nlohmann::json& document, const std::string& view,
                           const std::string& diagram = "");
  /// Opens a sweep file (docs/sweeps.md) in a sweep window that runs it as a job; nullptr (and a message)
  /// when the file is bad.
  SweepWindow* openSweep(const QString& path);
  /// Asks which of the problem's bifurcation diagrams to open (manual §2.4.4: Diagram name) and opens it.
  void diagramDialog();
  /// Create in the control panel's Tools tab: starts tool `id` on the map or opens its chart window.
  void createTool(const std::string& id);
  /// Opens a live 2D or 3D plot filter (by the number of axes of `plot`) fed by the 3D view's run and by
  /// every trajectory of the map window; nullptr (with the reason in the status bar) when the settings do not
  /// fit the problem.
  PlotWindow* openPlotWindow(const PlotView& plot);
  /// Opens a live multipliers filter fed by the map window's continuations and bifurcation trees.
  MultipliersWindow* openMultipliersWindow();
  /// Asks for the plot filter's settings (axes, output condition, period, points; the scene's plot section
  /// proposed) and opens it; `dimensions` 2 or 3.
  void plotDialog(int dimensions);
  /// Opens (or shows) the apex motion window: the apex view of the trajectory shown in the 3D view, or of the
  /// map trajectory selected in the tool manager (manual §2.4.5: the Poincaré map outputs into it as it
  /// integrates, every 1/25 of a time unit).
  QWidget* openApexWindow();
  /// The apex motion window (app/gui/ApexWindow.h): what it follows and draws.
  const ApexWindow& apex() const { return *apex_; }
  VisualizerSettings* settings() const { return settings_; }
  VisualScene* visual() const { return visual_.get(); }

public slots:
  void togglePlay();
  /// Pauses and goes one frame (1/25 s times the real-time factor) further.
  void stepFrame();
  void restart();
  void snapshot();
  void openDialog();
  void saveDialog();
  void recordDialog();
  /// A file dialog proposing `<problem>-t<time>.<extension>` in the user's `where` folder; a name without an
  /// extension gets it, one with another is refused (said in a message box); empty: cancelled or refused.
  QString askWhereToWrite(const QString& title, QStandardPaths::StandardLocation where,
                          const QString& extension, const QString& filter);

signals:
  /// A recording's file is written (`ok`) or could not be (the reason in Results).
  void recordingFinished(bool ok, const QString& path);

protected:
  void closeEvent(QCloseEvent* e) override;
  void dragEnterEvent(QDragEnterEvent* e) override;
  void dropEvent(QDropEvent* e) override;

private:
  /// Puts a new top-level window over the 3D view, below the menu and toolbars, cascaded.
  void placeWindow(QWidget* w) const;
  /// The model file changed on disk: the scene runs again on the file's new content.
  void reloadModel();
  /// Watches the open scene's model file, if it has one.
  void watchModelFile();
  void tick();
  /// The scene's document with the settings panel's edits written in (what Save and Record use).
  nlohmann::json documentWithEdits() const;
  void editObject(const std::string& name, const ObjectOptions& o);
  void editAxes(const AxesOptions& a);
  void setStyleOfAll(SurfaceStyle style);
  /// The toolbar's style and axes boxes and the settings panel show what the 3D view draws (one source: the
  /// visual scene's options), after every edit and scene.
  void showViewSettings();
  QComboBox* styleBox_;
  QComboBox* axesBox_;
  /// The playback and visualizer toolbars (MainWindowMenus.cpp); the latter shows and hides `settingsDock`.
  void buildToolBars(QDockWidget* settingsDock);
  /// The menu bar (MainWindowMenus.cpp), after every dock exists (the Windows menu lists them).
  void buildMenus();
  void rememberRecent(const QString& path);
  void fillRecentMenu();
  void showStatus();
  /// Replaces the running scene (from `source`, a file or "edited"; `origin`, when given, names it in the
  /// title instead of the file).
  /// `map`: Replace the map window's content (remembered for Undo first), Keep it (the same map), or Restore:
  /// empty it for saved trajectories the caller puts in.
  enum class MapUse { Replace, Keep, Restore };
  /// The scene of a document; nullptr after saying why in a message box.
  std::unique_ptr<Scene> sceneOf(const nlohmann::json& document);
  void useScene(std::unique_ptr<Scene> scene, const QString& source, const QString& origin = {},
                MapUse map = MapUse::Replace);
  /// Edit > Undo and Redo's steps (app/gui/MapHistory.h); the menu's actions show them.
  MapHistory history_{[this] { updateUndoActions(); }};
  QAction* undoAction_ = nullptr;
  QAction* redoAction_ = nullptr;
  void updateUndoActions();
  /// The map as it stands (its scene, trajectories, tool outputs, the user's zoom): what Undo and Redo go
  /// back to. `goOn`: the running trajectories go on (else they stop: the map is replaced next).
  Session mapAsItStands(bool goOn) const;
  /// Shows a map Undo or Redo kept: its scene, trajectories and tool outputs, and the user's zoom.
  void useMapOf(const Session& map);
  /// The map as it stands, as an Undo step, before it is replaced.
  void rememberMapForUndo();
  /// The trajectories and tool outputs among jobs `roots` (and those under them), before Delete takes them.
  void rememberDeletedForUndo(const std::vector<int>& roots);
  /// Where a save dialog proposes a scene or session file `name`: beside the open scene when its folder is
  /// the user's, else in the documents folder (never the working directory).
  QString besideTheScene(const QString& name) const;
  /// Opens the chart and sweep windows a session lists (gui.windows).
  void reopenWindows(const nlohmann::json& gui);
  void saveSessionDialog();
  void exportPageDialog();
  /// The scene with the control panel's edits, the map's trajectories and tool outputs, the Results log.
  Session currentSession() const;
  void openSessionDialog();
  /// Puts a session's scene and trajectories in place (no question; with `remember`, what was open becomes an
  /// Undo step). Throws InputError, changing nothing, for a scene that cannot be run.
  void useSession(const Session& session, const QString& file, bool remember);
  QString origin_; ///< what the title names as the scene's source instead of its file ("" : the file)
  QtVtkWidget* view_;
  VisualizerSettings* settings_;
  QMenu* recentMenu_;
  QAction* recordAction_;
  ViewEdits edits_; ///< the appearance edits kept over re-runs (settings panel, toolbar)
  QAction* followAction_ = nullptr;
  std::unique_ptr<ApexWindow> apex_;
  /// Record… (app/gui/ViewRecorder.h): the view's pictures into a video.
  ViewRecorder* recorder_ = nullptr;
  /// A stopped recording's file is written (or why not): said in Results, recordingFinished().
  void recordingWritten(bool ok, const QString& path, const QString& why, double seconds, long frames);
  MapPanel* map_;
  ControlPanel* control_;
  ToolManager* tools_;
  QAction* playAction_;
  QDoubleSpinBox* speedBox_;
  QLabel* status_;
  QPlainTextEdit* results_;
  QTimer timer_;
  QElapsedTimer clock_;
  QString scenePath_;
  QFileSystemWatcher* modelWatcher_ = nullptr; ///< the open scene's model file, when it has one
  QTimer modelReload_;                         ///< a burst of writes to it reloads it once
  QString method_;                             ///< the integrator and its settings, for the status bar
  // destroyed in reverse order: the stream's thread stops before the scene it integrates goes away
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<VisualScene> visual_;
  std::unique_ptr<TrajectoryStream> stream_;
  TrajectoryStream::Batch batch_;
  double requested_ = 0, shownTime_ = 0;
  std::optional<double> lastStepEnd_; ///< the time at the end of the last step taken
  double lastStep_ = 0;
  bool playing_ = true;
  bool mapWaits_ = false; ///< the map drew in the last tick: this one is the 3D view's
  QString error_;
};

} // namespace rv
