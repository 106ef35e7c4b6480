#include "render/video/VideoExport.h"

#include "dynamics/core/Errors.h"
#include "render/Snapshot.h"
#include "render/video/EncoderThread.h"
#include "render/video/Mp4Writer.h"

#include <cmath>
#include <tuple>
#include <utility>
#include <vtkRenderWindow.h>

namespace rv {

VideoExporter::VideoExporter(VisualScene& scene, vtkRenderWindow* window, Integrator& integrator,
                             const VideoSpec& spec)
    : scene_(scene), window_(window), integrator_(integrator), spec_(spec),
      total_(std::lround(spec.duration * spec.fps)), t0_(integrator.time()), x_(integrator.state().size()) {
  mp4_ = std::make_unique<Mp4Writer>(spec.path, spec.width, spec.height, spec.fps, spec.encoder);
  window->SetSize(spec.width, spec.height);
  encoder_ = std::make_unique<EncoderThread>(*mp4_, 3);
}

VideoExporter::~VideoExporter() {
  encoder_.reset(); // joins the worker before the writer (unfinished: it removes its temporary file) goes
}

bool VideoExporter::next() {
  if (k_ >= total_) return false;
  playTo(scene_, integrator_,
         t0_ + integrator_.direction() * spec_.speed * static_cast<double>(k_) / spec_.fps, x_);
  Image frame = encoder_->spare(); // an encoded frame's storage: no allocation per frame
  captureInto(window_, frame);
  encoder_->push(std::move(frame));
  return ++k_ < total_;
}

long VideoExporter::finish() {
  encoder_->close();
  mp4_->finish(); // a stopped export ends here too: a valid video of the frames so far
  return k_;
}

long exportVideo(VisualScene& scene, vtkRenderWindow* window, Integrator& integrator, const VideoSpec& spec,
                 const std::function<bool(long, long)>& progress) {
  VideoExporter video(scene, window, integrator, spec);
  while (video.done() < video.total()) {
    if (progress && !progress(video.done(), video.total())) break;
    video.next();
  }
  return video.finish();
}

VideoSpec videoSpec(const ParameterValues& video, double speed, const VideoOverrides& given) {
  VideoSpec spec{.width = static_cast<int>(video["width"]),
                 .height = static_cast<int>(video["height"]),
                 .fps = static_cast<int>(video["fps"]),
                 .duration = video["duration"],
                 .speed = speed,
                 .encoder = {.preset = video.choice("preset"), .crf = static_cast<int>(video["crf"])}};
  if (given.size) std::tie(spec.width, spec.height) = *given.size;
  if (given.duration) spec.duration = *given.duration;
  if (given.fps) spec.fps = *given.fps;
  if (spec.width % 2 || spec.height % 2)
    throw InputError((given.size ? given.sizeName : "video.width x video.height") + " " +
                     std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                     ": a video needs an even width and height");
  if (!(std::isfinite(spec.duration) && spec.duration > 0))
    throw InputError((given.duration ? given.durationName : "video.duration") + ": must be positive");
  if (spec.fps < 1 || spec.fps > 240)
    throw InputError((given.fps ? given.fpsName : "video.fps") + ": must lie in [1, 240]");
  return spec;
}

} // namespace rv
