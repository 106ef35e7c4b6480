// ApexWindow.h -- the apex motion window (manual §2.4.5): a second visualizer that draws the tracks of the
// body's apexes, fed either with the 3D view's run or with a map trajectory the user selected (its job
// samples its own states for it every 1/25 of a time unit, so it runs far ahead of the 3D view's real time).
// The main window owns it and forwards the states; the window itself is made when first opened.
#pragma once
#include "dynamics/jobs/PlotTap.h"
#include "render/view/VisualScene.h"
#include "scenes/Scene.h"

#include <Eigen/Core>
#include <QString>
#include <functional>
#include <memory>

class QWidget;

namespace rv {

class MapPanel;
class QtVtkWidget;

class ApexWindow {
public:
  /// `parent` owns the window; `place` puts a new window where the main window wants it.
  ApexWindow(QWidget* parent, std::function<void(QWidget*)> place);
  ~ApexWindow();
  ApexWindow(const ApexWindow&) = delete;
  ApexWindow& operator=(const ApexWindow&) = delete;

  /// Opens (or shows) the window for `scene`, drawn with `view` as the apex view (its box axes); a model
  /// without a body's geometry gets an empty window. Returns the window.
  QWidget* open(const Scene& scene, const ViewOptions& view);
  /// Whether the window was opened and shows now.
  bool visible() const;
  /// The scene is about to be replaced: its drawing and the followed trajectory go (the window stays).
  void dropScene();
  /// The 3D view's run starts again at the scene's initial state (a followed map trajectory goes on).
  void restart(const Scene& scene);
  /// Follows map trajectory `id` (-1, or a job that is not one: the 3D view's run, shown at `shownTime`).
  void follow(int id, MapPanel& map, const Scene& scene, double shownTime);
  /// Map trajectory `id` was deleted: the 3D view's run is followed again if it was that one.
  void forget(int id, MapPanel& map, const Scene& scene, double shownTime);
  /// A state of the 3D view's run (ignored while a map trajectory is followed): `advance` draws the steps
  /// in between, `show` the frame's state.
  void advance(double t, const Eigen::VectorXd& x);
  void show(double t, const Eigen::VectorXd& x);
  /// Draws what the followed map trajectory computed since the last frame.
  void feedFromMap(const Scene& scene);
  /// An appearance edit of the 3D view's object `name`, where the apex view draws it too.
  void setOptions(const std::string& name, const ObjectOptions& options);
  /// Redraws the window when it shows.
  void update();

  /// The trajectory followed: a map trajectory's job id, or -1 for the 3D view's run.
  int source() const { return source_; }
  /// Time of the last state drawn.
  double time() const { return time_; }
  /// The apex view's scene (nullptr before the window is opened or for a model without a body).
  VisualScene* visual() const { return visual_.get(); }

private:
  bool followsMap() const { return tap_ != nullptr; }
  QWidget* parent_;
  std::function<void(QWidget*)> place_;
  QWidget* window_ = nullptr;
  QtVtkWidget* view_ = nullptr;
  std::unique_ptr<VisualScene> visual_;
  int source_ = -1;
  std::shared_ptr<PlotTap> tap_; ///< the followed map trajectory's states
  double time_ = 0;
};

} // namespace rv
