// VideoExport.h -- playback of a run into frames at a fixed rate in simulation time: every integrator step
// feeds the traces, and each frame shows the state interpolated at exactly its time (MuJoCo's record.cc
// approach: offline, never by capturing the screen).
#pragma once
#include "dynamics/integrators/Integrator.h"
#include "render/VisualScene.h"

#include <functional>
#include <string>

class vtkRenderWindow;

namespace rv {

/// Integrates until `t` (in the integrator's direction), feeding every step to the scene, then shows the
/// state at exactly `t`. `work` is scratch space.
void playTo(VisualScene& scene, Integrator& integrator, double t, Eigen::VectorXd& work);

struct VideoSpec {
  std::string path;
  int width = 1280, height = 720;
  int fps = 25;
  double duration = 5; ///< seconds of video
  double speed = 1;    ///< simulation seconds per video second
  std::string encoder = "libx264";
};

/// Renders round(duration * fps) frames, frame k at simulation time k * speed / fps. `progress(done, total)`
/// returning false cancels: the frames so far are kept as a valid, shorter video. Returns frames written.
long exportVideo(VisualScene& scene, vtkRenderWindow* window, Integrator& integrator, const VideoSpec& spec,
                 const std::function<bool(long, long)>& progress = {});

} // namespace rv
