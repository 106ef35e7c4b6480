// ChartWindow.h -- a filter window (manual §2.4): any chart view of the scene (the list is
// scenes/SceneCharts'), computed as a Job of the job tree (scenes/ChartTask) -- listed in the tool manager,
// where it is stopped, continued, edited and restarted like every tool -- and drawn when the job ends. The
// GUI thread never computes; closing the window deletes the job.
#pragma once
#include "app/gui/FilterWindow.h"
#include "dynamics/jobs/JobTree.h"
#include "render/ViewOptions.h"

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rv {

/// A computation's error as the window says it: without the command line's flag ("--view spectrum: "), and a
/// value the scene lacks ("the scene has no spectrum.function") named with the control panel's tab to set it.
QString inGuiWords(std::string error);

class ChartWindow : public FilterWindow {
  Q_OBJECT
public:
  /// Starts computing `view` for the scene document (`source` names it in messages); `diagram` picks the
  /// bifurcation view's diagram (empty: the problem's first).
  ChartWindow(JobTree& jobs, const nlohmann::json& document, const std::string& source,
              const std::string& view, QWidget* parent = nullptr, const std::string& diagram = "");
  ~ChartWindow() override;
  bool ready() const { return chart_ != nullptr; }
  /// The chart drawn (nullptr until it is ready).
  const std::shared_ptr<Chart>& drawn() const { return chart_; }
  /// Stops the computation (Cancel): what was computed so far is drawn where the view can (a family, a
  /// plot), else the window says it stopped.
  void cancel();
  /// The job computing the chart (nullptr once deleted from the tool manager).
  Job* job() const;
  /// Its job's number in the tool manager (kept after the job is deleted).
  int jobId() const { return jobId_; }
  /// Why the computation failed (empty while running or when it succeeded).
  const QString& failure() const { return failure_; }
  const std::string& viewName() const { return viewName_; }
  /// The scene document it computes (a session saves it to open the window again).
  const nlohmann::json& document() const { return document_; }
  /// The bifurcation view's diagram id (empty: the problem's first).
  const std::string& diagram() const { return diagram_; }
  /// A marked point over the chart: manual §2.4.4, each trajectory of the map is a point on the plane of the
  /// bifurcation diagram.
  struct Mark {
    double x, y;
    Rgb colour;
    bool operator==(const Mark&) const = default;
  };
  /// Draws these marks (replacing the last ones; kept until the chart is ready).
  void setMarks(const std::vector<Mark>& marks);
  const std::vector<Mark>& marks() const { return marks_; }

signals:
  void finished();

protected:
  const Chart* chart() const override { return chart_.get(); }

private:
  nlohmann::json document_;
  /// Follows the job: its progress, and its chart or failure when it ends (polled by a timer).
  void poll();
  void drawMarks();
  std::string viewName_, diagram_;
  std::vector<Mark> marks_;
  std::vector<int> markSeries_;
  std::shared_ptr<Chart> chart_;
  QString failure_;
  JobTree& jobs_;
  int jobId_;
  Job::Status seen_ = Job::Status::Ready;
};

} // namespace rv
