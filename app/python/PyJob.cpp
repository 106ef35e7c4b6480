#include "app/python/PyJob.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

namespace rv::py {

namespace pyb = pybind11;

void runJob(const pyb::object& progress, const std::function<void(const ToolControl&)>& work) {
  std::atomic<bool> stop{false};
  std::atomic<double> fraction{-1};
  std::mutex m;
  std::condition_variable cv;
  bool done = false;
  std::exception_ptr failure;
  std::optional<pyb::error_already_set> pythonError;
  ToolControl control;
  control.stopRequested = [&] { return stop.load(std::memory_order_relaxed); };
  control.progress = [&](double f) { fraction.store(f, std::memory_order_relaxed); };
  const bool report = !progress.is_none();
  // the caller's side while the worker computes: signals and progress, the GIL taken briefly each time
  const auto poll = [&] {
    double shown = -1;
    for (;;) {
      {
        std::unique_lock lock(m);
        // 50 ms: Ctrl-C answers at once to a person, and the interpreter's other threads get the GIL
        if (cv.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; })) return;
      }
      if (pythonError) continue; // stopping: wait for the worker
      pyb::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {
        pythonError.emplace(); // takes the pending KeyboardInterrupt
        stop = true;
        continue;
      }
      const double f = fraction.load(std::memory_order_relaxed);
      if (report && f >= 0 && f != shown) {
        shown = f;
        try {
          progress(f);
        } catch (pyb::error_already_set& e) {
          pythonError.emplace(std::move(e));
          stop = true;
        }
      }
    }
  };
  {
    pyb::gil_scoped_release release;
    std::thread worker([&] {
      try {
        work(control);
      } catch (...) {
        failure = std::current_exception();
      }
      std::lock_guard lock(m);
      done = true;
      cv.notify_all();
    });
    try {
      poll();
    } catch (...) { // nothing may leave while the worker runs: stop it first
      stop = true;
      worker.join();
      throw;
    }
    worker.join();
  }
  if (pythonError) throw std::move(*pythonError);
  if (failure) std::rethrow_exception(failure);
  if (report) progress(1.0);
}

} // namespace rv::py
