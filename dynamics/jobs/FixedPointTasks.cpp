#include "dynamics/jobs/FixedPointTasks.h"

#include <sstream>

namespace rv {

std::string MapTaskSpec::describe() const {
  std::ostringstream os;
  os << run.describe() << " map order " << section.order;
  return os.str();
}

MapHolder::MapHolder(const MapTaskSpec& spec) : model_(spec.run.makeModel()) {
  const Model* m = model_.get();
  const RunSpec run = spec.run;
  map_ = std::make_unique<ReturnMap>(
      *model_, [run, m] { return run.makeIntegrator(*m); }, spec.section);
}

FixedPointTask::FixedPointTask(MapTaskSpec spec) : spec_(std::move(spec)) {
  reset();
}

void FixedPointTask::reset() {
  from_ = spec_.guess;
  path_.clear();
  std::lock_guard lock(mutex_);
  result_.reset();
}

bool FixedPointTask::run(const ToolControl& control) {
  MapHolder h(spec_);
  try {
    FixedPointResult r = findFixedPoint(h.map(), from_, spec_.search, control, [this](const SearchPoint& p) {
      from_ = p.point;
      path_.push(p);
    });
    std::lock_guard lock(mutex_);
    result_ = std::move(r);
    return true;
  } catch (const Stopped&) {
    return false;
  }
}

bool FixedPointTask::edit(const TaskEdit& e) {
  edit(e.mapTask());
  return true; // goes on from where it stopped
}

void FixedPointTask::edit(MapTaskSpec spec) {
  spec.guess = spec_.guess;
  spec_ = std::move(spec);
  std::lock_guard lock(mutex_);
  result_.reset(); // the point of the old settings
}

std::optional<FixedPointResult> FixedPointTask::result() const {
  std::lock_guard lock(mutex_);
  return result_;
}

} // namespace rv
