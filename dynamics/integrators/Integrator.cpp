#include "dynamics/integrators/Integrator.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/ExplainsNonFinite.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Adams.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Merson.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/integrators/Taylor.h"
#include "dynamics/integrators/Verner9.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace rv {

void Integrator::start(const Model& model, double t0, const Eigen::VectorXd& x0, int direction) {
  if (x0.size() != model.dimension())
    throw InputError("initial state has " + std::to_string(x0.size()) + " components, " + model.info().id +
                     " needs " + std::to_string(model.dimension()));
  model_ = &model;
  t_ = tPrev_ = t0;
  x_ = xPrev_ = x0;
  direction_ = direction >= 0 ? +1 : -1;
  evaluations_ = 0;
  if (laneSteps_ > 0) {
    if (x0.size() % laneSteps_ != 0)
      throw std::logic_error("Integrator: a state of " + std::to_string(x0.size()) + " components is not " +
                             std::to_string(laneSteps_) + " lanes");
    laneTime_.assign(static_cast<std::size_t>(laneSteps_), t0);
    lanePrevious_ = laneTime_;
  }
}

void Integrator::save(Snapshot& s) const {
  s.put(t_), s.put(tPrev_), s.put(direction_), s.put(static_cast<double>(evaluations_));
  s.put(x_), s.put(xPrev_);
}

void Integrator::restore(Snapshot& s) {
  const auto n = x_.size();
  t_ = s.get(), tPrev_ = s.get(), direction_ = s.get() < 0 ? -1 : +1, evaluations_ = s.getLong();
  s.get(x_), s.get(xPrev_);
  if (x_.size() != n || xPrev_.size() != n)
    throw InputError("checkpoint: the saved state has another dimension");
}

void Integrator::requireFlow(const Model& model) {
  if (model.isMap()) throw InputError(model.info().id + " is a map: it is iterated, not integrated");
}

void Integrator::requireFinite(const Eigen::VectorXd& x, double t, const char* what) {
  // a NaN or an infinity anywhere makes the sum non-finite (so does a sum past 1e308: a blow-up too); one
  // vectorised reduction instead of a test per component
  if (!std::isfinite(x.sum())) {
    std::ostringstream os;
    os << what << " stopped being finite at t = " << t << " (blow-up; try a smaller step)";
    throw ComputationError(os.str());
  }
}

void Integrator::checkFinite() const {
  if (std::isfinite(x_.sum())) return;
  try {
    requireFinite(x_, t_, "the solution");
  } catch (const ComputationError& e) {
    // a model written as equations names the expression that went non-finite at the step's start
    const auto* explains = dynamic_cast<const ExplainsNonFinite*>(model_);
    const std::string cause =
        explains && xPrev_.size() == x_.size() ? explains->nonFiniteCause(xPrev_.data()) : "";
    if (cause.empty()) throw;
    throw ComputationError(std::string(e.what()) + "; " + cause);
  }
}

std::string Integrator::nonFiniteField() const {
  Eigen::VectorXd f(x_.size());
  model_->rhs(x_.data(), f.data());
  const bool here = !std::isfinite(f.sum());
  // not finite at the step's start, or at a stage within the step (what shortened it: a model written as
  // equations remembers where its field last stopped being finite)
  const auto* explains = dynamic_cast<const ExplainsNonFinite*>(model_);
  const std::string cause = explains ? explains->nonFiniteCause(x_.data()) : "";
  if (!here && cause.empty()) return "";
  return std::string(here ? "; the field is not finite there" : "; the field is not finite within the step") +
         (cause.empty() ? std::string() : ": " + cause);
}

void Integrator::advanceCompensated(double h, const Eigen::VectorXd& increment,
                                    Eigen::VectorXd& compensation) {
  xPrev_ = x_;
  tPrev_ = t_;
  for (Eigen::Index i = 0; i < x_.size(); ++i) {
    const double y = increment[i] - compensation[i], sum = x_[i] + y;
    compensation[i] = (sum - x_[i]) - y;
    x_[i] = sum;
  }
  t_ = tPrev_ + h;
  checkFinite();
}

namespace {
// the cubic Hermite weights of xPrev, fPrev, x and f at s = (t - tPrev) / h (f's with h): one place, so every
// lane computes what hermite() computes
struct HermiteWeights {
  double prev, prevRate, end, endRate;
  HermiteWeights(double s, double h) {
    const double s2 = s * s, s3 = s2 * s;
    prev = 2 * s3 - 3 * s2 + 1, prevRate = (s3 - 2 * s2 + s) * h;
    end = -2 * s3 + 3 * s2, endRate = (s3 - s2) * h;
  }
};
} // namespace

void Integrator::hermite(double t, const Eigen::VectorXd& fPrev, const Eigen::VectorXd& f,
                         Eigen::VectorXd& out) const {
  const double h = t_ - tPrev_;
  if (h == 0) {
    out = x_;
    return;
  }
  const HermiteWeights w((t - tPrev_) / h, h);
  out = w.prev * xPrev_ + w.prevRate * fPrev + w.end * x_ + w.endRate * f;
}

void Integrator::hermiteLane(int lane, double t, const Eigen::VectorXd& fPrev, const Eigen::VectorXd& f,
                             Eigen::VectorXd& out) const {
  const auto l = static_cast<std::size_t>(lane);
  const double h = laneTime_[l] - lanePrevious_[l];
  const HermiteWeights w(h == 0 ? 0 : (t - lanePrevious_[l]) / h, h);
  for (Eigen::Index i = lane; i < x_.size(); i += laneSteps_)
    out[i] = h == 0 ? x_[i] : w.prev * xPrev_[i] + w.prevRate * fPrev[i] + w.end * x_[i] + w.endRate * f[i];
}

double Integrator::relativeError(const double* err, const double* x, const double* increment, int lane,
                                 int width, Eigen::Index rows) const {
  const auto magnitude = [&](Eigen::Index c) {
    const Eigen::Index i = c * width + lane;
    return std::max(std::abs(x[i]), std::abs(x[i] + increment[i]));
  };
  double largest = 0;
  for (Eigen::Index begin = 0; begin < rows;) {
    // the block of component `begin`: itself alone, the head, or a block after it
    Eigen::Index end = begin + 1;
    if (blockSize_ > 0 || blockHead_ > 0)
      end = begin < blockHead_ ? std::min<Eigen::Index>(blockHead_, rows)
                               : std::min<Eigen::Index>(begin + std::max(1, blockSize_), rows);
    // a block after the head (a tangent vector) is scaled by its own size alone: its length is arbitrary
    const bool vector = blockSize_ > 0 && begin >= blockHead_;
    double scale = vector ? 0 : 1;
    for (Eigen::Index c = begin; c < end; ++c)
      scale = std::max(scale, magnitude(c));
    if (scale == 0) scale = 1;
    for (Eigen::Index c = begin; c < end; ++c) {
      const double a = std::abs(err[c * width + lane]) / scale;
      if (std::isnan(a)) return a;
      largest = std::max(largest, a);
    }
    begin = end;
  }
  return largest;
}

void Integrator::stepLanes(const std::vector<char>&) {
  throw std::logic_error("Integrator: this method does not step lanes on its own");
}

void Integrator::interpolateLane(int, double, Eigen::VectorXd&) const {
  throw std::logic_error("Integrator: this method does not step lanes on its own");
}

bool Integrator::advanceLanesTo(double t, Eigen::VectorXd& out, const std::function<bool()>& stopRequested) {
  const auto lanes = static_cast<std::size_t>(laneSteps_);
  std::vector<char> behind(lanes);
  for (;;) {
    bool any = false;
    for (std::size_t l = 0; l < lanes; ++l)
      any |= behind[l] = direction_ * (laneTime_[l] - t) < 0;
    if (!any) break;
    if (stopRequested()) return false;
    stepLanes(behind);
  }
  out.resize(x_.size());
  for (int l = 0; l < laneSteps_; ++l) {
    if (laneTime_[static_cast<std::size_t>(l)] == t)
      for (Eigen::Index i = l; i < x_.size(); i += laneSteps_)
        out[i] = x_[i];
    else
      interpolateLane(l, t, out);
  }
  requireFinite(out, t, "the solution");
  // the integrator's own time: where the slowest lane stands (every lane at t or past it)
  t_ = *std::min_element(laneTime_.begin(), laneTime_.end());
  return true;
}

const IntegratorRegistry& IntegratorRegistry::global() {
  return mutableGlobal();
}

void IntegratorRegistry::add(IntegratorEntry entry) {
  if (const IntegratorEntry* e = find(entry.id))
    throw InputError(alreadyRegistered("integrator", entry.id, e->origin));
  entries_.push_back(std::move(entry));
}

const IntegratorEntry* IntegratorRegistry::find(const std::string& id) const {
  for (const auto& e : entries_)
    if (e.id == id) return &e;
  return nullptr;
}

IntegratorRegistry& IntegratorRegistry::mutableGlobal() {
  static IntegratorRegistry registry = [] {
    IntegratorRegistry r;
    r.add(Rk4::entry());
    r.add(Merson::entry());
    r.add(Everhart::entry());
    r.add(Taylor::entry());
    r.add(Verner9::entry());
    r.add(Adams::entry());
    return r;
  }();
  return registry;
}

const IntegratorEntry& IntegratorRegistry::get(const std::string& id) const {
  std::string known;
  for (const auto& e : entries_) {
    if (e.id == id) return e;
    known += " " + e.id;
  }
  throw InputError("unknown integrator '" + id + "' (known:" + known + ")");
}

} // namespace rv
