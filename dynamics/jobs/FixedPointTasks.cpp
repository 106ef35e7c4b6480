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

namespace {
IntegratorFactory integrators(const RunSpec& spec) {
  // makeIntegrator only asks the model whether it is a map: any model of the kind will do
  auto probe = std::shared_ptr<Model>(spec.makeModel());
  return [spec, probe] { return spec.makeIntegrator(*probe); };
}
} // namespace

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

ContinuationTask::ContinuationTask(MapTaskSpec spec, ContinuationSettings settings)
    : spec_(std::move(spec)), settings_(std::move(settings)) {
  settings_.search = spec_.search;
  reset();
}

std::string ContinuationTask::describe() const {
  return spec_.describe() + " continued in " + settings_.parameter;
}

void ContinuationTask::reset() {
  points_.clear();
  changes_.clear();
  continuation_ = std::make_unique<Continuation>(
      spec_.run.modelAt(settings_.parameter), integrators(spec_.run), spec_.section,
      spec_.run.modelParameters[settings_.parameter], spec_.guess, settings_);
}

bool ContinuationTask::edit(const TaskEdit& e) {
  edit(e.mapTask(), e.continuation());
  return false;
}

void ContinuationTask::edit(MapTaskSpec spec, ContinuationSettings settings) {
  spec.guess = spec_.guess;
  spec_ = std::move(spec);
  settings_ = std::move(settings);
  settings_.search = spec_.search;
  reset();
}

bool ContinuationTask::run(const ToolControl& control) {
  return continuation_->run(
      control, [this](const ContinuationPoint& p) { points_.push(p); },
      [this](const TypeChange& t) { changes_.push(t); });
}

SeparatrixTask::SeparatrixTask(MapTaskSpec spec, SeparatrixSettings settings)
    : spec_(std::move(spec)), settings_(settings) {}

bool SeparatrixTask::edit(const TaskEdit& e) {
  edit(e.mapTask(), e.separatrix());
  return false;
}

void SeparatrixTask::edit(MapTaskSpec spec, SeparatrixSettings settings) {
  spec.guess = spec_.guess;
  settings.branch = settings_.branch;
  spec_ = std::move(spec);
  settings_ = settings;
  reset();
}

bool SeparatrixTask::run(const ToolControl& control) {
  points_.clear();
  MapHolder h(spec_);
  try {
    const FixedPointResult fp = findFixedPoint(h.map(), spec_.guess, spec_.search, control);
    const SeparatrixResult r = growSeparatrix(
        h.map(), fp, settings_, control, [this](const std::vector<Eigen::VectorXd>& b) { points_.push(b); });
    return r.stoppedBecause != "stopped";
  } catch (const Stopped&) {
    return false;
  }
}

BifurcationTreeTask::BifurcationTreeTask(MapTaskSpec spec, BifurcationTreeSettings settings)
    : spec_(std::move(spec)), settings_(std::move(settings)) {
  settings_.continuation.search = spec_.search;
}

bool BifurcationTreeTask::edit(const TaskEdit& e) {
  edit(e.mapTask(), e.bifurcationTree());
  return false;
}

void BifurcationTreeTask::edit(MapTaskSpec spec, BifurcationTreeSettings settings) {
  spec.guess = spec_.guess;
  spec_ = std::move(spec);
  settings_ = std::move(settings);
  settings_.continuation.search = spec_.search;
  reset();
}

void BifurcationTreeTask::reset() {
  points_.clear();
  doublings_.clear();
  ends_.clear();
}

bool BifurcationTreeTask::run(const ToolControl& control) {
  reset();
  const std::string& id = settings_.continuation.parameter;
  try {
    const BifurcationTreeResult r = bifurcationTree(
        spec_.run.modelAt(id), integrators(spec_.run), spec_.section, spec_.run.modelParameters[id],
        spec_.guess, settings_, control,
        [this](const TreeBranch& b, const ContinuationPoint& p) {
          points_.push({b.level, b.order, p});
        },
        [this](const PeriodDoubling& d) { doublings_.push(d); });
    ends_.push(r.end);
    return true;
  } catch (const Stopped&) {
    return false;
  }
}

} // namespace rv
