#include "scenes/SweepTask.h"

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fmt/core.h>
#include <limits>
#include <thread>
#include <unistd.h>

namespace rv {

namespace {
std::string temporaryStore() {
  static std::atomic<int> counter{0};
  return (std::filesystem::temp_directory_path() /
          fmt::format("rollviz-sweep-{}-{}.store", ::getpid(), counter.fetch_add(1)))
      .string();
}
} // namespace

SweepTask::SweepTask(SweepSpec spec, int threads)
    : spec_(std::move(spec)),
      threads_(threads > 0 ? threads : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()))),
      path_(temporaryStore()) {
  reset();
}

SweepTask::~SweepTask() {
  if (store_) store_->remove();
}

std::string SweepTask::name() const {
  return "Sweep: " + spec_.quantity->id + spec_.quantityName;
}

std::string SweepTask::describe() const {
  std::string axes;
  for (const auto& a : spec_.axes)
    axes += fmt::format("{}{} in [{}, {}] x {}", axes.empty() ? "" : "; ", a.id, a.min, a.max, a.count);
  return fmt::format("{}{}quantity {}{} over {} ({} points, {} threads); scene: problem {}", spec_.title,
                     spec_.title.empty() ? "" : "\n", spec_.quantity->id, spec_.quantityName, axes,
                     spec_.points(), threads_, spec_.base.model->info().id);
}

bool SweepTask::run(const ToolControl& control) {
  return runSweepLevels(spec_, *store_, threads_, [&](ChunkScheduler& scheduler) {
    return runSweepThreads(
        *store_, scheduler,
        [this](const std::vector<long>& chunk, const ToolControl& c, const RecordSink& sink) {
          evaluateSweepPoints(spec_, chunk, c, sink);
        },
        threads_, control);
  });
}

void SweepTask::reset() {
  ++generation_;
  if (store_) store_->remove();
  store_ = std::make_unique<SweepStore>(path_, spec_.resolved.dump(), spec_.points(),
                                        static_cast<int>(spec_.columns.size()), "sweep");
}

void SweepTask::updateChartData(SweepChartData& d, std::vector<char>& read) const {
  const std::size_t n = spec_.columns.size(), points = static_cast<std::size_t>(spec_.points());
  if (read.size() != points) {
    d = sweepChartData(spec_);
    d.values.assign(points * n, std::numeric_limits<double>::quiet_NaN());
    read.assign(points, 0);
  }
  if (spec_.refine > 0) { // a new point repaints the cells around it: the whole grid again
    if (computed_.size() != points || read[0] != 1) computed_.assign(points, {}); // (a new start)
    const long done = store_->doneCount();
    if (read[0] != 1 || lastPainted_ != done) {
      for (std::size_t i = 0; i < points; ++i)
        if (computed_[i].empty() && store_->done(static_cast<long>(i)))
          computed_[i] = store_->read(static_cast<long>(i)).values;
      d.values = sweepGridValues(
          spec_, [&](long i) { return !computed_[static_cast<std::size_t>(i)].empty(); },
          [&](long i) { return SweepRecord{computed_[static_cast<std::size_t>(i)]}; });
    }
    read[0] = 1;
    lastPainted_ = done;
    return;
  }
  for (std::size_t i = 0; i < points; ++i)
    if (!read[i] && store_->done(static_cast<long>(i))) {
      const SweepRecord r = store_->read(static_cast<long>(i));
      std::copy(r.values.begin(), r.values.end(), d.values.begin() + static_cast<std::ptrdiff_t>(i * n));
      read[i] = 1;
    }
}

} // namespace rv
