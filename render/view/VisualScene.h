// VisualScene.h -- the scene graph of the 3D view: named visual objects bound to a model's state, the
// camera that frames (and follows) the body, the time / energy-error overlay. Used identically on screen,
// in snapshots and in videos.
#pragma once
#include "dynamics/core/Model.h"
#include "dynamics/integrators/Integrator.h"
#include "render/ViewOptions.h"
#include "render/objects/VisualObject.h"

#include <array>
#include <map>
#include <memory>
#include <vector>
#include <vtkSmartPointer.h>

class vtkProp;
class vtkRenderer;
class vtkRenderWindow;
class vtkTextActor;

namespace rv {

class VisualScene {
public:
  /// Builds the default objects for the model's body (ball: plane, ball, trace; none: phase curve).
  VisualScene(const Model& model, const ViewOptions& options, const Eigen::VectorXd& initialState);
  ~VisualScene();

  vtkRenderer* renderer() const;
  /// Shows the scene in a window (adds the renderer, applies the window's options such as multisampling).
  void addTo(vtkRenderWindow* window) const;
  /// Registers an object under its name (replacing one of the same name) and applies saved options.
  VisualObject& add(std::unique_ptr<VisualObject> object);
  VisualObject* find(const std::string& name) const;
  const std::vector<std::unique_ptr<VisualObject>>& objects() const { return objects_; }
  /// The props an object added to the renderer (exports name the pieces after their objects).
  std::vector<vtkProp*> props(const std::string& name) const;
  /// Changes an object's appearance; the options are kept for re-runs.
  void setOptions(const std::string& name, const ObjectOptions& options);
  const ViewOptions& options() const { return options_; }
  /// Changes the scene axes' style, range and ticks; kept for re-runs like object options.
  void setAxes(const AxesOptions& axes);

  /// A state between frames (traces record it).
  void advance(double t, const Eigen::VectorXd& x);
  /// The state to draw in the next frame: places the bodies, the camera and the overlay.
  void show(double t, const Eigen::VectorXd& x);
  /// The relative energy error of the last state shown (nothing for models without an energy).
  std::optional<double> energyError() const { return energyError_; }
  /// Forgets traces and the energy reference (a new run).
  void clear();
  /// Puts the camera back to its default placement around the current state. In a phase-space view it then
  /// frames the growing curve at every frame, until the user turns, moves or zooms it: from then on the
  /// camera is the user's (playing or not) until the next reset.
  void resetCamera();
  /// Whether the user has turned, moved or zoomed the camera since it was last placed (resetCamera).
  bool cameraMoved() const { return !cameraAsPlaced(); }
  /// Whether the camera is carried along with the body as it rolls (view.camera.follow): the user's toggle,
  /// taking effect from the next frame on, the camera left where it is.
  void setFollow(bool on) { options_.camera.follow = on; }
  /// The apex view's key to its colours, a line per axis (red, green, blue); empty in other views.
  const std::vector<std::string>& colourKey() const { return keyLines_; }

  /// In a body view over the plane, lifts a camera the user has turned below the floor back above it (the
  /// same distance from what it looks at, the lowest elevation that keeps it 5 % of a body size above the
  /// plane); runs before every render, whoever moved the camera -- unless the scene's own
  /// view.camera.elevation is below the floor.
  void keepCameraAboveFloor();

private:
  void placeCamera();
  /// The camera is where placeCamera last left it (the user has not turned, moved or zoomed it since).
  bool cameraAsPlaced() const;
  const Model& model_;
  ViewOptions options_;
  double scale_ = 1;     ///< size of the body (ball radius), or of the initial state
  int energyIndex_ = -1; ///< index of "E" among the integrals
  double energy0_ = 0;   ///< energy at the start of the run
  bool haveEnergy0_ = false;
  std::optional<double> energyError_;
  Eigen::Vector3d focus_ = Eigen::Vector3d::Zero();
  std::array<double, 10> placed_{}; ///< the camera placeCamera left: position, focal point, view up, angle
  vtkSmartPointer<vtkRenderer> renderer_;
  vtkSmartPointer<vtkTextActor> overlay_;
  std::vector<std::string> keyLines_;
  std::vector<std::unique_ptr<VisualObject>> objects_;
  std::map<std::string, std::vector<vtkProp*>> props_; ///< by object name; the objects own them
  unsigned long floorObserver_ = 0;                    ///< the renderer's StartEvent observer
};

/// Integrates until `t` (in the integrator's direction), feeding every step to the scene, then shows the
/// state at exactly `t` (what a video's or a web page's frame shows). `work` is scratch space.
void playTo(VisualScene& scene, Integrator& integrator, double t, Eigen::VectorXd& work);

} // namespace rv
