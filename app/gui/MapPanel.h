// MapPanel.h -- the map window (manual §2.1, Fig. 3): the Poincare map of the scene as a chart, fed by one
// Poincare job per trajectory. A click on the map (in the "trajectories" mode, or Ctrl+click in any) starts a
// new trajectory there (the point is completed through the scene's energy and other integrals); in the "fixed
// points" mode (or Shift+click) it searches a fixed point of the map from there (manual §2.3.4: the search
// path is drawn, the point, its multipliers and type reported); in the "pan / zoom" mode a drag moves the
// chart. "Colour by MEGNO" computes the chaos indicator <Y> of each trajectory (a MEGNO job under its
// trajectory's, with the scene's megno settings) and colours its points by it: blue near 2 (a torus), red
// from 8 up (chaos), hue between; 0 (a stable periodic orbit of a map) is blue too. The jobs run on their own
// threads; this panel only draws. The fixed-point tools on the map live in MapPanelTools.cpp.
#pragma once
#include "app/gui/ChartWindow.h"
#include "app/gui/Map3DWindow.h"
#include "app/gui/MapFilters.h"
#include "app/gui/MapTrajectories.h"
#include "dynamics/jobs/JobTree.h"
#include "dynamics/jobs/PlotTap.h"
#include "render/charts/PoincareChart.h"
#include "scenes/Scene.h"
#include "scenes/SceneLoader.h"
#include "scenes/Session.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QWidget>
#include <array>
#include <complex>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;

namespace rv {

class QtVtkWidget;
class MultipliersWindow;
class PlotWindow;
class PoincareTask;
class ToolTask;
class MegnoTask;

class MapPanel : public QWidget {
  Q_OBJECT
public:
  /// What a plain click on the map does.
  enum class ClickMode { Trajectory, FixedPoint, Navigate };
  explicit MapPanel(QWidget* parent = nullptr);
  void setClickMode(ClickMode mode);
  ClickMode clickMode() const { return clickMode_; }
  ~MapPanel() override;
  /// Drops every trajectory and tool of the map and, with `startTrajectory`, starts one at the scene's
  /// initial state (the scene must outlive the panel's use).
  void setScene(const Scene& scene, bool startTrajectory = true);
  /// Takes a scene that defines the same map (problem, parameters, method, section): everything on the map
  /// stays; new clicks use the new scene (e.g. its number of points).
  void keepScene(const Scene& scene);
  /// Starts a trajectory at the scene's initial state, the one setScene starts.
  void startSceneTrajectory();
  /// The top-level jobs that belong to the scene (trajectories, searches, families; not the chart and sweep
  /// windows' jobs, which compute their own scene): what setScene deletes.
  std::vector<int> sceneJobs() const;
  /// sceneJobs() less the trajectory setScene started: what the user added.
  std::vector<int> addedJobs() const;
  /// Starts a trajectory at map coordinates (x, y); false (with a message) when there is no state there. A
  /// flow without map coordinates of its own (Lorenz) starts from the scene's state with the map's axes and
  /// the section's variable set to the point clicked (where they are state variables), and says so.
  bool startAt(double x, double y);
  /// Starts a fixed-point search (the scene's fixedpoint settings) from map coordinates (x, y).
  void searchFixedPointAt(double x, double y);
  /// Grows the four separatrices of the fixed point found from the scene's fixedpoint settings (one job per
  /// branch, each the separatrix tool's runner, drawn as they grow).
  void startSeparatrices();
  /// Continues the scene's fixed point (its continuation settings); the family is drawn on the map and each
  /// change of type reported.
  void startContinuation();
  /// Continues the fixed point search `id` found (a Shift+click's) with the scene's continuation settings
  /// (the control panel's continuation tab: parameter, end value, step, method); false (with a message)
  /// when that search found no point. The map's context menu on a found point offers it.
  bool continueFixedPoint(int id);
  /// The search whose fixed point is drawn within a few pixels of the view's pixel `at` (Qt's, from the top
  /// left), or -1: what the map's context menu offers to continue.
  int fixedPointAt(const QPoint& at) const;
  /// The period doublings the last continuation of the scene's fixed point located, in the order found, each
  /// as "period doubling at a = ...": where followDoubledFamily(k) can switch.
  const std::vector<QString>& locatedDoublings() const { return doublings_; }
  /// Branch switching: continues the family of doubled order born at the k-th (1-based) located period
  /// doubling (continuation.switch = k) as a new job; it is drawn on the map like any family.
  void followDoubledFamily(int k);
  /// The map points a tool's job (a family, a tree, a separatrix) has drawn so far; empty for another job.
  std::vector<std::pair<double, double>> toolPoints(int id) const;
  /// The period-doubling tree of the scene's fixed point (bifurcation_tree section); its families drawn.
  void startBifurcationTree();
  /// Runs registered tool `id` (ToolWindow::MapRows) on the scene as a job of the map window that draws its
  /// rows as they come: Tools > Create of any such tool, a module's included.
  void startRows(const std::string& id);
  /// A fixed-point search from the scene's fixedpoint.guess.
  void searchFromGuess();
  /// The scene document a search or a map tool runs on (default: the scene's). The main window gives the
  /// scene with the control panel's tool tabs as they are shown, so a tool runs with its settings (the
  /// continuation's parameter, end value and step) without an Apply first; what defines the map (problem,
  /// method, section) stays the scene's.
  void setToolDocument(std::function<nlohmann::json()> document) { toolDocument_ = std::move(document); }
  /// Deletes every trajectory and tool of the map and puts the saved trajectories and tool outputs in their
  /// place (Undo, Open session).
  void replaceTrajectories(const std::vector<SavedTrajectory>& saved,
                           const std::vector<SavedToolOutput>& tools = {});
  /// What the fixed-point tools among jobs `ids` (empty: all) drew -- searches, families, separatrices,
  /// trees -- with their multipliers and outcome (a running one: what it drew so far).
  std::vector<SavedToolOutput> saveToolOutputs(const std::vector<int>& ids) const;
  /// Draws saved tool outputs again, each as a finished job of the tool manager that computes nothing (a
  /// record: its multipliers reach the filters, Delete and Undo work on it as on any tool).
  void restoreToolOutputs(const std::vector<SavedToolOutput>& saved);
  /// The running trajectories, stopped and saved (their settings, whole state and points) to go on after a
  /// restart (MainWindow saves them when it closes); an empty array when none runs.
  nlohmann::json saveRunning();
  /// Goes on with trajectories saveRunning() saved, under the current scene; returns how many. Throws
  /// InputError when the saved data do not fit the scene.
  int resume(const nlohmann::json& saved);
  /// Takes the points computed since the last call, as many as a few milliseconds allow (kDrainMilliseconds;
  /// the rest on the next call), and redraws; called by the window's frame timer. True when there was
  /// something new (the map is redrawn).
  bool drain();
  void stopAll();
  /// The jobs of the map window (trajectories and the tools started from it), for the tool manager.
  JobTree& jobs() { return jobs_; }
  /// Deletes a job and those under it, with what the panel draws of them.
  void removeJob(Job& job);
  /// Edit properties (manual §2.1): gives the job (stopped first) the edited scene's values (scenes/
  /// SceneTools editTask); a tool that starts again with them loses what it drew. Throws InputError when it
  /// cannot take them.
  void editJob(Job& job, const Scene& edited);
  /// Forgets what the job drew (on the map and in the filters): it starts again (Restart).
  void clearOutput(int id);
  /// Draws the trajectory of job `id` emphasised (-1, or a job that is not a trajectory: none).
  void highlightJob(int id);
  /// Colours every trajectory, those running and those to come, by its MEGNO <Y> (a MEGNO job each, under
  /// the trajectory's job, started once); off gives back their own colours.
  void setColourByMegno(bool on);
  bool colourByMegno() const { return trajectories_.colourByMegno(); }
  /// Opens (or shows) the Map3D window of a 3D map (manual §2.1: the full map beside its projection), fed
  /// with the trajectories' points as they come; nullptr (with a message) for a 2D map.
  QWidget* openMap3D();
  /// Feeds an open 2D / 3D plot filter (manual §2.4) with every trajectory of the map, those running now and
  /// those started later; the window is drawn on each drain() until it closes.
  void addPlotWindow(PlotWindow* window);
  /// Feeds an open multipliers filter (manual §2.4.3) with the fixed points of every continuation and
  /// bifurcation tree of the map window, those computed so far and those to come.
  void addMultipliersWindow(MultipliersWindow* window);
  /// Marks every trajectory of the map (in its colour) on an open bifurcation diagram window (manual §2.4.4:
  /// a trajectory is a point on the plane of first integrals), kept up to date as trajectories come, go and
  /// are edited.
  void addDiagramWindow(ChartWindow* window);
  /// The open plot filters (the 3D view's run offers them its states too).
  std::vector<PlotWindow*> plotWindows();
  /// Points drawn in the Map3D window (tests).
  long map3DPoints() const;
  long points() const;
  /// The map's trajectories (app/gui/MapTrajectories.h): where they start, their points, colours, ranges,
  /// MEGNO; saved and restored.
  MapTrajectories& trajectories() { return trajectories_; }
  const MapTrajectories& trajectories() const { return trajectories_; }
  /// Fixed-point searches started, and how many found a point.
  int searches() const { return static_cast<int>(searches_.size()); }
  int fixedPointsFound() const;
  /// Jobs of other tools drawn on the map (separatrix branches, continuations).
  int toolJobs() const { return static_cast<int>(tools_.size()); }
  QtVtkWidget* view() const { return view_; }
  /// The map chart (to export it).
  const PoincareChart& chart() const { return *chart_; }
  /// Zooms the map to these ranges (x0, x1, y0, y1), held as a user's zoom is.
  void setMapRanges(const std::array<double, 4>& r);

signals:
  void message(const QString& text);
  /// A job was deleted (with what the panel drew of it).
  void jobRemoved(int id);

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  std::function<nlohmann::json()> toolDocument_;
  nlohmann::json toolDocument() const { return toolDocument_ ? toolDocument_() : scene_->document; }
  /// startAt for a flow without map coordinates: returns what it did, in words, and the trajectory's job.
  std::pair<QString, int> startOnSection(double x, double y);
  /// Starts a trajectory at a full state, from `origin` (map coordinates; empty: its first point).
  Job& start(const Eigen::VectorXd& state, const QString& origin = {});
  QCheckBox* megnoBox_;
  QLabel* megnoLegend_;
  QLabel* cursorLabel_; ///< the map coordinates under the cursor
  std::array<std::string, 2> axisNames_{"x", "y"};
  struct Search {
    Job* job;
    ToolTask* task; ///< the fixedpoint tool's run; null for a restored record
    std::vector<double> x, y;
    int path, point;
    int found = -1; ///< the point found, as a marker of its own
    bool reported = false;
    std::vector<std::complex<double>> multipliers; ///< of the point found (empty: none yet)
    QString caption;                               ///< the point, its type and multipliers, in words
    std::vector<double> foundAt;                   ///< the point found, on the map (empty: none)
    int run = 0;                                   ///< the task's run its path is drawn from
  };
  /// Draws the searches' new steps and reports those that ended; true when something was drawn.
  bool drainSearches();
  /// The colour of a fixed-point search's path and point.
  static constexpr Rgb kSearchColour{0.9, 0.1, 0.1};
  std::vector<double> mapPoint(double x, double y) const;
  std::vector<Search> searches_;
  // the output of other tools drawn on the map: `pull` appends what arrived to x, y and says whether
  // anything did
  struct ToolSeries {
    Job* job;
    int plot;
    Rgb colour;
    std::vector<double> x, y;
    std::function<bool(ToolSeries&)> pull;
    /// the multipliers of a family's points (continuation, tree), kept for filters opened later
    std::vector<std::pair<double, std::vector<std::complex<double>>>> multipliers;
    std::vector<double> along; ///< the continued parameter at each point drawn, where its rows carry it
    bool everyStep = false;    ///< a tree: each step is output (not by the filter's period)
    /// What the Results dock says once the job has finished and everything it made is drawn
    std::function<QString(const ToolSeries&)> ended;
    bool endSaid = false;
  };
  std::vector<ToolSeries> tools_;
  /// Starts registered tool `id` on the scene with `overrides` (kept by Edit properties) as a job drawn on
  /// the map as its rows come (ToolWindow::MapRows), in `colour` (else the next of a palette); `said` goes to
  /// the Results dock.
  void startMapRows(const std::string& id, const std::vector<SceneOverride>& overrides, const QString& said,
                    std::optional<Rgb> colour = std::nullopt);
  std::vector<QString> doublings_; ///< located by the last family followed from the scene's point
  /// Adds a tool's job, a series on the map for its output (`pull` fetches it), and starts it.
  void startTool(std::unique_ptr<Task> task, const Rgb& colour, std::function<bool(ToolSeries&)> pull,
                 std::function<QString(const ToolSeries&)> ended = {});
  /// A fixed point of a family: kept, and offered to the open multipliers filters.
  void offerMultipliers(ToolSeries& t, double parameter, const std::vector<std::complex<double>>& m);
  /// Where each trajectory lies on the scene's first bifurcation diagram; marks the diagram windows with it.
  void markDiagrams(bool force);
  /// The plot, multipliers and diagram windows the map feeds (app/gui/MapFilters.h).
  MapFilters filters_;
  QtVtkWidget* view_;
  ClickMode clickMode_ = ClickMode::Trajectory;
  QComboBox* modeBox_;
  std::unique_ptr<PoincareChart> chart_;
  /// Drops the Map3D chart (its series follow the trajectories); draws it again if `reopen` and it shows.
  void resetMap3D(bool reopen);
  std::unique_ptr<Map3DWindow> map3D_;
  const Scene* scene_ = nullptr;
  int sceneStart_ = -1; ///< the job of the trajectory setScene started
  JobTree jobs_;
  MapTrajectories trajectories_;
};

} // namespace rv
