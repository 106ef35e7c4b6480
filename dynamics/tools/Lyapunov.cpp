#include "dynamics/tools/Lyapunov.h"

#include "dynamics/core/Errors.h"
#include "dynamics/integrators/MapIteration.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/tools/TangentSystem.h"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace rv {

const SettingsTable<LyapunovSettings>& lyapunovSettingsTable() {
  using S = LyapunovSettings;
  using T = SettingsTable<S>;
  static const T t{
      T::choice(&S::mode,
                {.id = "mode",
                 .label = "Method",
                 .description =
                     "tangent (variational equations, exact Jacobian) or perturbed (nearby trajectories)",
                 .choices = {"tangent", "perturbed"}},
                std::vector{S::Mode::Tangent, S::Mode::Perturbed}),
      T::number(&S::count, {.id = "count",
                            .label = "Number of exponents",
                            .min = 0,
                            .max = 1e6,
                            .description = "how many of the largest exponents; 0: as many as the dimension"}),
      T::number(&S::interval,
                {.id = "interval",
                 .label = "Orthonormalisation interval",
                 .min = 1e-300,
                 .max = 1e300,
                 .description =
                     "the longest time between re-orthonormalisations (tangent method: shorter where the "
                     "vectors spread beyond `spread`; maps: iterations)"}),
      T::number(&S::spread,
                {.id = "spread",
                 .label = "Largest spread in an interval",
                 .min = 0,
                 .max = 1e12,
                 .description =
                     "tangent method: an interval in which a vector shrinks or cancels by more than this "
                     "factor is taken again at half the length (and grows back to the interval where they "
                     "keep within); 0: every interval as set"}),
      T::number(&S::transient,
                {.id = "transient",
                 .label = "Transient",
                 .min = 0,
                 .max = 1e300,
                 .description =
                     "time integrated first and discarded (the vectors align with the directions of "
                     "growth); the exponents are averaged over the time after it"}),
      T::number(&S::perturbation, {.id = "perturbation",
                                   .label = "Initial perturbation",
                                   .min = 1e-300,
                                   .max = 1e300,
                                   .description = "distance of the nearby trajectories (perturbed method)"}),
      T::number(
          &S::maxPerturbation,
          {.id = "max_perturbation",
           .label = "Max. perturbation",
           .min = 1e-300,
           .max = 1e300,
           .description = "perturbed method: an interval is halved while a perturbation grows beyond this"}),
      T::number(&S::estimateEvery,
                {.id = "estimate_every",
                 .label = "Iterations between estimates",
                 .min = 1,
                 .max = 1e9,
                 .description = "estimates this many intervals apart are compared for the stopping rule"}),
      T::number(&S::accuracy, {.id = "accuracy",
                               .label = "Accuracy",
                               .min = 1e-300,
                               .max = 1e300,
                               .description = "compared estimates this close count as a success"}),
      T::number(&S::successes,
                {.id = "successes",
                 .label = "Successful comparisons",
                 .min = 0,
                 .max = 1e9,
                 .description = "stop after this many successes in a row (0: run to the time)"}),
      T::number(&S::outputPeriod, {.id = "output_period",
                                   .label = "Output period",
                                   .min = 1e-300,
                                   .max = 1e300,
                                   .description = "time between the estimates streamed to charts"}),
      T::choice(&S::renormalizeIntegrals,
                {.id = "renormalize",
                 .label = "Keep to the integrals' level",
                 .description =
                     "project the tangent vectors on the level set of the first integrals (the trivial "
                     "exponents vanish)",
                 .choices = {"no", "yes"}},
                std::vector{false, true}),
      T::number(&S::maxTime,
                {.id = "time",
                 .label = "Time",
                 .min = 1e-300,
                 .max = 1e300,
                 .description =
                     "time over which the exponents are averaged, after the transient (maps: iterations)"}),
  };
  return t;
}

double LyapunovEstimate::sum() const {
  double s = 0;
  for (double e : exponents)
    s += e;
  return s;
}

namespace {

// an orthonormal basis of the integrals' gradients (core coordinates), by central differences
Eigen::MatrixXd integralNormals(const Model& model, const Eigen::VectorXd& x) {
  const int m = model.info().coreDimension;
  const Eigen::Index p = model.integrals(x.data()).size();
  Eigen::MatrixXd G(m, p);
  for (int i = 0; i < m; ++i) {
    const double h = 1e-6 * std::max(1.0, std::abs(x[i]));
    Eigen::VectorXd a = x, b = x;
    a[i] += h, b[i] -= h;
    G.row(i) = (model.integrals(a.data()) - model.integrals(b.data())).transpose() / (2 * h);
  }
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(G);
  return qr.householderQ() * Eigen::MatrixXd::Identity(m, std::min<Eigen::Index>(p, m));
}

// QR of V: Q (columns of unit length, R's diagonal made positive), the log stretches log |R_jj| and the
// worst loss of scale of a vector, max_j max(1, |v_j|) / |R_jj|: a vector shrunk by that factor, or cancelled
// by it against the ones before it (the digits Gram-Schmidt loses); infinite where R_jj is 0 or not finite
struct Orthonormalized {
  Eigen::MatrixXd Q;
  Eigen::VectorXd logs;
  double loss = 1;
};
Orthonormalized orthonormalize(const Eigen::MatrixXd& V) {
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(V);
  const Eigen::MatrixXd R = qr.matrixQR().topRows(V.cols()).triangularView<Eigen::Upper>();
  Orthonormalized o{qr.householderQ() * Eigen::MatrixXd::Identity(V.rows(), V.cols()),
                    Eigen::VectorXd(V.cols())};
  for (Eigen::Index j = 0; j < V.cols(); ++j) {
    const double r = R(j, j);
    o.logs[j] = std::log(std::abs(r));
    if (r < 0) o.Q.col(j) = -o.Q.col(j);
    const double loss = std::max(1.0, V.col(j).norm()) / std::abs(r);
    o.loss = std::isfinite(loss) && std::isfinite(o.logs[j]) ? std::max(o.loss, loss)
                                                             : std::numeric_limits<double>::infinity();
  }
  return o;
}

} // namespace

LyapunovRun::LyapunovRun(const Model& model, IntegratorFactory makeIntegrator, const Eigen::VectorXd& x0,
                         LyapunovSettings settings)
    : model_(model), make_(std::move(makeIntegrator)), s_(settings) {
  m_ = model.info().coreDimension, n_ = model.dimension();
  // kept on the integrals' level set, the vectors span its tangent space only: p integrals leave m - p
  // exponents, the others would be the logarithm of a projected-away (zero) stretch, -inf
  const int integrals = s_.renormalizeIntegrals ? static_cast<int>(model.integrals(x0.data()).size()) : 0;
  const int free = std::max(1, m_ - integrals);
  k_ = s_.count > 0 ? s_.count : free;
  if (k_ > m_)
    throw InputError("lyapunov: at most " + std::to_string(m_) + " exponents for " + model.info().id);
  if (k_ > free)
    throw InputError("lyapunov.count: at most " + std::to_string(free) +
                     " exponents with renormalize = yes (" + model.info().id + " has " +
                     std::to_string(integrals) +
                     " first integrals, whose gradients the vectors are kept orthogonal to)");
  if (!(s_.interval > 0)) throw InputError("lyapunov: the interval must be positive");
  if (!(s_.perturbation > 0) || !(s_.maxPerturbation >= s_.perturbation))
    throw InputError("lyapunov: need 0 < perturbation <= max perturbation");
  if (s_.estimateEvery < 1) throw InputError("lyapunov: estimate_every must be at least 1");
  if (!(s_.spread == 0 || s_.spread > 1)) throw InputError("lyapunov.spread: 0 (fixed intervals) or above 1");
  if (!(s_.transient >= 0)) throw InputError("lyapunov.transient: must not be negative");
  interval_ = model.isMap() ? std::max(1.0, std::round(s_.interval)) : s_.interval;
  span_ = interval_;
  nextOutput_ = s_.transient + s_.outputPeriod;
  logs_ = Eigen::VectorXd::Zero(k_);
  V_ = Eigen::MatrixXd::Identity(m_, k_);
  x_ = x0;
  if (s_.mode == LyapunovSettings::Mode::Tangent) {
    tangent_ = std::make_unique<TangentSystem>(model, k_);
    // rk4 with a model that compiles its tangent equations into the steps: the same steps, no integrator
    const auto probe = model.isMap() ? nullptr : make_();
    Eigen::VectorXd ask = Eigen::VectorXd::Zero(tangent_->dimension());
    if (const auto* rk4 = dynamic_cast<const Rk4*>(probe.get()); rk4 && tangent_->rk4Steps(ask, 0, 0))
      fusedStep_ = rk4->stepSize();
  }
  if (integrals > 0) {
    // k vectors orthogonal to the gradients: the first unit vectors projected may be dependent (a gradient
    // in their span), a pivoted QR of all m projected ones picks k independent
    Eigen::MatrixXd all = Eigen::MatrixXd::Identity(m_, m_);
    project(x_, all);
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(all);
    V_ = qr.householderQ() * Eigen::MatrixXd::Identity(m_, k_);
  }
  project(x_, V_);
  V_ = orthonormalize(V_).Q; // the first interval starts from unit vectors too (its spread is then its own)
  startAll(0);
}

LyapunovRun::~LyapunovRun() = default;

void LyapunovRun::project(const Eigen::VectorXd& x, Eigen::MatrixXd& V) const {
  if (!s_.renormalizeIntegrals || model_.integrals(x.data()).size() == 0) return;
  const Eigen::MatrixXd N = integralNormals(model_, x);
  V -= N * (N.transpose() * V);
}

// tangent mode: one integrator on (x, V); perturbed mode: k + 1 integrators on x and x + d v_i
void LyapunovRun::startAll(double t0) {
  const auto fresh = [&]() -> std::unique_ptr<Integrator> {
    if (model_.isMap()) return std::make_unique<MapIteration>();
    auto integrator = make_(); // tangent mode: the steps see the vectors too (a contracting one needs them
    if (tangent_) integrator->scaleErrorsByBlocks(n_, m_); // short), each vector relative to its own scale
    return integrator;
  };
  integs_.clear();
  if (tangent_) {
    state_.resize(n_ + static_cast<Eigen::Index>(m_) * k_);
    state_.head(n_) = x_;
    state_.tail(static_cast<Eigen::Index>(m_) * k_) = Eigen::Map<const Eigen::VectorXd>(V_.data(), V_.size());
    if (fusedStep_ == 0) {
      integs_.push_back(fresh());
      integs_.back()->start(*tangent_, t0, state_);
    }
  } else {
    integs_.push_back(fresh());
    integs_.back()->start(model_, t0, x_);
    for (int j = 0; j < k_; ++j) {
      Eigen::VectorXd y = x_;
      y.head(m_) += s_.perturbation * V_.col(j);
      integs_.push_back(fresh());
      integs_.back()->start(model_, t0, y);
    }
  }
}

// one interval: advance, orthonormalise, restart; false when stopped on the way (nothing is changed then)
bool LyapunovRun::interval(const ToolControl& control) {
  double step = nextSpan();
  if (tangent_) {
    for (;;) { // taken again, shorter, while its vectors spread beyond the bound
      if (const long steps = fusedSteps(step); steps > 0) {
        if (!advanceFused(steps, control)) {
          startAll(t_);
          return false;
        }
      } else {
        if (integs_.empty()) { // an interval that is not a whole number of rk4 steps (often the last one)
          integs_.push_back(make_());
          integs_.back()->scaleErrorsByBlocks(n_, m_);
          integs_.back()->start(*tangent_, t_, state_);
        }
        integs_[0]->advanceTo(t_ + step, state_, [&] { return control.stopRequested(); });
      }
      if (control.stopRequested()) {
        startAll(t_);
        return false;
      }
      if (close(step)) return true;
      step = nextSpan();
    }
  } else {
    for (;;) { // cut the interval short while a perturbation grows beyond its maximum
      std::vector<Eigen::VectorXd> ends(k_ + 1);
      for (int j = 0; j <= k_; ++j)
        integs_[j]->advanceTo(t_ + step, ends[j], [&] { return control.stopRequested(); });
      if (control.stopRequested()) {
        startAll(t_);
        return false;
      }
      double worst = 0;
      for (int j = 1; j <= k_; ++j)
        worst = std::max(worst, (ends[j] - ends[0]).head(m_).norm());
      if (worst > s_.maxPerturbation && step > 1e-9 * interval_ && !model_.isMap()) {
        step /= 2;
        startAll(t_); // x and V still hold the interval's start
        continue;
      }
      x_ = ends[0];
      for (int j = 0; j < k_; ++j)
        V_.col(j) = (ends[j + 1] - ends[0]).head(m_) / s_.perturbation;
      break;
    }
  }
  close(step);
  return true;
}

// the interval of `span` advanced (tangent mode: in state_): orthonormalise, restart. False, back at the
// interval's start with a shorter span, when the tangent vectors spread beyond the bound in it.
bool LyapunovRun::close(double span) {
  Eigen::VectorXd x = tangent_ ? Eigen::VectorXd(state_.head(n_)) : x_;
  Eigen::MatrixXd V =
      tangent_ ? Eigen::MatrixXd(Eigen::Map<const Eigen::MatrixXd>(state_.data() + n_, m_, k_)) : V_;
  // the spread is the integration's, measured before a projection on the integrals' level (which leaves the
  // vectors beyond the level's dimension degenerate on purpose)
  const bool projects = s_.renormalizeIntegrals && model_.integrals(x.data()).size() > 0;
  const double spread = projects ? orthonormalize(V).loss : 0;
  project(x, V);
  Orthonormalized o = orthonormalize(V);
  if (projects) o.loss = spread;
  const bool adapts = tangent_ && !model_.isMap() && s_.spread > 0; // a map's interval: whole iterations
  if (adapts && !(o.loss <= s_.spread)) {
    if (const double shorter = shorterSpan(span); shorter > 0) {
      span_ = shorter;
      startAll(t_); // x_ and V_ still hold the interval's start
      return false;
    }
    span_ = interval_; // a vector degenerate whatever the length (R_jj = 0): no halving forever after
    if (result_.warning.empty()) { // at the shortest interval: go on, and say so once
      std::ostringstream os;
      os << "the tangent vectors spread by " << o.loss << " (more than lyapunov.spread = " << s_.spread
         << ") in an interval of " << span << " at t = " << t_
         << ": the smallest exponents may have lost digits; "
         << (fusedStep_ > 0 ? "a smaller integrator.step helps"
                            : "a smaller integrator step or tolerance helps");
      result_.warning = os.str();
    }
  }
  x_ = std::move(x);
  V_ = std::move(o.Q);
  logs_ += o.logs;
  t_ += span;
  // where the vectors kept well within the bound, the next interval may be twice as long (up to the setting)
  if (adapts && o.loss <= std::pow(s_.spread, 0.4)) span_ = std::min(interval_, 2 * span_);
  if (s_.transient > 0 && tStart_ == 0 && t_ >= s_.transient) { // the transient ends: averaging begins
    tStart_ = t_;
    logs_.setZero();
    history_.clear();
  }
  startAll(t_);
  return true;
}

// half of `span` (a whole number of the fused rk4 steps); 0 where it cannot be shortened further
double LyapunovRun::shorterSpan(double span) const {
  if (fusedStep_ > 0) {
    const double steps = std::floor(std::round(span / fusedStep_) / 2);
    return steps >= 1 ? steps * fusedStep_ : 0;
  }
  return span / 2 >= 1e-9 * interval_ ? span / 2 : 0;
}

long LyapunovRun::nextFusedSteps() const {
  return tangent_ && !finished() ? fusedSteps(nextSpan()) : 0;
}

bool LyapunovRun::closeAdvancedInterval(const std::function<void(const LyapunovEstimate&)>& onEstimate,
                                        const ToolControl& control) {
  if (!close(nextSpan())) return false;
  recordEstimate(onEstimate, control);
  return true;
}

// how many rk4 steps make `span` when the fused path applies and they make it exactly; 0 otherwise
long LyapunovRun::fusedSteps(double span) const {
  if (fusedStep_ == 0) return 0;
  const double n = std::round(span / fusedStep_);
  return n >= 1 && n < 1e15 && std::abs(n * fusedStep_ - span) <= 1e-9 * span ? static_cast<long>(n) : 0;
}

// the fused path over one interval, in chunks between which a stop request is seen; false when stopped
bool LyapunovRun::advanceFused(long steps, const ToolControl& control) {
  constexpr long kChunk = 4096;
  for (long done = 0; done < steps; done += kChunk) {
    if (control.stopRequested()) return false;
    const long chunk = std::min(kChunk, steps - done);
    tangent_->rk4Steps(state_, fusedStep_, chunk);
    Integrator::requireFinite(state_, t_ + static_cast<double>(done + chunk) * fusedStep_,
                              "lyapunov: the variational equations");
  }
  return true;
}

bool LyapunovRun::advanceOneInterval(const std::function<void(const LyapunovEstimate&)>& onEstimate,
                                     const ToolControl& control) {
  if (control.stopRequested() || !interval(control)) return false;
  recordEstimate(onEstimate, control);
  return true;
}

// the estimate after an interval: the history, the stopping rule, the streamed output
void LyapunovRun::recordEstimate(const std::function<void(const LyapunovEstimate&)>& onEstimate,
                                 const ToolControl& control) {
  if (s_.transient > 0 && !(t_ > tStart_ && tStart_ > 0)) { // in the transient (or at its very end)
    control.progress(t_ / endTime());
    return;
  }
  const Eigen::VectorXd estimate = logs_ / (t_ - tStart_);
  result_.last.time = t_;
  result_.last.exponents.assign(estimate.data(), estimate.data() + k_);
  history_.push_back(estimate);
  if (static_cast<int>(history_.size()) > s_.estimateEvery) {
    const double change = (history_.back() - history_.front()).lpNorm<Eigen::Infinity>();
    history_.erase(history_.begin());
    successes_ = change < s_.accuracy ? successes_ + 1 : 0;
    if (s_.successes > 0 && successes_ >= s_.successes) result_.converged = true;
  }
  if (t_ >= nextOutput_) {
    if (onEstimate) onEstimate(result_.last);
    nextOutput_ += s_.outputPeriod;
  }
  control.progress(t_ / endTime());
}

bool LyapunovRun::run(const std::function<void(const LyapunovEstimate&)>& onEstimate,
                      const ToolControl& control) {
  result_.stopped = false;
  while (!finished()) {
    if (!advanceOneInterval(onEstimate, control)) {
      result_.stopped = true;
      return false;
    }
  }
  if (onEstimate && result_.last.time > 0) onEstimate(result_.last);
  return true;
}

void LyapunovRun::save(Snapshot& s) const {
  s.put(t_), s.put(nextOutput_), s.put(successes_), s.put(logs_), s.put(x_), s.put(V_);
  s.put(static_cast<double>(history_.size()));
  for (const auto& h : history_)
    s.put(h);
  const Eigen::VectorXd last = Eigen::Map<const Eigen::VectorXd>(
      result_.last.exponents.data(), static_cast<Eigen::Index>(result_.last.exponents.size()));
  s.put(result_.last.time), s.put(last), s.put(result_.converged ? 1 : 0);
  s.put(span_), s.put(tStart_);
}

void LyapunovRun::restore(Snapshot& s) {
  t_ = s.get(), nextOutput_ = s.get(), successes_ = static_cast<int>(s.get());
  s.get(logs_), s.get(x_), s.get(V_);
  if (logs_.size() != k_ || x_.size() != n_ || V_.rows() != m_ || V_.cols() != k_)
    throw InputError("checkpoint: saved for another number of exponents or another model");
  const long count = s.getLong();
  if (count < 0 || count > s_.estimateEvery + 1) throw InputError("checkpoint: saved with other settings");
  history_.resize(static_cast<std::size_t>(count));
  for (auto& h : history_)
    s.get(h);
  Eigen::VectorXd last;
  result_.last.time = s.get();
  s.get(last);
  result_.last.exponents.assign(last.data(), last.data() + last.size());
  result_.converged = s.get() != 0;
  span_ = s.get(), tStart_ = s.get();
  startAll(t_);
}

LyapunovResult lyapunovExponents(const Model& model, const IntegratorFactory& makeIntegrator,
                                 const Eigen::VectorXd& x0, const LyapunovSettings& s,
                                 const std::function<void(const LyapunovEstimate&)>& onEstimate,
                                 const ToolControl& control) {
  LyapunovRun run(model, makeIntegrator, x0, s);
  run.run(onEstimate, control);
  return run.result();
}

} // namespace rv
