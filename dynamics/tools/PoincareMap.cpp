#include "dynamics/tools/PoincareMap.h"

#include "dynamics/core/Errors.h"

#include <cmath>

namespace rv {

const ParameterTable& poincareTable() {
  const SectionSettings d; // the defaults
  static const ParameterTable t{
      {.id = "value",
       .label = "Section value",
       .defaultValue = d.value,
       .description = "the level of the section"},
      {.id = "direction",
       .label = "Direction",
       .defaultValue = !d.checkDirection ? 2.0
                       : d.direction > 0 ? 0.0
                                         : 1.0,
       .min = 0,
       .max = 2,
       .description = "the crossings kept: the observable increasing, decreasing, or both",
       .integer = true,
       .choices = {"positive", "negative", "both"}},
      {.id = "points",
       .label = "Number of points",
       .defaultValue = static_cast<double>(d.maxPoints),
       .min = 1,
       .max = 1e15,
       .description = "how many points a headless map or a chart computes",
       .integer = true},
      {.id = "accuracy",
       .label = "Accuracy",
       .defaultValue = d.accuracy,
       .min = 1e-300,
       .max = 1,
       .description = "of the crossing time (Newton on the dense output)"},
      {.id = "integrate",
       .label = "Integrate",
       .defaultValue = d.backward ? 1.0 : 0.0,
       .min = 0,
       .max = 1,
       .description = "forward or backward in time",
       .integer = true,
       .choices = {"forward", "backward"}},
      {.id = "many_sheeted",
       .label = "Many-sheeted",
       .defaultValue = d.manySheeted ? 1.0 : 0.0,
       .min = 0,
       .max = 1,
       .description = "keep only the points on the sheet `root` of the completion",
       .integer = true,
       .choices = {"no", "yes"}},
      {.id = "root",
       .label = "Root",
       .defaultValue = static_cast<double>(d.root),
       .min = 1,
       .max = 1e6,
       .description = "the sheet kept in many-sheeted mode (1: the smallest root)",
       .integer = true},
      {.id = "order",
       .label = "Order",
       .defaultValue = static_cast<double>(d.order),
       .min = 1,
       .max = 1e6,
       .description = "keep every order-th crossing (the map to this power)",
       .integer = true},
      {.id = "max_time",
       .label = "Max. time",
       .defaultValue = d.maxTime,
       .min = 1e-300,
       .max = 1e300,
       .description = "stop integrating at this time"},
  };
  return t;
}

SectionSettings poincareSettings(const ParameterValues& v, std::string observable) {
  SectionSettings s;
  s.observable = std::move(observable);
  s.value = v["value"];
  s.checkDirection = v.choice("direction") != "both";
  s.direction = v.choice("direction") == "negative" ? -1 : +1;
  s.maxPoints = static_cast<long>(v["points"]);
  s.accuracy = v["accuracy"];
  s.backward = v.choice("integrate") == "backward";
  s.manySheeted = v.choice("many_sheeted") == "yes";
  s.root = static_cast<int>(v["root"]);
  s.order = static_cast<int>(v["order"]);
  s.maxTime = v["max_time"];
  return s;
}

SectionCrossings::SectionCrossings(const Model& model, SectionSettings settings)
    : model_(model), s_(std::move(settings)) {
  if (s_.order < 1) throw InputError("poincare: the map order must be at least 1");
  const auto& obs = model.observables();
  const auto find = [&](const std::string& id) -> const Observable* {
    const int i = model.findObservable(id);
    return i < 0 ? nullptr : &obs[i];
  };
  if (!model.isMap()) {
    const std::string id = s_.observable.empty() ? model.info().section : s_.observable;
    section_ = find(id);
    if (!section_)
      throw InputError("poincare.section: unknown observable '" + id + "' of " + model.info().id);
  }
  names_ = model.info().mapCoordinates;
  if (names_.empty())
    for (int i = 0; i < model.info().coreDimension; ++i)
      if (!section_ || model.info().stateNames[i] != section_->id)
        names_.push_back(model.info().stateNames[i]);
  for (const auto& n : names_)
    coords_.push_back(find(n));
}

void SectionCrossings::start(double t, const Eigen::VectorXd& x) {
  last_ = x;
  work_.resize(x.size());
  sigma_ = section_ ? sectionFunction(t, x) : 0;
  startOnSection_ = section_ && std::abs(sigma_) < 1e-9;
}

double SectionCrossings::sectionFunction(double t, const Eigen::VectorXd& x) const {
  const double v = section_->value(t, x.data()) - s_.value;
  return section_->angle ? std::sin(v) : v;
}

bool SectionCrossings::acceptable(double t, const Eigen::VectorXd& x) const {
  if (section_->angle && std::cos(section_->value(t, x.data()) - s_.value) < 0) return false; // the far side
  return true;
}

std::vector<double> SectionCrossings::coordinatesOf(double t, const Eigen::VectorXd& x) const {
  std::vector<double> c;
  for (const Observable* o : coords_)
    c.push_back(o->value(t, x.data()));
  return c;
}

std::optional<MapPoint> SectionCrossings::afterStep(double tPrevious, double t, const Eigen::VectorXd& x,
                                                    int direction, const Interpolate& interpolate) {
  if (model_.isMap()) {
    work_ = x;
  } else {
    const double sigmaBefore = sigma_;
    sigma_ = sectionFunction(t, x);
    // a crossing in the requested direction of time-forward motion (the sign flips when integrating
    // backward)
    const double rising = direction * (sigma_ - sigmaBefore);
    const bool crossed = (sigmaBefore < 0) != (sigma_ < 0) && sigmaBefore != 0;
    const bool leaving = startOnSection_;
    startOnSection_ = false;
    // a point started on the section (a map point) must not count as its own first return
    if (!crossed || leaving || (s_.checkDirection && rising * s_.direction <= 0)) return std::nullopt;
    // Illinois regula falsi on the dense output
    double a = tPrevious, b = t, fa = sigmaBefore, fb = sigma_;
    int side = 0;
    for (int it = 0; it < 200 && std::abs(b - a) > s_.accuracy; ++it) {
      double c = (a * fb - b * fa) / (fb - fa);
      if (!(std::min(a, b) < c && c < std::max(a, b))) c = 0.5 * (a + b);
      interpolate(c, work_);
      const double fc = sectionFunction(c, work_);
      if (fc == 0) {
        a = b = c;
        break;
      }
      if ((fc < 0) == (fb < 0)) {
        b = c, fb = fc;
        if (side == -1) fa /= 2;
        side = -1;
      } else {
        a = c, fa = fc;
        if (side == +1) fb /= 2;
        side = +1;
      }
    }
    t = std::abs(fa) < std::abs(fb) ? a : b;
    interpolate(t, work_);
    if (!acceptable(t, work_)) return std::nullopt;
  }
  ++crossings_;
  if (crossings_ % s_.order != 0) return std::nullopt;
  const int sheet = s_.manySheeted ? model_.sheetOf(work_, {.sectionValue = s_.value, .root = s_.root}) : 0;
  if (s_.manySheeted && sheet != s_.root) return std::nullopt;
  ++points_;
  last_ = work_;
  return MapPoint{coordinatesOf(t, work_), t, sheet};
}

void SectionCrossings::save(Snapshot& s) const {
  s.put(sigma_), s.put(startOnSection_ ? 1 : 0), s.put(static_cast<double>(crossings_));
  s.put(static_cast<double>(points_)), s.put(last_);
}

void SectionCrossings::restore(Snapshot& s) {
  sigma_ = s.get(), startOnSection_ = s.get() != 0, crossings_ = s.getLong(), points_ = s.getLong();
  s.get(last_);
}

PoincareMap::PoincareMap(const Model& model, std::unique_ptr<Integrator> integrator, SectionSettings settings)
    : integ_(std::move(integrator)), s_(settings), crossings_(model, std::move(settings)) {
  crossings_.start(integ_->time(), integ_->state());
}

std::optional<MapPoint> PoincareMap::next(const ToolControl& control) {
  const int dir = integ_->direction();
  const SectionCrossings::Interpolate interpolate = [this](double t, Eigen::VectorXd& out) {
    integ_->sampleAt(t, out);
  };
  while (s_.maxPoints <= 0 || crossings_.points() < s_.maxPoints) {
    if (control.stopRequested() || dir * integ_->time() >= s_.maxTime) return std::nullopt;
    integ_->step();
    if (observer_) observer_(*integ_);
    auto point =
        crossings_.afterStep(integ_->previousTime(), integ_->time(), integ_->state(), dir, interpolate);
    if (!point) continue;
    if (s_.maxPoints > 0) control.progress(static_cast<double>(crossings_.points()) / s_.maxPoints);
    return point;
  }
  return std::nullopt;
}

void PoincareMap::save(Snapshot& s) const {
  integ_->save(s);
  crossings_.save(s);
}

void PoincareMap::restore(Snapshot& s) {
  integ_->restore(s);
  crossings_.restore(s);
}

} // namespace rv
