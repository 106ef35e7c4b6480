// Task.h -- the work a job runs: resumable, so that a stopped job continues where it stopped.
#pragma once
#include "dynamics/tools/ToolControl.h"

#include <string>

namespace rv {

class Task {
public:
  virtual ~Task() = default;
  /// Short name for the tool manager ("Poincare map", "Lyapunov exponents", ...).
  virtual std::string name() const = 0;
  /// The technical information shown for the instance: method, problem and tool parameters.
  virtual std::string describe() const = 0;
  /// Goes on from where it stopped; returns true when the work is complete, false when stopped on request.
  /// Throws on failure (the job records the reason).
  virtual bool run(const ToolControl& control) = 0;
  /// Back to the beginning (for restart).
  virtual void reset() = 0;
};

} // namespace rv
