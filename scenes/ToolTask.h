// ToolTask.h -- a registered tool that runs through scenes/ToolRunner.h, as a job of the tool manager: it
// runs the tool on a scene (or on the first of a few alternative scenes that does not fail) and keeps the
// result for the window that started it (a sweep window draws a bifurcation curve over its chart this way).
// Its rows and notes stream through channels while it runs (ToolControl::row, note): the map window draws a
// continuation's, a separatrix's, a bifurcation tree's -- any ToolWindow::MapRows tool's -- as they come.
#pragma once
#include "dynamics/jobs/Channel.h"
#include "dynamics/jobs/Task.h"
#include "scenes/SceneLoader.h"
#include "scenes/ToolRunner.h"

#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rv {

class ToolTask final : public Task {
public:
  /// Runs tool `id` on `documents` in turn until one does not fail (a ComputationError); `source` names them
  /// in messages. InputError when the tool has no runner or no document is given. `ownScene`: it belongs to
  /// the window that started it (ownsItsScene), not to the scene the main window shows. `kept`: settings of
  /// its own, set on its documents and on an edited scene (the map's doubled family keeps its
  /// continuation.switch, its separatrices their branches).
  ToolTask(const std::string& id, std::vector<nlohmann::json> documents, std::string source,
           bool ownScene = true, std::vector<SceneOverride> kept = {});
  std::string name() const override;
  std::string describe() const override;
  /// The first document's run, or the next ones' when it fails; the last failure when all do.
  bool run(const ToolControl& control) override;
  void reset() override;
  /// Edit properties: the edited scene's document (with the kept settings) is the one it runs on; it starts
  /// again (returns false).
  bool edit(const TaskEdit& e) override;
  bool ownsItsScene() const override { return ownScene_; }
  const ToolEntry& tool() const { return tool_; }
  /// A row as a run computed it: runs are numbered 1, 2, ... (each begins from the start: after a stop, an
  /// edit), so that a window drops what an earlier run drew when the next run's first row comes, and an
  /// earlier run's rows that come late.
  struct RunRow {
    int run;
    StreamedRow row;
  };
  /// The rows, as they are computed.
  Channel<RunRow>& rows() { return rows_; }
  /// The notes, as they are said.
  Channel<std::string>& notes() { return notes_; }
  /// The result of the last complete run (nullopt before, and after a stop). Thread-safe.
  std::optional<ToolResult> result() const;
  /// Which document gave it (0-based; -1 before).
  int used() const;

private:
  const ToolEntry& tool_;
  std::vector<nlohmann::json> documents_;
  std::string source_;
  bool ownScene_;
  std::vector<SceneOverride> kept_;
  Channel<RunRow> rows_;
  Channel<std::string> notes_;
  int runs_ = 0; ///< runs begun (read and written by the job's thread only)
  mutable std::mutex mutex_;
  std::optional<ToolResult> result_;
  int used_ = -1;
};

} // namespace rv
