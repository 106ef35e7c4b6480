#include "scenes/ToolTask.h"

#include "dynamics/core/Errors.h"
#include "scenes/SceneLoader.h"

namespace rv {

ToolTask::ToolTask(const std::string& id, std::vector<nlohmann::json> documents, std::string source,
                   bool ownScene, std::vector<SceneOverride> kept)
    : tool_(ToolRegistry::global().get(id)), source_(std::move(source)), ownScene_(ownScene),
      kept_(std::move(kept)) {
  if (!findToolRunner(id)) throw InputError("tool '" + id + "' cannot run on a scene by itself");
  if (documents.empty()) throw InputError("tool '" + id + "': no scene to run on");
  for (auto& d : documents)
    documents_.push_back(kept_.empty() ? std::move(d) : sceneFromJson(std::move(d), source_, kept_).document);
}

std::string ToolTask::name() const {
  return tool_.title;
}

std::string ToolTask::describe() const {
  return tool_.title + " on " + source_;
}

bool ToolTask::run(const ToolControl& control) {
  reset();
  const int run = ++runs_; // from the start: what an earlier run streamed is stale
  ToolControl streaming = control;
  streaming.row = [this, run](const StreamedRow& row) { rows_.push({run, row}); };
  streaming.note = [this](const std::string& note) { notes_.push(note); };
  std::string failure;
  for (std::size_t i = 0; i < documents_.size(); ++i) {
    const Scene scene = sceneFromJson(documents_[i], source_);
    try {
      ToolResult r = runTool(tool_, scene, streaming);
      if (r.stopped) return false;
      const std::lock_guard lock(mutex_);
      result_ = std::move(r);
      used_ = static_cast<int>(i);
      return true;
    } catch (const ComputationError& e) {
      failure = e.what(); // the next alternative
    }
  }
  throw ComputationError(failure);
}

bool ToolTask::edit(const TaskEdit& e) {
  // validated now: bad input changes nothing
  nlohmann::json document = sceneFromJson(nlohmann::json::parse(e.document()), source_, kept_).document;
  documents_ = {std::move(document)};
  reset();
  return false;
}

void ToolTask::reset() {
  const std::lock_guard lock(mutex_);
  result_.reset();
  used_ = -1;
}

std::optional<ToolResult> ToolTask::result() const {
  const std::lock_guard lock(mutex_);
  return result_;
}

int ToolTask::used() const {
  const std::lock_guard lock(mutex_);
  return used_;
}

} // namespace rv
