// Channel.h -- results streamed from a job's thread to whoever watches it: the producer appends, the consumer
// takes everything at once by swapping buffers, so neither waits on the other for more than a swap.
#pragma once
#include <mutex>
#include <vector>

namespace rv {

template <class T> class Channel {
public:
  void push(T value) {
    std::lock_guard lock(mutex_);
    items_.push_back(std::move(value));
    ++total_;
  }
  /// Moves every item pushed since the last take into `out` (cleared first); returns how many.
  std::size_t take(std::vector<T>& out) {
    out.clear();
    std::lock_guard lock(mutex_);
    std::swap(out, items_);
    return out.size();
  }
  /// Items pushed since the channel was made (or cleared).
  long total() const {
    std::lock_guard lock(mutex_);
    return total_;
  }
  void clear() {
    std::lock_guard lock(mutex_);
    items_.clear();
    total_ = 0;
  }

private:
  mutable std::mutex mutex_;
  std::vector<T> items_;
  long total_ = 0;
};

} // namespace rv
