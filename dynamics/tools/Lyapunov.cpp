#include "dynamics/tools/Lyapunov.h"

#include "dynamics/core/Errors.h"
#include "dynamics/integrators/MapIteration.h"
#include "dynamics/tools/TangentSystem.h"

#include <Eigen/QR>
#include <cmath>
#include <deque>

namespace rv {

double LyapunovEstimate::sum() const {
  double s = 0;
  for (double e : exponents) s += e;
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

// QR of V in place: V := Q (columns of unit length), the log stretches added to `logs`
void orthonormalize(Eigen::MatrixXd& V, Eigen::VectorXd& logs) {
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(V);
  const Eigen::MatrixXd R = qr.matrixQR().topRows(V.cols()).triangularView<Eigen::Upper>();
  Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(V.rows(), V.cols());
  for (Eigen::Index j = 0; j < V.cols(); ++j) {
    const double r = R(j, j);
    logs[j] += std::log(std::abs(r));
    if (r < 0) Q.col(j) = -Q.col(j);
  }
  V = Q;
}

// advances an integrator to exactly t (interpolating past it) and restarts it there from `out`
void advanceTo(Integrator& integ, const Model& m, double t, Eigen::VectorXd& out, const ToolControl& control) {
  const int dir = integ.direction();
  while (dir * (integ.time() - t) < 0) {
    if (control.stopRequested()) {
      out = integ.state();
      return;
    }
    integ.step();
  }
  if (integ.time() == t || m.isMap())
    out = integ.state();
  else
    integ.interpolate(t, out);
}

} // namespace

LyapunovResult lyapunovExponents(const Model& model, const IntegratorFactory& makeIntegrator, const Eigen::VectorXd& x0,
                                 const LyapunovSettings& s, const std::function<void(const LyapunovEstimate&)>& onEstimate,
                                 const ToolControl& control) {
  const int m = model.info().coreDimension, n = model.dimension();
  const int k = s.count > 0 ? s.count : m;
  if (k > m) throw InputError("lyapunov: at most " + std::to_string(m) + " exponents for " + model.info().id);
  if (!(s.interval > 0)) throw InputError("lyapunov: the interval must be positive");
  if (!(s.perturbation > 0) || !(s.maxPerturbation >= s.perturbation))
    throw InputError("lyapunov: need 0 < perturbation <= max perturbation");
  const double interval = model.isMap() ? std::max(1.0, std::round(s.interval)) : s.interval;
  const auto fresh = [&]() -> std::unique_ptr<Integrator> {
    if (model.isMap()) return std::make_unique<MapIteration>();
    return makeIntegrator();
  };

  Eigen::VectorXd logs = Eigen::VectorXd::Zero(k);
  Eigen::MatrixXd V = Eigen::MatrixXd::Identity(m, k);
  LyapunovResult result;
  std::deque<Eigen::VectorXd> history; // estimates of the last estimateEvery iterations
  int successes = 0;
  double t = 0, nextOutput = s.outputPeriod;
  const auto project = [&](const Eigen::VectorXd& x) {
    if (!s.renormalizeIntegrals || model.integrals(x.data()).size() == 0) return;
    const Eigen::MatrixXd N = integralNormals(model, x);
    V -= N * (N.transpose() * V);
  };

  // tangent mode: one integrator on (x, V); perturbed mode: k + 1 integrators on x and x + d v_i
  std::unique_ptr<TangentSystem> tangent;
  std::vector<std::unique_ptr<Integrator>> integs;
  Eigen::VectorXd x = x0, state;
  const auto startAll = [&](double t0) {
    integs.clear();
    if (s.mode == LyapunovSettings::Mode::Tangent) {
      state.resize(n + m * k);
      state.head(n) = x;
      state.tail(m * k) = Eigen::Map<const Eigen::VectorXd>(V.data(), m * k);
      integs.push_back(fresh());
      integs.back()->start(*tangent, t0, state);
    } else {
      integs.push_back(fresh());
      integs.back()->start(model, t0, x);
      for (int j = 0; j < k; ++j) {
        Eigen::VectorXd y = x;
        y.head(m) += s.perturbation * V.col(j);
        integs.push_back(fresh());
        integs.back()->start(model, t0, y);
      }
    }
  };
  if (s.mode == LyapunovSettings::Mode::Tangent) tangent = std::make_unique<TangentSystem>(model, k);
  project(x);
  startAll(0);

  while (t < s.maxTime) {
    if (control.stopRequested()) {
      result.stopped = true;
      break;
    }
    double step = std::min(interval, s.maxTime - t);
    if (s.mode == LyapunovSettings::Mode::Tangent) {
      advanceTo(*integs[0], *tangent, t + step, state, control);
      if (control.stopRequested()) continue;
      x = state.head(n);
      V = Eigen::Map<const Eigen::MatrixXd>(state.data() + n, m, k);
    } else {
      // cut the interval short while a perturbation grows beyond its maximum
      for (;;) {
        std::vector<Eigen::VectorXd> ends(k + 1);
        for (int j = 0; j <= k; ++j) advanceTo(*integs[j], model, t + step, ends[j], control);
        if (control.stopRequested()) break;
        double worst = 0;
        for (int j = 1; j <= k; ++j) worst = std::max(worst, (ends[j] - ends[0]).head(m).norm());
        if (worst > s.maxPerturbation && step > 1e-9 * interval && !model.isMap()) {
          step /= 2;
          startAll(t); // x and V still hold the interval's start
          continue;
        }
        x = ends[0];
        for (int j = 0; j < k; ++j) V.col(j) = (ends[j + 1] - ends[0]).head(m) / s.perturbation;
        break;
      }
      if (control.stopRequested()) continue;
    }
    t += step;
    project(x);
    orthonormalize(V, logs);
    startAll(t);

    const Eigen::VectorXd estimate = logs / t;
    result.last.time = t;
    result.last.exponents.assign(estimate.data(), estimate.data() + k);
    history.push_back(estimate);
    if (static_cast<int>(history.size()) > s.estimateEvery) {
      const double change = (history.back() - history.front()).lpNorm<Eigen::Infinity>();
      history.pop_front();
      successes = change < s.accuracy ? successes + 1 : 0;
      if (s.successes > 0 && successes >= s.successes) {
        result.converged = true;
        break;
      }
    }
    if (t >= nextOutput) {
      if (onEstimate) onEstimate(result.last);
      nextOutput += s.outputPeriod;
    }
    control.progress(t / s.maxTime);
  }
  if (onEstimate && result.last.time > 0) onEstimate(result.last);
  return result;
}

} // namespace rv
