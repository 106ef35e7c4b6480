#include "dynamics/jobs/Job.h"

#include "dynamics/core/Errors.h"

#include <exception>

namespace rv {

bool Task::edit(const TaskEdit&) {
  throw InputError(name() + " takes no new values: restart it");
}

const char* statusName(Job::Status s) {
  switch (s) {
  case Job::Status::Ready:
    return "ready";
  case Job::Status::Running:
    return "running";
  case Job::Status::Stopped:
    return "stopped";
  case Job::Status::Finished:
    return "finished";
  case Job::Status::Failed:
    return "failed";
  }
  return "?";
}

Job::Job(int id, std::unique_ptr<Task> task, Job* parent)
    : id_(id), task_(std::move(task)), parent_(parent) {}

Job::~Job() {
  stop();
}

void Job::start() {
  const Status s = status();
  if (s == Status::Running || s == Status::Finished) return;
  join(); // a thread that ended by itself
  stopRequested_ = false;
  status_ = Status::Running;
  thread_ = std::thread([this] {
    ToolControl control;
    control.stopRequested = [this] { return stopRequested_.load(std::memory_order_relaxed); };
    control.progress = [this](double f) {
      progress_.store(f, std::memory_order_relaxed);
      if (f >= pauseAt_.load(std::memory_order_relaxed)) {
        pauseAt_ = std::numeric_limits<double>::infinity();
        stopRequested_ = true;
      }
    };
    try {
      const bool finished = task_->run(control);
      if (finished) progress_ = 1.0;
      status_ = finished ? Status::Finished : Status::Stopped;
    } catch (const std::exception& e) {
      {
        std::lock_guard lock(errorMutex_);
        error_ = e.what();
      }
      status_ = Status::Failed;
    }
  });
}

void Job::join() {
  if (thread_.joinable()) thread_.join();
}

void Job::stop() {
  stopRequested_ = true;
  join();
}

void Job::restart() {
  stop();
  task_->reset();
  progress_ = 0;
  {
    std::lock_guard lock(errorMutex_);
    error_.clear();
  }
  status_ = Status::Ready;
  start();
}

void Job::edit(const std::function<void(Task&)>& change) {
  stop();
  change(*task_);
  if (status() == Status::Finished || status() == Status::Failed) status_ = Status::Stopped;
}

std::string Job::error() const {
  std::lock_guard lock(errorMutex_);
  return error_;
}

} // namespace rv
