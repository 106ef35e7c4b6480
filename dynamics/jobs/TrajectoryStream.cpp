#include "dynamics/jobs/TrajectoryStream.h"

#include <exception>

namespace rv {

TrajectoryStream::TrajectoryStream(std::unique_ptr<Integrator> integrator)
    : integrator_(std::move(integrator)), target_(integrator_->time()), served_(target_) {
  thread_ = std::thread([this] { run(); });
}

TrajectoryStream::~TrajectoryStream() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void TrajectoryStream::requestUntil(double t) {
  {
    std::lock_guard lock(mutex_);
    target_ = t;
  }
  wake_.notify_all();
}

bool TrajectoryStream::take(Batch& out) {
  out.times.clear(), out.states.clear(), out.reached = false, out.error.clear();
  std::lock_guard lock(mutex_);
  std::swap(out, pending_);
  return !out.times.empty() || out.reached || !out.error.empty();
}

bool TrajectoryStream::idle() {
  std::lock_guard lock(mutex_);
  return pending_.times.empty() && !pending_.reached && pending_.error.empty() &&
         (stop_ || served_ == target_);
}

void TrajectoryStream::run() {
  Integrator& integ = *integrator_;
  const int dir = integ.direction();
  double served = integ.time(); // the last target whose state was delivered (served_ under the lock)
  Eigen::VectorXd x(integ.state().size());
  for (;;) {
    double target;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || target_ != served; });
      if (stop_) return;
      target = target_;
    }
    // a few steps at a time, so that stop and new targets are seen promptly
    const auto fail = [this](const std::exception& e) {
      std::lock_guard lock(mutex_);
      pending_.error = e.what();
      stop_ = true; // nothing more can be computed
    };
    for (int k = 0; k < 64 && dir * (integ.time() - target) < 0; ++k) {
      try {
        integ.step();
        // a module's method may not check its steps: nothing non-finite is handed on
        Integrator::requireFinite(integ.state(), integ.time(), "the solution");
      } catch (const std::exception& e) {
        fail(e);
        return;
      }
      std::lock_guard lock(mutex_);
      pending_.times.push_back(integ.time());
      pending_.states.push_back(integ.state());
    }
    if (dir * (integ.time() - target) >= 0) {
      try {
        if (target != integ.time() && dir * (target - integ.previousTime()) >= 0)
          integ.sampleAt(target, x);
        else // the step ends at the target, or the target is behind the last step (time went back): show
             // where we are
          x = integ.state();
      } catch (const std::exception& e) {
        fail(e);
        return;
      }
      std::lock_guard lock(mutex_);
      pending_.reached = true;
      pending_.atTime = target;
      pending_.at = x;
      served = served_ = target;
    }
  }
}

} // namespace rv
