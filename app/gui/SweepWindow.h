// SweepWindow.h -- a chart of regimes (scenes/Sweep.h) in the GUI: the sweep runs as a Job of the tool
// manager (scenes/SweepTask: progress, stop, continue, restart, delete there) and the window fills in as its
// points arrive; a click on a cell (or on a point of a one-axis chart) opens that grid point's scene -- its
// parameters or its initial point -- in the main window: from the chart to the trajectory in one click.
// "Zoom" and a rectangle dragged on the chart compute that window at the same counts as a child job (its own
// store), shown in the same window; Back and Forward go through the zooms.
#pragma once
#include "app/gui/FilterWindow.h"
#include "dynamics/jobs/JobTree.h"
#include "scenes/Sweep.h"

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

class QPushButton;
class QRubberBand;

namespace rv {

class SweepWindow : public FilterWindow {
  Q_OBJECT
public:
  SweepWindow(JobTree& jobs, SweepSpec spec, QWidget* parent = nullptr);
  ~SweepWindow() override;
  /// The job computing the sweep (nullptr once deleted from the tool manager).
  Job* job() const;
  /// Points with a result so far.
  long done() const { return done_; }
  /// The grid point nearest to chart coordinates (x, y); -1 outside the grid.
  long pointAt(double x, double y) const;
  /// The grid point under a position of the view (widget coordinates); -1 where there is none.
  long pointUnder(const QPointF& position) const;
  /// Where a grid point's scene goes: to the main window, which may decline (the map kept): false then.
  using SceneOpener = std::function<bool(const nlohmann::json& document)>;
  void setSceneOpener(SceneOpener opener) { opener_ = std::move(opener); }
  /// Opens grid point `index` with the scene opener; the status says whether it was opened.
  void openPoint(long index);
  const SweepSpec& spec() const { return spec_; }
  /// A chart of two model parameters: follows the bifurcation of grid point `index`'s scene
  /// (bifurcation_curve.kind: its fixed point continued in the first axis' parameter toward either end) in
  /// the chart's plane as a job, and draws the curve over the chart when it is done. "Bifurcation curve" then
  /// a click on a cell does it.
  void startCurve(long index);
  /// The curves drawn over the chart.
  const std::vector<SweepOverlay>& overlays() const { return overlays_; }
  /// The job following a curve (nullptr when none runs).
  Job* curveJob() const;
  /// Computes the sweep over `bounds` (min, max of each axis) as a child job and shows it; the zooms after
  /// the one shown are dropped (as a browser's forward history). False, saying why, when the window is empty.
  bool zoomTo(const std::vector<double>& bounds);
  /// Shows the zoom before (Back) or after (Forward) the one shown; false where there is none.
  bool back();
  bool forward();
  /// Which zoom is shown (0: the sweep file's window) and how many there are.
  std::size_t zoomLevel() const { return at_; }
  std::size_t zooms() const { return history_.size(); }

signals:
  /// The job ended (finished, stopped or failed).
  void finished();

protected:
  const Chart* chart() const override { return chart_.get(); }
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  void poll();
  void showZoom(std::size_t zoom); // makes history_[zoom] the sweep shown
  void updateZoomButtons();
  void endDrag(); // hides the band
  struct Zoom {
    SweepSpec spec;
    int jobId;
  };
  std::vector<Zoom> history_; // the sweep file's window first, then each zoom
  std::size_t at_ = 0;
  SweepSpec spec_;
  JobTree& jobs_;
  int jobId_;
  QPushButton *zoomButton_ = nullptr, *backButton_ = nullptr, *forwardButton_ = nullptr;
  SceneOpener opener_;
  QRubberBand* band_ = nullptr; // a child of this window: it outlives the views a redraw replaces
  bool dragging_ = false;       // a zoom's rectangle is being dragged
  QPoint pressed_;              // where a zoom's drag began (view coordinates)
  bool clicking_ = false;       // the left button went down on the chart (a click if released in place)
  QPoint clickAt_;
  double pressedAt_[2] = {0, 0}; // and there in chart coordinates
  long done_ = -1;
  Job::Status seen_ = Job::Status::Ready;
  void takeCurve();
  std::shared_ptr<Chart> chart_;
  QPushButton* curveButton_ = nullptr;
  int curveJobId_ = -1;
  std::vector<SweepOverlay> overlays_;
  bool redraw_ = false;
  SweepChartData data_;    ///< what was read of the job's store
  std::vector<char> read_; ///< the points read into data_
  int generation_ = 0;     ///< of the store read (SweepTask::generation)
};

} // namespace rv
