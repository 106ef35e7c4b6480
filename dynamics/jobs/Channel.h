// Channel.h -- results streamed from a job's thread to whoever watches it: the producer appends, the consumer
// takes everything at once by swapping buffers, so neither waits on the other for more than a swap. A channel
// with a capacity bounds its memory however long a job runs: push() then waits while it is full until the
// consumer takes (back-pressure: nothing is dropped) or the job is asked to stop.
#pragma once
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <vector>

namespace rv {

template <class T> class Channel {
public:
  /// `capacity` 0: unbounded.
  explicit Channel(std::size_t capacity = 0) : capacity_(capacity) {}
  /// Appends; with a capacity, first waits while the channel is full, polling `stop` (a stop ends the wait
  /// and the item is appended all the same: a channel holds at most capacity + 1 items, and nothing is lost).
  void push(T value, const std::function<bool()>& stop = {}) {
    std::unique_lock lock(mutex_);
    while (capacity_ > 0 && items_.size() >= capacity_ && !(stop && stop()))
      room_.wait_for(lock, std::chrono::milliseconds(10));
    items_.push_back(std::move(value));
    ++total_;
    highWater_ = std::max(highWater_, items_.size());
  }
  /// Moves every item pushed since the last take into `out` (cleared first); returns how many.
  std::size_t take(std::vector<T>& out) {
    out.clear();
    {
      std::lock_guard lock(mutex_);
      std::swap(out, items_);
    }
    room_.notify_all();
    return out.size();
  }
  /// Items pushed since the channel was made (or cleared).
  long total() const {
    std::lock_guard lock(mutex_);
    return total_;
  }
  /// The most items it ever held at once (since made or cleared).
  std::size_t highWater() const {
    std::lock_guard lock(mutex_);
    return highWater_;
  }
  std::size_t capacity() const { return capacity_; }
  void clear() {
    {
      std::lock_guard lock(mutex_);
      items_.clear();
      total_ = 0;
      highWater_ = 0;
    }
    room_.notify_all();
  }

private:
  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable room_;
  std::vector<T> items_;
  long total_ = 0;
  std::size_t highWater_ = 0;
};

} // namespace rv
