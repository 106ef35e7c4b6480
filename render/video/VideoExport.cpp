#include "render/video/VideoExport.h"

#include "render/Snapshot.h"
#include "render/video/Mp4Writer.h"

#include <cmath>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vtkRenderWindow.h>

namespace rv {

void playTo(VisualScene& scene, Integrator& integrator, double t, Eigen::VectorXd& work) {
  const int dir = integrator.direction();
  while (dir * (integrator.time() - t) < 0) {
    integrator.step();
    if (dir * (integrator.time() - t) < 0) scene.advance(integrator.time(), integrator.state());
  }
  if (integrator.time() == t)
    work = integrator.state();
  else
    integrator.interpolate(t, work);
  scene.show(t, work);
}

// Encodes frames on a worker thread so that rendering the next frame overlaps encoding this one; holds at
// most `depth` frames. An encoder error stops the worker and is rethrown to the renderer.
class EncoderThread {
public:
  EncoderThread(Mp4Writer& mp4, std::size_t depth) : mp4_(mp4), depth_(depth), worker_([this] { run(); }) {}
  ~EncoderThread() { close(); }
  void push(Image frame) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return queue_.size() < depth_ || error_; });
    if (error_) std::rethrow_exception(error_);
    queue_.push_back(std::move(frame));
    changed_.notify_all();
  }
  /// Waits until every frame pushed is encoded; rethrows an encoder error.
  void close() {
    {
      std::lock_guard lock(mutex_);
      closed_ = true;
      changed_.notify_all();
    }
    if (worker_.joinable()) worker_.join();
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  }

private:
  void run() {
    for (;;) {
      Image frame;
      {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return !queue_.empty() || closed_; });
        if (queue_.empty()) return;
        frame = std::move(queue_.front());
        queue_.pop_front();
        changed_.notify_all();
      }
      try {
        mp4_.add(frame.rgb.data());
      } catch (...) {
        std::lock_guard lock(mutex_);
        error_ = std::current_exception();
        queue_.clear();
        changed_.notify_all();
        return;
      }
    }
  }
  Mp4Writer& mp4_;
  std::size_t depth_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Image> queue_;
  bool closed_ = false;
  std::exception_ptr error_;
  std::thread worker_; // last: starts once the rest is built
};

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
  encoder_->push(capture(window_));
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

} // namespace rv
