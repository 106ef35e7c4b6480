// Task.h -- the work a job runs: resumable, so that a stopped job continues where it stopped.
#pragma once
#include "dynamics/tools/ToolControl.h"

#include <string>

namespace rv {

struct RunSpec;
struct SectionSettings;

/// Edit properties (manual §2.1): the values of an edited scene as each kind of tool reads them (the scenes
/// layer builds one from a scene; dynamics does not see scenes).
class TaskEdit {
public:
  virtual ~TaskEdit() = default;
  /// Problem and method.
  virtual RunSpec run() const = 0;
  virtual SectionSettings section() const = 0;
  /// The whole scene document as JSON text, for tasks that compute from a scene (charts).
  virtual std::string document() const = 0;
};

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
  /// Takes an edit's values while stopped: returns true when it goes on from its stop point with them, false
  /// when it starts again. Throws InputError when the tool takes no new values (the default) or cannot take
  /// these.
  virtual bool edit(const TaskEdit& edit);
  /// Whether it computes from a scene of its own and belongs to a window (a chart, a sweep), so that another
  /// scene in the main window leaves it be; the map's tools (false) belong to the scene shown.
  virtual bool ownsItsScene() const { return false; }
  /// Whether it only stands for an outcome computed earlier (a session or Undo put it back): its failure was
  /// said when it happened.
  virtual bool isRecord() const { return false; }
};

} // namespace rv
