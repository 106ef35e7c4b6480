// WaitFor.h -- polling until a job reaches a state, with a generous limit (sanitizer builds are slow).
#pragma once
#include <chrono>
#include <thread>

namespace rv::test {

/// Polls `done` every millisecond; false when `limit` passes first.
template <class F> bool waitFor(F done, std::chrono::milliseconds limit = std::chrono::milliseconds(30000)) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

} // namespace rv::test
