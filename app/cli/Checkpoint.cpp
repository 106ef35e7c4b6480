#include "app/cli/Checkpoint.h"

#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "scenes/SnapshotJson.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace rv {

namespace {
// 2: Everhart's snapshot holds its step (adaptive) and the last step's length; a format-1 file is refused
constexpr int kFormat = 2;
} // namespace

Checkpoint::Checkpoint(std::string path, std::string command, std::string run)
    : path_(std::move(path)), command_(std::move(command)), run_(std::move(run)),
      last_(std::chrono::steady_clock::now()) {
  if (enabled()) checkWritable(path_, "--checkpoint");
}

std::optional<Checkpoint::Saved> Checkpoint::load() const {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!enabled() || !fs::exists(path_, ec)) return std::nullopt;
  const std::string where = "--checkpoint " + path_ + ": ";
  if (!fs::is_regular_file(path_, ec)) throw InputError(where + "not a regular file");
  std::ifstream in(path_, std::ios::binary);
  if (!in) throw InputError(where + "cannot be read");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object() || j.value("format", 0) != kFormat || !j.contains("state") ||
      !j["state"].is_array() || !j.contains("text") || !j["text"].is_string())
    throw InputError(where + "not a rollviz checkpoint (or a damaged one): delete it to start afresh");
  if (j.value("command", "") != command_ || j.value("run", "") != run_)
    throw InputError(where + "saved by another run (" + j.value("command", std::string("?")) +
                     " with another scene or options): delete it or choose another file");
  Saved saved;
  saved.state = snapshotFromJson(j["state"], where + "delete it to start afresh");
  saved.text = j["text"].get<std::string>();
  return saved;
}

bool Checkpoint::due() const {
  return enabled() && std::chrono::steady_clock::now() - last_ >= period_;
}

void Checkpoint::save(const Snapshot& state, const std::string& text) {
  if (!enabled()) return;
  const auto begin = std::chrono::steady_clock::now();
  const nlohmann::json j{{"format", kFormat},
                         {"command", command_},
                         {"run", run_},
                         {"state", snapshotToJson(state)},
                         {"text", text}};
  AtomicFile file(path_, "--checkpoint");
  {
    std::ofstream out(file.tempPath(), std::ios::binary);
    out << j.dump();
    out.flush();
    if (!out) throw ComputationError("cannot write the checkpoint " + path_);
  }
  file.commit();
  last_ = std::chrono::steady_clock::now();
  // saving stays a small part of the run: at most a tenth of the time
  period_ = std::max(std::chrono::duration<double>(1.0), std::chrono::duration<double>(10 * (last_ - begin)));
}

void Checkpoint::finish() const {
  std::error_code ec;
  if (enabled()) std::filesystem::remove(path_, ec);
}

ToolControl Checkpoint::stoppingWhenDue(const ToolControl& control) const {
  ToolControl c = control;
  c.stopRequested = [this, stop = control.stopRequested] { return stop() || due(); };
  return c;
}

bool Checkpoint::run(const std::function<bool(const ToolControl&)>& work,
                     const std::function<void(Snapshot&)>& save, const ToolControl& control) {
  const ToolControl stopping = stoppingWhenDue(control);
  for (;;) {
    if (work(stopping)) return true;
    Snapshot state;
    save(state);
    this->save(state, "");
    if (control.stopRequested()) return false;
  }
}

void addCheckpointOption(CLI::App* cmd, std::string& path) {
  cmd->add_option(
      "--checkpoint", path,
      "save progress to FILE every few seconds and on Ctrl-C; started again with the same FILE, a "
      "killed or interrupted run goes on from there to the same result (removed when the run completes)");
}

} // namespace rv
