// PlotWindow.h -- the 2D and 3D plot filters as live windows (manual §2.4.1-§2.4.2): "creating a filter
// starts no thread; the base tools output into it as well". The 3D view's running trajectory offers its
// states here (sampled on the GUI thread: they arrive anyway), and every trajectory of the map window feeds
// it through a PlotTap its job samples on its own thread. One series per trajectory, in the map's colour;
// the scene's plot section gives the axes (2 or 3), the output condition, period, maximum points per
// trajectory and the window options.
#pragma once
#include "app/gui/FilterWindow.h"
#include "dynamics/jobs/PlotTap.h"
#include "scenes/Scene.h"

#include <map>
#include <memory>
#include <vector>

namespace rv {

class PlotChart;

class PlotWindow : public FilterWindow {
  Q_OBJECT
public:
  /// The id of the 3D view's trajectory among the sources.
  static constexpr int kViewRun = -1;
  /// Throws InputError for a plot section the model cannot give.
  PlotWindow(const Model& model, const PlotView& plot, QWidget* parent = nullptr);
  ~PlotWindow() override;
  /// A state of the 3D view's running trajectory.
  void offer(double t, const double* x);
  /// A source starts again (the 3D view's run by default): its points go.
  void clear(int id = kViewRun);
  /// Follows map trajectory `id` drawn in `colour`: returns the tap to give its job.
  std::shared_ptr<PlotTap> follow(int id, const Rgb& colour);
  /// The trajectory was deleted: its points go.
  void unfollow(int id);
  void setColour(int id, const Rgb& colour);
  /// Draws the source's points emphasised (an id it does not follow: none).
  void highlight(int id);
  /// Takes what the taps streamed, and draws what arrived since the last call.
  void flush();
  int dimensions() const;
  /// Points of one source (kViewRun or a trajectory id), and of all.
  long points(int id) const;
  long points() const;
  /// The values of a source along axis `axis` (tests).
  const std::vector<double>& values(int id, int axis) const;

protected:
  const Chart* chart() const override;

private:
  struct Source {
    std::shared_ptr<PlotTap> tap; ///< none for the 3D view's run
    int series;
    std::array<std::vector<double>, 3> values;
    bool dirty = false;
  };
  Source& add(int id, const Rgb& colour);
  PlotView plot_;
  PlotSampler sampler_; ///< the 3D view's run
  std::unique_ptr<PlotChart> chart_;
  std::map<int, Source> sources_;
};

} // namespace rv
