// EncoderThread.h -- frames encoded on a worker thread so that producing the next frame (rendering it, or
// the GUI's event loop) overlaps encoding this one.
#pragma once
#include "render/Snapshot.h"
#include "render/video/Mp4Writer.h"

#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace rv {

/// Holds at most `depth` frames (push waits for room). An encoder error stops the worker and is rethrown to
/// the producer.
class EncoderThread {
public:
  EncoderThread(Mp4Writer& mp4, std::size_t depth) : mp4_(mp4), depth_(depth), worker_([this] { run(); }) {}
  ~EncoderThread() {
    try {
      close();
    } catch (...) { // an unfinished video: its writer removes the temporary file
    }
  }
  void push(Image frame) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return queue_.size() < depth_ || error_; });
    if (error_) std::rethrow_exception(error_);
    queue_.push_back(std::move(frame));
    changed_.notify_all();
  }
  /// A frame already encoded, to capture the next one into (its storage reused), or an empty one.
  Image spare() {
    std::lock_guard lock(mutex_);
    if (spares_.empty()) return {};
    Image frame = std::move(spares_.back());
    spares_.pop_back();
    return frame;
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
        std::lock_guard lock(mutex_);
        if (spares_.size() < depth_) spares_.push_back(std::move(frame));
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
  std::vector<Image> spares_; ///< encoded frames whose storage the producer may reuse
  bool closed_ = false;
  std::exception_ptr error_;
  std::thread worker_; // last: starts once the rest is built
};

} // namespace rv
