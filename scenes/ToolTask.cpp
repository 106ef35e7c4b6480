#include "scenes/ToolTask.h"

#include "dynamics/core/Errors.h"
#include "scenes/SceneLoader.h"

namespace rv {

ToolTask::ToolTask(const std::string& id, std::vector<nlohmann::json> documents, std::string source)
    : tool_(ToolRegistry::global().get(id)), documents_(std::move(documents)), source_(std::move(source)) {
  if (!findToolRunner(id)) throw InputError("tool '" + id + "' cannot run on a scene by itself");
  if (documents_.empty()) throw InputError("tool '" + id + "': no scene to run on");
}

std::string ToolTask::name() const {
  return tool_.title;
}

std::string ToolTask::describe() const {
  return tool_.title + " on " + source_;
}

bool ToolTask::run(const ToolControl& control) {
  reset();
  std::string failure;
  for (std::size_t i = 0; i < documents_.size(); ++i) {
    const Scene scene = sceneFromJson(documents_[i], source_);
    try {
      ToolResult r = runTool(tool_, scene, control);
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
