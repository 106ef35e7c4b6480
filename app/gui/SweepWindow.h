// SweepWindow.h -- a chart of regimes (scenes/Sweep.h) in the GUI: the sweep runs as a Job of the tool
// manager (scenes/SweepTask: progress, stop, continue, restart, delete there) and the window fills in as its
// points arrive; a click on a cell (or on a point of a one-axis chart) opens that grid point's scene -- its
// parameters or its initial point -- in the main window: from the chart to the trajectory in one click.
#pragma once
#include "app/gui/FilterWindow.h"
#include "dynamics/jobs/JobTree.h"
#include "scenes/Sweep.h"

#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

class QPushButton;

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
  /// Opens grid point `index` (emits openScene with its scene document).
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

signals:
  /// A grid point's scene, to run in the main window.
  void openScene(const nlohmann::json& document);
  /// The job ended (finished, stopped or failed).
  void finished();

protected:
  const Chart* chart() const override { return chart_.get(); }
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  void poll();
  SweepSpec spec_;
  JobTree& jobs_;
  int jobId_;
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
