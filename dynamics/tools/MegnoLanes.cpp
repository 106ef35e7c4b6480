#include "dynamics/tools/MegnoLanes.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/LaneField.h"
#include "dynamics/tools/LaneStack.h"
#include "dynamics/tools/Megno.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace rv {

namespace {

// W MEGNO systems (MegnoRun::System) stacked component-major: y[c * W + l] is component c of lane l, the
// components x (n), w (m), tau, A, B
class LaneSystem final : public LaneStack {
public:
  /// `models`: the lanes' models (the last one repeated into lanes left over)
  LaneSystem(const std::vector<const Model*>& models, const LaneKernel& kernel)
      : LaneStack(*models.front(), kernel,
                  models.front()->dimension() + models.front()->info().coreDimension + 3, "megno lanes"),
        n_(models.front()->dimension()), m_(models.front()->info().coreDimension) {
    ownLaneSystems(models, &MegnoRun::system);
  }
  void rhs(const double* y, double* dy) const override {
    kernel_.tangentRhs(y, 1, dy);
    if (lanes_ % 8 == 0 && cpuHasAvx512())
      sumsAvx512(y, dy);
    else if (cpuHasAvx2())
      sumsAvx2(y, dy);
    else
      sumsBaseline(y, dy);
  }

private:
  // the MEGNO sums' derivatives of every lane, eight or four at a time: megnoIntegrand and 2 A / tau, lane by
  // lane the scalar run's operations in its order (no fused multiply-add), so each lane rounds as MegnoRun
  // does
  [[gnu::target("avx512f"), gnu::flatten]] void sumsAvx512(const double* y, double* dy) const {
    for (int q = 0; q < lanes_; q += 8)
      sums<8>(y + q, dy + q);
  }
  [[gnu::target("avx2"), gnu::flatten]] void sumsAvx2(const double* y, double* dy) const {
    for (int q = 0; q < lanes_; q += 4)
      sums<4>(y + q, dy + q);
  }
  void sumsBaseline(const double* y, double* dy) const {
    for (int q = 0; q < lanes_; q += 4)
      sums<4>(y + q, dy + q);
  }
  template <int P> [[gnu::always_inline]] void sums(const double* y, double* dy) const {
    using Packet = LaneVector<P>;
    const int tau = (n_ + m_) * lanes_, a = tau + lanes_, b = a + lanes_;
    Packet dot(0.0), squared(0.0);
    for (int i = 0; i < m_; ++i) {
      const Packet w = Packet::load(y + (n_ + i) * lanes_), dw = Packet::load(dy + (n_ + i) * lanes_);
      dot += w * dw;
      squared += w * w;
    }
    const Packet t = Packet::load(y + tau);
    Packet(1.0).store(dy + tau);
    (t * dot / squared).store(dy + a);
    const Packet rate = Packet(2.0) * Packet::load(y + a) / t;
    for (int l = 0; l < P; ++l)
      dy[b + l] = t[l] > 0 ? rate[l] : 0;
  }
  int n_, m_;
};

} // namespace

bool megnoRunsOnLanes(const std::vector<const Model*>& models, const IntegratorFactory& makeIntegrator) {
  const auto kernel = laneKernelFor(models);
  return kernel && kernel->compiledFor(1) && makeIntegrator()->stepLanesAlone(kernel->width());
}

std::vector<MegnoLaneResult> megnoOnLanes(const std::vector<const Model*>& models,
                                          const IntegratorFactory& makeIntegrator,
                                          const std::vector<Eigen::VectorXd>& x0s, const MegnoSettings& s,
                                          const ToolControl& control) {
  const auto kernel = laneKernelFor(models);
  if (!kernel) throw std::logic_error("megnoOnLanes: these models do not run on lanes together");
  if (x0s.empty() || x0s.size() != models.size()) throw std::logic_error("megnoOnLanes: one model per state");
  const Model& model = *models[0];
  if (!(s.maxTime > 0) || !std::isfinite(s.maxTime)) throw InputError("megno: the time must be positive");
  if (!(s.interval > 0)) throw InputError("megno: the interval must be positive");
  const int n = model.dimension(), m = model.info().coreDimension, count = static_cast<int>(x0s.size());
  const LaneSystem system(models, *kernel);
  const int width = kernel->width();
  const int tau = (n + m) * width, sumA = tau + width, sumB = sumA + width;

  // the lanes' states: the orbits given, the last repeated into lanes left over; w as MegnoRun starts it
  Eigen::VectorXd w0(m);
  for (int i = 0; i < m; ++i)
    w0[i] = 1.0 / (i + 1);
  w0.normalize();
  Eigen::VectorXd y = Eigen::VectorXd::Zero(system.dimension());
  for (int l = 0; l < width; ++l) {
    const Eigen::VectorXd& x0 = x0s[static_cast<std::size_t>(std::min(l, count - 1))];
    if (x0.size() != n) throw InputError("megno: the initial state has the wrong size");
    for (int c = 0; c < n; ++c)
      y[c * width + l] = x0[c];
    for (int i = 0; i < m; ++i)
      y[(n + i) * width + l] = w0[i];
  }
  const auto alone = [&] { // every orbit by the scalar run: each fails, or not, as it would alone
    std::vector<MegnoLaneResult> r(static_cast<std::size_t>(count));
    for (int l = 0; l < count; ++l) {
      try {
        const MegnoResult one = megno(*models[static_cast<std::size_t>(l)], makeIntegrator,
                                      x0s[static_cast<std::size_t>(l)], s, {}, control);
        if (one.stopped) return std::vector<MegnoLaneResult>{};
        r[static_cast<std::size_t>(l)].last = one.last;
      } catch (const ComputationError&) {
        r[static_cast<std::size_t>(l)].failure = std::current_exception();
      }
    }
    return r;
  };

  double t = 0;
  std::vector<double> logNorm(width, 0.0);
  while (t < s.maxTime) {
    const double target = t + std::min(s.interval, s.maxTime - t);
    try {
      auto integ = makeIntegrator();
      if (!integ->stepLanesAlone(width))
        throw std::logic_error("megnoOnLanes: the method does not step lanes as alone");
      integ->controlBy((n + m) * width); // each orbit and its vector, each its own scale (as MegnoRun)
      integ->scaleErrorsByBlocks(n, m);
      integ->start(system, t, y);
      if (!integ->advanceTo(target, y, [&] { return control.stopRequested(); })) return {};
    } catch (const ComputationError&) {
      return alone();
    }
    t = target;
    for (int l = 0; l < width; ++l) {
      const double norm = tangentLength(y.data() + n * width + l, m, width);
      if (!(norm > 0) || !std::isfinite(norm) || !std::isfinite(y[sumB + l])) return alone();
      logNorm[static_cast<std::size_t>(l)] += std::log(norm);
      for (int i = 0; i < m; ++i)
        y[(n + i) * width + l] /= norm;
    }
    control.progress(t / s.maxTime);
  }
  std::vector<MegnoLaneResult> r(static_cast<std::size_t>(count));
  for (int l = 0; l < count; ++l) { // as MegnoRun::record
    MegnoEstimate& e = r[static_cast<std::size_t>(l)].last;
    e.time = t;
    e.y = 2 * y[sumA + l] / t;
    e.megno = y[sumB + l] / t;
    e.megnoRate = e.megno / (t / 2);
    e.fli = logNorm[static_cast<std::size_t>(l)];
  }
  return r;
}

} // namespace rv
