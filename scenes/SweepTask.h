// SweepTask.h -- a sweep (Sweep.h) as a Task, so that the GUI runs it as a Job of the tool manager: progress,
// stop, continue (the points done are kept: a continued sweep computes only the rest), restart, delete. Its
// results stay in a store on disk (a temporary file, removed with the task) that a window reads while it
// runs.
#pragma once
#include "dynamics/jobs/SweepStore.h"
#include "dynamics/jobs/Task.h"
#include "scenes/Sweep.h"

#include <memory>
#include <string>
#include <vector>

namespace rv {

class SweepTask final : public Task {
public:
  /// `threads` computing threads (0: every core).
  explicit SweepTask(SweepSpec spec, int threads = 0);
  ~SweepTask() override;
  std::string name() const override;
  std::string describe() const override;
  bool run(const ToolControl& control) override;
  void reset() override;
  bool ownsItsScene() const override { return true; }

  const SweepSpec& spec() const { return spec_; }
  /// The records so far; safe to read while the task runs (a point is done once its record is whole).
  const SweepStore& store() const { return *store_; }
  /// Brings a chart's data up to date: the values of the points done, NaN for the others. `read` marks the
  /// points already read into `data` (both empty at first: they are sized here), so only the points done
  /// since are read from the store.
  void updateChartData(SweepChartData& data, std::vector<char>& read) const;
  /// How many times the store was started afresh (a restart makes what was read of it stale).
  int generation() const { return generation_; }

private:
  SweepSpec spec_;
  int threads_;
  std::string path_;
  std::unique_ptr<SweepStore> store_;
  int generation_ = 0;
  mutable long lastPainted_ = -1; // a refined sweep's points done when its chart was last painted
  /// A refined sweep's computed points as read (each once from the store; empty: not yet), repainted from
  /// memory when more are done -- a 10^5-point grid's repaint read every record from disk.
  mutable std::vector<std::vector<double>> computed_;
};

} // namespace rv
