#include "dynamics/tools/Megno.h"

#include "dynamics/core/Errors.h"

#include <cmath>

namespace rv {

const SettingsTable<MegnoSettings>& megnoSettingsTable() {
  using T = SettingsTable<MegnoSettings>;
  static const T t{
      T::number(&MegnoSettings::maxTime, {.id = "time",
                                          .label = "Time",
                                          .min = 1e-300,
                                          .max = 1e300,
                                          .description = "integration time (maps: iterations)"}),
      T::number(&MegnoSettings::outputPeriod,
                {.id = "output_period",
                 .label = "Output period",
                 .min = 1e-300,
                 .max = 1e300,
                 .description = "time between the estimates streamed to charts (given at the ends of the "
                                "renormalisation intervals)"}),
      T::number(&MegnoSettings::interval,
                {.id = "interval",
                 .label = "Renormalisation interval",
                 .min = 1e-300,
                 .max = 1e300,
                 .description = "the tangent vector is scaled back to length 1 this often (flows); the "
                                "logarithms add up in the FLI"}),
  };
  return t;
}

namespace detail {
struct MegnoSystemInfo {
  ModelInfo systemInfo;
};
} // namespace detail

namespace {
detail::MegnoSystemInfo makeInfo(const Model& base) {
  detail::MegnoSystemInfo s{base.info()};
  s.systemInfo.id = base.info().id + "+megno";
  for (int i = 0; i < base.info().coreDimension; ++i)
    s.systemInfo.stateNames.push_back("w_" + std::to_string(i + 1));
  if (!base.isMap())
    for (const char* name : {"megno_tau", "megno_A", "megno_B"})
      s.systemInfo.stateNames.emplace_back(name);
  s.systemInfo.integralNames.clear();
  s.systemInfo.hasMeasure = false;
  return s;
}
} // namespace

/// The model with one tangent vector w in core coordinates and, for flows, tau' = 1, A' = tau (w.w')/(w.w),
/// B' = 2 A / tau: then Y(tau) = 2 A / tau and <Y>(tau) = B / tau.
class MegnoRun::System final : private detail::MegnoSystemInfo, public Model {
public:
  explicit System(const Model& base)
      : detail::MegnoSystemInfo(makeInfo(base)), Model(systemInfo, base.parameters()), base_(base),
        n_(base.dimension()), m_(base.info().coreDimension) {
    observables_ = base.observables(); // they read the base part of the state only
  }
  void rhs(const double* x, double* dx) const override {
    base_.tangentRhs(x, x + n_, 1, dx, dx + n_);
    if (base_.isMap()) return;
    const double tau = x[n_ + m_], a = x[n_ + m_ + 1];
    dx[n_ + m_] = 1;
    dx[n_ + m_ + 1] = megnoIntegrand(tau, x + n_, dx + n_, m_);
    dx[n_ + m_ + 2] = tau > 0 ? 2 * a / tau : 0;
  }
  void jacobian(const double*, double*) const override {
    throw ComputationError("the Jacobian of the MEGNO system is not available");
  }

private:
  const Model& base_;
  int n_, m_;
};

MegnoRun::MegnoRun(const Model& model, IntegratorFactory makeIntegrator, const Eigen::VectorXd& x0,
                   MegnoSettings settings)
    : model_(model), make_(std::move(makeIntegrator)), s_(settings) {
  if (!(s_.maxTime > 0) || !std::isfinite(s_.maxTime)) throw InputError("megno: the time must be positive");
  if (!(s_.interval > 0)) throw InputError("megno: the interval must be positive");
  if (!(s_.outputPeriod > 0)) throw InputError("megno: the output period must be positive");
  n_ = model.dimension(), m_ = model.info().coreDimension;
  if (x0.size() != n_) throw InputError("megno: the initial state has the wrong size");
  nextOutput_ = s_.outputPeriod;
  system_ = std::make_unique<System>(model);
  // a fixed generic unit direction: no special direction (the flow's, an integral's gradient) is favoured
  Eigen::VectorXd w(m_);
  for (int i = 0; i < m_; ++i)
    w[i] = 1.0 / (i + 1);
  state_ = Eigen::VectorXd::Zero(system_->dimension());
  state_.head(n_) = x0;
  state_.segment(n_, m_) = w.normalized();
  start();
}

MegnoRun::~MegnoRun() = default;

std::unique_ptr<Model> MegnoRun::system(const Model& model) {
  return std::make_unique<System>(model);
}

void MegnoRun::start() {
  if (model_.isMap()) return;
  integ_ = make_();
  // steps follow the orbit and the tangent vector, each measured against its own scale (as Lyapunov's): on a
  // dissipative flow a vector along a contracting direction needs shorter steps than the orbit allows. The
  // sums that make the averages are quadratures of these and do not control the steps.
  integ_->controlBy(n_ + m_);
  integ_->scaleErrorsByBlocks(n_, m_);
  integ_->start(*system_, t_, state_);
}

// a flow from t_ over one interval; the tangent vector is scaled back to unit length at its end
bool MegnoRun::flowInterval(const ToolControl& control) {
  const double target = t_ + std::min(s_.interval, s_.maxTime - t_);
  if (!integ_->advanceTo(target, state_, [&] { return control.stopRequested(); })) {
    start(); // back to the interval's start: a continued run is the same as an uninterrupted one
    return false;
  }
  t_ = target;
  sumA_ = state_[n_ + m_ + 1], sumB_ = state_[n_ + m_ + 2];
  const double norm = tangentLength(state_.data() + n_, m_);
  if (!(norm > 0) || !std::isfinite(norm)) throw ComputationError("megno: the tangent vector degenerated");
  logNorm_ += std::log(norm);
  state_.segment(n_, m_) /= norm;
  start();
  return true;
}

void MegnoRun::mapIteration() {
  Eigen::VectorXd next(state_.size());
  system_->rhs(state_.data(), next.data());
  const double norm = next.segment(n_, m_).norm();
  if (!(norm > 0) || !std::isfinite(norm) || !next.allFinite())
    throw ComputationError("megno: the orbit or its tangent vector is not finite at iteration " +
                           std::to_string(static_cast<long>(t_) + 1));
  const double k = t_ + 1, growth = std::log(norm); // |w_{k-1}| = 1
  sumA_ += k * growth;
  sumB_ += 2 * sumA_ / k;
  logNorm_ += growth;
  next.segment(n_, m_) /= norm;
  state_ = std::move(next);
  t_ = k;
}

void MegnoRun::record() {
  MegnoEstimate& e = result_.last;
  e.time = t_;
  e.y = 2 * sumA_ / t_;
  e.megno = sumB_ / t_;
  e.megnoRate = e.megno / (t_ / 2);
  e.fli = logNorm_;
}

bool MegnoRun::run(const std::function<void(const MegnoEstimate&)>& onEstimate, const ToolControl& control) {
  result_.stopped = false;
  const double end = model_.isMap() ? std::round(s_.maxTime) : s_.maxTime;
  while (t_ < end) {
    if (control.stopRequested()) {
      result_.stopped = true;
      return false;
    }
    if (model_.isMap()) {
      mapIteration();
    } else if (!flowInterval(control)) {
      result_.stopped = true;
      return false;
    }
    record();
    if (t_ >= nextOutput_) {
      if (onEstimate) onEstimate(result_.last);
      while (nextOutput_ <= t_)
        nextOutput_ += s_.outputPeriod;
    }
    control.progress(t_ / end);
  }
  return true;
}

void MegnoRun::save(Snapshot& s) const {
  s.put(t_), s.put(nextOutput_), s.put(logNorm_), s.put(sumA_), s.put(sumB_), s.put(state_);
}

void MegnoRun::restore(Snapshot& s) {
  t_ = s.get(), nextOutput_ = s.get(), logNorm_ = s.get(), sumA_ = s.get(), sumB_ = s.get();
  Eigen::VectorXd state;
  s.get(state);
  if (state.size() != state_.size()) throw InputError("checkpoint: saved for another model");
  state_ = state;
  if (t_ > 0) record();
  start();
}

MegnoResult megno(const Model& model, const IntegratorFactory& makeIntegrator, const Eigen::VectorXd& x0,
                  const MegnoSettings& settings, const std::function<void(const MegnoEstimate&)>& onEstimate,
                  const ToolControl& control) {
  MegnoRun run(model, makeIntegrator, x0, settings);
  run.run(onEstimate, control);
  return run.result();
}

} // namespace rv
