#include "dynamics/jobs/PoincareTask.h"

#include "dynamics/core/Errors.h"

#include <sstream>

namespace rv {

PoincareTask::PoincareTask(RunSpec spec, SectionSettings settings)
    : spec_(std::move(spec)), settings_(std::move(settings)) {
  reset();
}

void PoincareTask::build(const Eigen::VectorXd& x0, double t0) {
  levelState_ = x0;
  auto integ = spec_.makeIntegrator(*model_);
  integ->start(*model_, t0, x0, settings_.backward ? -1 : +1);
  SectionSettings s = settings_;
  builtAt_ = produced_;
  if (s.maxPoints > 0) s.maxPoints = std::max<long>(0, s.maxPoints - produced_);
  map_ = std::make_unique<PoincareMap>(*model_, std::move(integ), s);
  map_->setStepObserver([this](const Integrator& in) { taps_.offer(*model_, in); });
}

void PoincareTask::reset() {
  model_ = spec_.makeModel();
  last_.reset();
  produced_ = 0;
  points_.clear();
  taps_.restart();
  build(spec_.initialState, 0);
}

bool PoincareTask::edit(const TaskEdit& e) {
  edit(e.run(), e.section());
  return true;
}

void PoincareTask::edit(RunSpec spec, SectionSettings settings) {
  const Eigen::VectorXd from = lastState();
  const double t = last_ ? last_->time : 0.0;      // no point yet: it starts again from its first point
  std::unique_ptr<Model> model = spec.makeModel(); // may throw InputError: nothing changes then
  Eigen::VectorXd x0 = from;
  if (!model->isMap() && !model->info().mapCoordinates.empty()) {
    // the same point of the map on the new level of the integrals (InputError when it has no state there);
    // with no point yet, the trajectory's first point (a click on the map starts it on the section)
    const std::vector<double> at = last_ ? last_->coordinates : map_->coordinatesOf(0, spec_.initialState);
    const int root = last_ ? std::max(1, last_->sheet) : 1;
    x0 = model->stateFromMap(at, {.sectionValue = settings.value, .root = root},
                             last_ ? "the last map point" : "the first map point");
    if (!last_) spec.initialState = x0;
  }
  spec_ = std::move(spec);
  settings_ = std::move(settings);
  model_ = std::move(model);
  build(x0, t);
}

bool PoincareTask::run(const ToolControl& control) {
  while (auto p = map_->next(control)) {
    last_ = *p;
    ++produced_;
    points_.push(std::move(*p), control.stopRequested);
  }
  return !control.stopRequested();
}

void PoincareTask::save(Snapshot& s) const {
  s.put(static_cast<double>(produced_)), s.put(static_cast<double>(builtAt_)), s.put(levelState_);
  s.put(last_ ? 1 : 0);
  if (last_) {
    const Eigen::VectorXd c = Eigen::Map<const Eigen::VectorXd>(
        last_->coordinates.data(), static_cast<Eigen::Index>(last_->coordinates.size()));
    s.put(c), s.put(last_->time), s.put(last_->sheet);
  }
  map_->save(s);
}

void PoincareTask::restore(Snapshot& s) {
  const long produced = s.getLong();
  produced_ = s.getLong(); // the map is built as it was, then takes its saved state
  Eigen::VectorXd level;
  s.get(level);
  if (level.size() != model_->dimension())
    throw InputError("saved trajectory: the state has another dimension");
  last_.reset();
  if (s.get() != 0) {
    Eigen::VectorXd c;
    s.get(c);
    MapPoint p;
    p.coordinates.assign(c.data(), c.data() + c.size());
    p.time = s.get();
    p.sheet = static_cast<int>(s.get());
    last_ = std::move(p);
  }
  build(level, 0);
  map_->restore(s);
  produced_ = produced;
}

void PoincareTask::extend(long more) {
  if (settings_.maxPoints <= 0 || more <= 0) return;
  // the map rebuilt with the larger limit takes the state it stands in: the same steps as one long run
  Snapshot s;
  save(s);
  settings_.maxPoints += more;
  restore(s);
}

Eigen::VectorXd PoincareTask::lastState() const {
  return last_ ? map_->lastState() : map_->integrator().state();
}

std::string PoincareTask::describe() const {
  std::ostringstream os;
  os << spec_.describe() << " section("
     << (settings_.observable.empty() ? model_->info().section : settings_.observable) << "="
     << settings_.value << ")";
  return os.str();
}

} // namespace rv
