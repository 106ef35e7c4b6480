// PlotWindow.h -- the 2D plot filter as a live window (manual §2.4.1): the 3D view's running trajectory feeds
// it state by state, and the scene's plot section decides which states become points (PlotSampler: the
// condition moved by the period). The first two of its axes are drawn; Save CSV writes them.
#pragma once
#include "dynamics/tools/PlotFilter.h"

#include <QWidget>
#include <memory>
#include <vector>

namespace rv {

class PoincareChart;
class QtVtkWidget;

class PlotWindow : public QWidget {
  Q_OBJECT
public:
  /// Throws InputError for a plot section the model cannot give.
  PlotWindow(const Model& model, const PlotSettings& settings, QWidget* parent = nullptr);
  ~PlotWindow() override;
  /// A state of the running trajectory.
  void offer(double t, const double* x);
  /// Draws what arrived since the last call.
  void flush();
  /// A new run: the points go.
  void clear();
  long points() const { return static_cast<long>(x_.size()); }
  const std::vector<double>& xs() const { return x_; }
  const std::vector<double>& ys() const { return y_; }
  QtVtkWidget* view() const { return view_; }

private:
  PlotSampler sampler_;
  std::unique_ptr<PoincareChart> chart_;
  QtVtkWidget* view_;
  std::vector<double> x_, y_;
  bool dirty_ = false;
};

} // namespace rv
