// TrajectoryStream.h -- integrates one trajectory on its own thread, on demand: the consumer (the GUI's
// frame timer) asks for the motion up to a time and later takes every step computed so far plus the state
// at exactly that time. Neither side blocks the other for longer than a buffer swap.
#pragma once
#include "dynamics/integrators/Integrator.h"

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace rv {

class TrajectoryStream {
public:
  /// What the consumer takes: the states at every step since the last take, and the state at the
  /// requested time once it has been reached.
  struct Batch {
    std::vector<double> times;
    std::vector<Eigen::VectorXd> states;
    bool reached = false; ///< `at` holds the state at `atTime`
    double atTime = 0;
    Eigen::VectorXd at;
    std::string error; ///< non-empty when the integration failed (it then stops)
  };

  /// Takes ownership of a started integrator (its model must outlive the stream) and starts the thread.
  explicit TrajectoryStream(std::unique_ptr<Integrator> integrator);
  /// Stops the thread promptly (within one step) and joins it.
  ~TrajectoryStream();
  TrajectoryStream(const TrajectoryStream&) = delete;
  TrajectoryStream& operator=(const TrajectoryStream&) = delete;

  /// Asks for the motion up to time t (in the integrator's direction); never blocks on computation.
  void requestUntil(double t);
  /// Moves what has been computed into `out` (clearing it first). Returns true when anything was taken.
  bool take(Batch& out);
  /// Whether the state at the last requested time has been delivered and everything computed taken: nothing
  /// more comes until another time is asked for (or the integration failed and its error was taken).
  bool idle();

private:
  void run();
  std::unique_ptr<Integrator> integrator_;
  std::mutex mutex_;
  std::condition_variable wake_;
  double target_;
  double served_; ///< the last target whose state was delivered
  bool stop_ = false;
  Batch pending_;
  std::thread thread_;
};

} // namespace rv
