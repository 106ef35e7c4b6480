// MapTrajectories.h -- the trajectories of the map window (manual §2.1): one Poincaré job each in the map's
// job tree, its points taken a few thousand at a time and drawn on the map chart in its colour and range
// (Set range), fed to the open plot filters, coloured by its MEGNO <Y> on request (a MEGNO job under its
// trajectory's), saved whole -- points, settings and the state to go on from -- and restored bit for bit.
// The map window (MapPanel) owns it, makes its chart and says where a trajectory starts.
#pragma once
#include "app/gui/ChartWindow.h"
#include "app/gui/Map3DWindow.h"
#include "dynamics/core/Diagram.h"
#include "dynamics/jobs/JobTree.h"
#include "dynamics/jobs/PlotTap.h"
#include "dynamics/tools/PoincareMap.h"
#include "scenes/Scene.h"
#include "scenes/Session.h"

#include <QElapsedTimer>
#include <QString>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace rv {

class MapFilters;
class MegnoTask;
class PlotWindow;
class PoincareChart;
class PoincareTask;

class MapTrajectories {
public:
  /// The trajectories' jobs go into `jobs`; `filters` has the plot windows they feed; `say` takes what the
  /// Results dock is to show, `redraw` asks for a frame of the map.
  MapTrajectories(JobTree& jobs, MapFilters& filters, std::function<void(const QString&)> say,
                  std::function<void()> redraw);
  ~MapTrajectories();
  MapTrajectories(const MapTrajectories&) = delete;
  MapTrajectories& operator=(const MapTrajectories&) = delete;

  /// The chart they are drawn on (made by the map window once) and the scene new ones run under.
  void setChart(PoincareChart* chart) { chart_ = chart; }
  void setScene(const Scene* scene) { scene_ = scene; }
  /// Forgets every trajectory (their jobs are removed by the caller).
  void clear();

  /// Starts a trajectory at a full state; `origin` says where (a click's map coordinates; empty: its first
  /// map point). Returns its job.
  Job& start(const Eigen::VectorXd& state, const QString& origin = {});
  /// Adds saved trajectories under the current scene, each with its points, colour and range; those that ran
  /// go on (bit for bit). Throws InputError, adding none, when one does not fit the scene.
  int restore(const std::vector<SavedTrajectory>& saved);
  /// The trajectories `ids` (empty: all; with `onlyRunning`, those running), each with its points and the
  /// state to go on from: stopped to be read, and started again with `goOn`.
  std::vector<SavedTrajectory> save(const std::vector<int>& ids, bool onlyRunning, bool goOn);
  /// A finished trajectory goes on for `more` points (bit for bit one longer run); false for a job that is
  /// not a trajectory, runs, or has no limit.
  bool morePoints(int id, long more);

  /// Takes what the jobs computed since the last call: MEGNO values that arrived colour their trajectories,
  /// and each trajectory's new points, as many as a few milliseconds allow (kDrainMilliseconds; the rest on
  /// the next call), are drawn. True when something was drawn.
  bool drain();
  /// Jobs `isGone` says are deleted: their trajectories go (a MEGNO job alone: its trajectory's own colour
  /// comes back).
  void remove(const std::function<bool(const Job*)>& isGone);
  /// Forgets what trajectory `id` drew (it starts again).
  void clearOutput(int id);

  /// Whether job `id` is a trajectory.
  bool contains(int id) const { return find(id) != nullptr; }
  int count() const { return static_cast<int>(series_.size()); }
  /// Where trajectory `id` starts, in map coordinates ("(x, y)": the click, else its first map point; empty
  /// before it has one or for no trajectory): what tells trajectories apart in the tool manager.
  QString origin(int id) const;
  /// The map points trajectory `id` has drawn so far, x and y (empty for no trajectory).
  std::pair<std::vector<double>, std::vector<double>> points(int id) const;
  /// Points of all trajectories.
  long points() const;
  /// The colour of a trajectory's points (manual §2.1: colour of output); false when `id` is not one.
  bool setColour(int id, const Rgb& colour);
  /// Which of a trajectory's points show (manual §2.1: Set range): the `first`-th to the `last`-th (1-based,
  /// inclusive; last <= 0: to the end). False when `id` is not a trajectory.
  bool setRange(int id, long first, long last);
  /// The points of trajectory `id` shown now.
  long shownPoints(int id) const;
  /// Colours every trajectory, those running and those to come, by its MEGNO <Y> (a MEGNO job each, under
  /// the trajectory's job, started once); off gives back their own colours.
  void setColourByMegno(bool on);
  bool colourByMegno() const { return colourByMegno_; }
  /// The MEGNO <Y> of trajectory `id` once its job has finished; nothing before, or for no trajectory.
  std::optional<double> megno(int id) const;
  /// The colour trajectory `id` is drawn in now (its own, or its MEGNO's); black for no trajectory.
  Rgb shownColour(int id) const;
  /// The colour of a MEGNO <Y>: hue from blue (2 and below) to red (8 and above).
  static Rgb megnoColour(double megno);
  /// The chart's series of trajectory `id` and its place among the trajectories, or (-1, -1).
  std::pair<int, int> plotOf(int id) const;
  /// A tap on trajectory `id` (its job samples its own steps for it from now on); nullptr when `id` is not a
  /// trajectory or the settings do not fit the problem.
  std::shared_ptr<PlotTap> tap(int id, const PlotSettings& settings);
  /// Feeds a plot filter with every trajectory, those running and those started later.
  void follow(PlotWindow* window);
  /// Where each trajectory lies on diagram `d` (manual §2.4.4), in its colour.
  std::vector<ChartWindow::Mark> marks(const Diagram& d) const;
  /// Every trajectory's points, for the Map3D window.
  std::vector<Map3DWindow::Track> tracks() const;

private:
  struct Series {
    Job* job;
    PoincareTask* task;
    std::vector<double> x, y, z; ///< z: the third coordinate of a 3D map
    int plot;
    Rgb colour;
    long first = 1, last = 0; ///< the range shown (Set range)
    Job* megnoJob = nullptr;  ///< the MEGNO job colouring it (under its job), once started
    MegnoTask* megno = nullptr;
    std::optional<double> megnoValue; ///< <Y> when that job has finished
    QString origin;                   ///< where a click started it (map coordinates); else its first point
    std::vector<MapPoint> pending;    ///< points taken from the job, drawn from pendingAt on
    std::size_t pendingAt = 0;
    QElapsedTimer since;         ///< since it started: a flow's orbit that never crosses the section
    bool noCrossingSaid = false; ///< is said once that it has not crossed it yet
  };
  /// How long a trajectory of a flow may run without a point before the map says why it may stay empty.
  static constexpr qint64 kNoCrossingMilliseconds = 4000;
  /// The most points of one trajectory a drain draws: a job can hand over 2^18 at once, and copying and
  /// drawing them in one turn would keep the window from answering for tens of milliseconds.
  static constexpr std::size_t kDrainPerTick = 1 << 16;
  static constexpr qint64 kDrainMilliseconds = 4; ///< the time a turn of the event loop spends taking points
  const Series* find(int id) const;
  Series* find(int id);
  /// Adds a series for a job and what follows it (plot filters, MEGNO colouring).
  Series& add(Job& job, PoincareTask* task, const Rgb& colour);
  /// A MEGNO job that has ended colours its trajectory; true when one did.
  bool takeMegnoValues();
  void startMegno(Series& s);
  /// Draws a trajectory in its own colour or its MEGNO's.
  void applyColour(const Series& s);
  /// The points of a trajectory its range shows: [first, second) of its indices.
  static std::pair<long, long> shownSpan(const Series& s);
  /// Draws the part of a trajectory its range shows.
  void drawSeries(const Series& s);
  /// Appends at most `most` of a trajectory's points not yet appended (taking the job's next ones when those
  /// taken are used up); returns how many.
  static std::size_t takePoints(Series& s, std::size_t most);

  JobTree& jobs_;
  MapFilters& filters_;
  std::function<void(const QString&)> say_;
  std::function<void()> redraw_;
  PoincareChart* chart_ = nullptr;
  const Scene* scene_ = nullptr;
  bool colourByMegno_ = false;
  std::vector<Series> series_;
};

} // namespace rv
