// MapFilters.h -- the filter windows the map window feeds (manual §2.4): 2D / 3D plot filters (each
// trajectory's job samples its own states for them), multipliers filters (the fixed points of every
// continuation, bifurcation tree and search), and bifurcation diagram windows marked with every trajectory
// (a point on the plane of first integrals). The windows are the user's: closed ones are dropped here as they
// go. The map window owns this and says what to give them.
#pragma once
#include "app/gui/ChartWindow.h"
#include "dynamics/core/Diagram.h"

#include <QPointer>
#include <QString>
#include <complex>
#include <functional>
#include <optional>
#include <vector>

namespace rv {

class Model;
class MultipliersWindow;
class PlotWindow;

class MapFilters {
public:
  /// Plot filters: added, and the open ones.
  void addPlot(PlotWindow* window);
  std::vector<PlotWindow*> plots();

  /// Multipliers filters: added (the caller offers it what was computed so far), the open ones, and what
  /// every open one is given: a family's fixed point (`everyStep`: a tree's step), a search's point, a job
  /// deleted or restarted (its points go, drawn at once), and a flush of what arrived.
  void addMultipliers(MultipliersWindow* window);
  std::vector<MultipliersWindow*> multipliers();
  void offer(int job, double parameter, const std::vector<std::complex<double>>& m, bool everyStep);
  void showFixedPoint(int job, const QString& caption, const std::vector<std::complex<double>>& m);
  void forget(int job);
  void flush();

  /// Bifurcation diagram windows: added, then marked with `place` -- the marks of every trajectory on a
  /// diagram's plane -- when they changed (or always with `force`). The model's diagrams are built once per
  /// scene.
  void addDiagram(ChartWindow* window);
  void markDiagrams(const Model& model,
                    const std::function<std::vector<ChartWindow::Mark>(const Diagram&)>& place, bool force);

  /// Another scene: the multipliers filters empty, the diagram windows (drawn for the old scene) keep their
  /// chart but are no longer marked or fed.
  void newScene();

private:
  std::vector<QPointer<PlotWindow>> plots_;
  std::vector<QPointer<MultipliersWindow>> multipliers_;
  std::vector<QPointer<ChartWindow>> diagrams_;
  std::optional<std::vector<Diagram>> modelDiagrams_;  ///< the scene's, once a diagram window is open
  std::vector<std::vector<ChartWindow::Mark>> marked_; ///< the marks drawn, per window
};

} // namespace rv
