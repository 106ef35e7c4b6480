// ToolTask.h -- a registered tool that runs through scenes/ToolRunner.h, as a job of the tool manager: it
// runs the tool on a scene (or on the first of a few alternative scenes that does not fail) and keeps the
// result for the window that started it (a sweep window draws a bifurcation curve over its chart this way).
#pragma once
#include "dynamics/jobs/Task.h"
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
  /// in messages. InputError when the tool has no runner or no document is given.
  ToolTask(const std::string& id, std::vector<nlohmann::json> documents, std::string source);
  std::string name() const override;
  std::string describe() const override;
  /// The first document's run, or the next ones' when it fails; the last failure when all do.
  bool run(const ToolControl& control) override;
  void reset() override;
  bool ownsItsScene() const override { return true; }
  /// The result of the last complete run (nullopt before, and after a stop). Thread-safe.
  std::optional<ToolResult> result() const;
  /// Which document gave it (0-based; -1 before).
  int used() const;

private:
  const ToolEntry& tool_;
  std::vector<nlohmann::json> documents_;
  std::string source_;
  mutable std::mutex mutex_;
  std::optional<ToolResult> result_;
  int used_ = -1;
};

} // namespace rv
