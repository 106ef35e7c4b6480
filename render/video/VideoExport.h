// VideoExport.h -- playback of a run into frames at a fixed rate in simulation time: every integrator step
// feeds the traces, and each frame shows the state interpolated at exactly its time (MuJoCo's record.cc
// approach: offline, never by capturing the screen).
#pragma once
#include "dynamics/integrators/Integrator.h"
#include "render/video/Mp4Writer.h"
#include "render/view/VisualScene.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>

class vtkRenderWindow;

namespace rv {

class Mp4Writer;

struct VideoSpec {
  std::string path;
  int width = 1280, height = 720;
  int fps = 25;
  double duration = 5; ///< seconds of video
  double speed = 1;    ///< simulation seconds per video second
  EncoderSettings encoder;
};

/// What a front end was given beside the scene's video section (unset: the section's value), and the names
/// its messages use for them (the flag or keyword).
struct VideoOverrides {
  std::optional<std::pair<int, int>> size;
  std::optional<double> duration;
  std::optional<int> fps;
  std::string sizeName, durationName, fpsName;
};

/// The scene's "video" section (render/video/VideoSettings.h videoTable) as a spec, with `speed` (the
/// view's) and the overrides given. InputError when the result is odd-sized, not of positive length or its
/// rate is outside [1, 240], naming the override -- or the section's key -- that made it so.
VideoSpec videoSpec(const ParameterValues& video, double speed, const VideoOverrides& given = {});

class EncoderThread;

/// A video export done one frame at a time (so that a GUI can interleave it with its events): frame k shows
/// simulation time t0 + k * speed / fps. finish() (also after stopping early) leaves a valid video of the
/// frames so far; destroying an unfinished export leaves nothing.
class VideoExporter {
public:
  /// Sizes the window to the video. Throws InputError / ComputationError as Mp4Writer does.
  VideoExporter(VisualScene& scene, vtkRenderWindow* window, Integrator& integrator, const VideoSpec& spec);
  ~VideoExporter();
  /// Renders and queues the next frame; false when every frame is done.
  bool next();
  long done() const { return k_; }
  long total() const { return total_; }
  /// Encodes what is queued and writes the file. Returns the number of frames.
  long finish();

private:
  VisualScene& scene_;
  vtkRenderWindow* window_;
  Integrator& integrator_;
  VideoSpec spec_;
  long total_, k_ = 0;
  double t0_;
  Eigen::VectorXd x_;
  std::unique_ptr<Mp4Writer> mp4_;
  std::unique_ptr<EncoderThread> encoder_;
};

/// Renders round(duration * fps) frames, frame k at simulation time k * speed / fps. `progress(done, total)`
/// returning false cancels: the frames so far are kept as a valid, shorter video. Returns frames written.
long exportVideo(VisualScene& scene, vtkRenderWindow* window, Integrator& integrator, const VideoSpec& spec,
                 const std::function<bool(long, long)>& progress = {});

} // namespace rv
