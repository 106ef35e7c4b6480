// Checkpoint.h -- `--checkpoint FILE` of the long commands: the computation's Snapshot (and the output
// written so far) saved every few seconds under a temporary name and renamed, so that a run killed at any
// moment -- SIGKILL included -- and started again with the same file goes on from the last save and ends
// bit-identical to an uninterrupted run. The file names the command and the run (the scene after --set and
// the options): another run's checkpoint is refused (exit 2), never silently mixed in. It is removed when the
// run completes.
#pragma once
#include "dynamics/core/Snapshot.h"
#include "dynamics/tools/ToolControl.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <functional>
#include <optional>
#include <string>

namespace rv {

class Checkpoint {
public:
  /// `path` empty: no checkpointing (every call does nothing). `run` identifies the computation: the same
  /// command on the same scene with the same options gives the same string.
  Checkpoint(std::string path, std::string command, std::string run);
  bool enabled() const { return !path_.empty(); }
  /// What an earlier run saved, when the file exists; InputError naming --checkpoint when it is unreadable or
  /// belongs to another run.
  struct Saved {
    Snapshot state;
    std::string text; ///< the output written up to the save
  };
  std::optional<Saved> load() const;
  /// True when the last save is older than the save period (and checkpointing is on).
  bool due() const;
  /// Writes the state atomically; the period grows when saving takes long (big outputs).
  void save(const Snapshot& state, const std::string& text);
  /// The run completed: the checkpoint is removed.
  void finish() const;
  /// `control` that also stops when a save is due (the caller saves and goes on).
  ToolControl stoppingWhenDue(const ToolControl& control) const;
  /// The loop of a resumable computation: `work(control)` (true when finished, false when stopped) runs until
  /// it finishes or `control` asks to stop; a due save stops it, `save` fills the snapshot, and it goes on.
  /// On a stop it saves once more. Returns whether it finished.
  bool run(const std::function<bool(const ToolControl&)>& work, const std::function<void(Snapshot&)>& save,
           const ToolControl& control);

private:
  std::string path_, command_, run_;
  std::chrono::steady_clock::time_point last_;
  std::chrono::duration<double> period_{1.0};
};

/// Adds `--checkpoint FILE` to a long command.
void addCheckpointOption(CLI::App* cmd, std::string& path);

} // namespace rv
