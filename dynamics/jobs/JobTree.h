// JobTree.h -- the tool manager's model: jobs in a tree (a spectrum or Lyapunov job hangs under the
// trajectory it studies). Used from one thread (the GUI's or the command line's); the jobs themselves run on
// their own threads.
#pragma once
#include "dynamics/jobs/Job.h"

#include <limits>
#include <memory>
#include <set>
#include <vector>

namespace rv {

class JobTree {
public:
  ~JobTree();
  /// Adds a job (not started) under `parent` (nullptr: a root). `number` > 0 asks for that id: a job put back
  /// (Undo, a session) keeps the number the user knows it by. It is given when no job has it and it never
  /// went to a job that owns its scene (a window holds that number); else the next number is. The jobs are
  /// listed by number, each after its parent.
  Job& add(std::unique_ptr<Task> task, Job* parent = nullptr, int number = 0);
  /// The next job added pauses once its progress reaches `fraction` (Job::pauseAt, set before anything can
  /// start it): for scripts and tests that stop a job a front end creates and starts at once.
  void pauseNextAt(double fraction) { pauseNext_ = fraction; }
  /// Stops and deletes the job and everything under it.
  void remove(Job& job);
  void stopAll();
  void removeAll();
  std::vector<Job*> jobs() const;
  std::vector<Job*> children(const Job& job) const;
  /// The job and everything under it, each parent before its children.
  std::vector<Job*> subtree(Job& job) const;
  Job* find(int id) const;

private:
  std::vector<std::unique_ptr<Job>> jobs_;
  int nextId_ = 1;
  std::set<int> windowIds_; ///< numbers given to jobs that own their scene: never given again
  double pauseNext_ = std::numeric_limits<double>::infinity();
};

} // namespace rv
