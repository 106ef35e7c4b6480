// Job.h -- a task running on its own thread: start, stop (promptly: the task polls between steps), continue
// after editing, restart, and a status, progress and error for the tool manager. Jobs form a tree (JobTree).
#pragma once
#include "dynamics/jobs/Task.h"

#include <atomic>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace rv {

class Job {
public:
  enum class Status { Ready, Running, Stopped, Finished, Failed };

  Job(int id, std::unique_ptr<Task> task, Job* parent);
  /// Stops the thread and waits for it.
  ~Job();
  Job(const Job&) = delete;
  Job& operator=(const Job&) = delete;

  /// Runs (or continues) the task on the job's thread; does nothing while it runs or when finished.
  void start();
  /// Asks the task to stop and waits for the thread (the task stops within one step's worth of work).
  void stop();
  /// Asks the task to stop once its progress reaches `fraction` (set before or while it runs; does not wait):
  /// a pause at a known place whatever the machine's speed, for scripted runs and tests. Used up by that
  /// stop.
  void pauseAt(double fraction) { pauseAt_ = fraction; }
  /// Stops, resets the task and starts it again.
  void restart();
  /// Changes the task while it does not run (stops it first); the change continues from where it stopped.
  void edit(const std::function<void(Task&)>& change);

  Status status() const { return status_.load(); }
  bool running() const { return status() == Status::Running; }
  double progress() const { return progress_.load(); }
  std::string error() const;
  int id() const { return id_; }
  Job* parent() const { return parent_; }
  /// The task, to read its channels (thread-safe) or its settings (only while it does not run).
  Task& task() { return *task_; }
  const Task& task() const { return *task_; }

private:
  void join();
  int id_;
  std::unique_ptr<Task> task_;
  Job* parent_;
  std::thread thread_;
  std::atomic<bool> stopRequested_{false};
  std::atomic<Status> status_{Status::Ready};
  std::atomic<double> progress_{0};
  std::atomic<double> pauseAt_{std::numeric_limits<double>::infinity()};
  mutable std::mutex errorMutex_;
  std::string error_;
};

/// "ready", "running", ...
const char* statusName(Job::Status status);

} // namespace rv
