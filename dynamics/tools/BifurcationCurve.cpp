#include "dynamics/tools/BifurcationCurve.h"
#include "dynamics/tools/Bordered.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"
#include "dynamics/tools/Continuation.h"

#include <algorithm>
#include <cmath>

namespace rv {

const char* toString(CurveKind kind) {
  switch (kind) {
  case CurveKind::Fold:
    return "fold";
  case CurveKind::PeriodDoubling:
    return "period doubling";
  case CurveKind::NeimarkSacker:
    return "Neimark-Sacker";
  }
  return "fold";
}

namespace {

/// A watched quantity along the curve: where it changes sign, the curve meets another.
struct Watch {
  const char* what;
  double value;
};

/// The multipliers other than the integral's (a 3D map's unit one) and the bifurcation's own, and the
/// quantities watched on them.
std::vector<Watch> watched(std::vector<std::complex<double>> m, CurveKind kind, double tol) {
  if (m.size() == 3)
    for (std::size_t i = 0; i < 3; ++i)
      if (std::abs(m[i] - 1.0) <= tol) {
        m.erase(m.begin() + static_cast<long>(i));
        break;
      }
  const auto nearest = [&](std::complex<double> to) {
    return std::min_element(m.begin(), m.end(),
                            [&](auto a, auto b) { return std::abs(a - to) < std::abs(b - to); });
  };
  if (kind == CurveKind::NeimarkSacker) {
    // the pair nearest the unit circle: cos of its angle, continued past the real axis as (m + 1/m) / 2
    if (m.size() < 2) return {};
    std::sort(m.begin(), m.end(),
              [](auto a, auto b) { return std::abs(std::abs(a) - 1) < std::abs(std::abs(b) - 1); });
    const double c = 0.5 * (m[0] + m[1]).real();
    return {{"1:1 resonance (the pair of multipliers at +1: the curve meets a fold curve)", c - 1},
            {"1:2 resonance (the pair of multipliers at -1: the curve meets a period-doubling curve)", c + 1},
            {"1:3 resonance", c + 0.5},
            {"1:4 resonance", c}};
  }
  if (m.empty()) return {};
  m.erase(nearest(kind == CurveKind::Fold ? 1.0 : -1.0));
  std::complex<double> plus = 1, minus = 1;
  for (auto z : m)
    plus *= z + 1.0, minus *= z - 1.0;
  if (kind == CurveKind::Fold)
    return {{"the curve meets a period-doubling curve (another multiplier -1)", plus.real()},
            {"a second multiplier +1 (1:1 resonance)", minus.real()}};
  return {{"the curve meets a fold curve (another multiplier +1)", minus.real()},
          {"a second multiplier -1 (1:2 resonance)", plus.real()}};
}

class Tracer {
public:
  Tracer(const ModelAt2& modelAt, const IntegratorFactory& make, const SectionSettings& section,
         const BifurcationCurveSettings& s, double first, double second, Eigen::VectorXd templatePoint)
      : modelAt_(modelAt), make_(make), section_(section), s_(s), template_(std::move(templatePoint)),
        model_(modelAt(first, second)) {
    shape_ = std::make_unique<ReturnMap>(*model_, make_, section_);
    k_ = s_.search.section2D ? 2 : shape_->dimension();
  }
  int k() const { return k_; }

  Eigen::VectorXd pointOf(const Eigen::VectorXd& v) const {
    Eigen::VectorXd x = template_;
    x.head(k_) = v.head(k_);
    return x;
  }
  Eigen::VectorXd unknownsOf(const CurvePoint& c) const {
    Eigen::VectorXd v(k_ + 2);
    v.head(k_) = c.fixedPoint.point.head(k_);
    v[k_] = c.first, v[k_ + 1] = c.second;
    return v;
  }
  Eigen::VectorXd difference(const Eigen::VectorXd& v, const Eigen::VectorXd& w) const {
    Eigen::VectorXd d = v - w;
    d.head(k_) = shape_->difference(pointOf(v), pointOf(w)).head(k_);
    return d;
  }

  /// (F, psi) at v, and D Map^n there.
  std::pair<Eigen::VectorXd, Eigen::MatrixXd> system(const Eigen::VectorXd& v,
                                                     const ToolControl& control) const {
    const auto model = modelAt_(v[k_], v[k_ + 1]);
    const ReturnMap map(*model, make_, section_);
    const Eigen::VectorXd x = pointOf(v);
    const Linearization lin = map.linearize(x, s_.search.derivatives, control);
    Eigen::VectorXd G(k_ + 1);
    G.head(k_) = map.difference(lin.image, x).head(k_);
    G[k_] = test(multipliersOf(lin.jacobian));
    return {G, lin.jacobian};
  }
  double test(const std::vector<std::complex<double>>& m) const {
    const double tol = s_.search.typeTolerance;
    switch (s_.kind) {
    case CurveKind::Fold:
      return bifurcationTests(m, tol).second;
    case CurveKind::PeriodDoubling:
      return bifurcationTests(m, tol).first;
    case CurveKind::NeimarkSacker:
      return neimarkSackerTest(m, tol);
    }
    return 0;
  }

  /// d(F, psi)/d(x, p, q): F in x from the map's derivative, the rest by central differences.
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& v, const Eigen::MatrixXd& DP,
                           const ToolControl& control) const {
    Eigen::MatrixXd J(k_ + 1, k_ + 2);
    for (int i = 0; i < k_ + 2; ++i) {
      const double h = (i < k_ ? 1e-6 : 6e-6) * std::max(1.0, std::abs(v[i]));
      Eigen::VectorXd up = v, down = v;
      up[i] += h, down[i] -= h;
      J.col(i) = (system(up, control).first - system(down, control).first) / (2 * h);
    }
    J.topLeftCorner(k_, k_) = DP.topLeftCorner(k_, k_) - Eigen::MatrixXd::Identity(k_, k_);
    return J;
  }

  Eigen::VectorXd tangent(const Eigen::VectorXd& v, const Eigen::VectorXd& along,
                          const ToolControl& control) const {
    const Eigen::MatrixXd DP = system(v, control).second;
    return curveTangent(jacobian(v, DP, control), along,
                        "the curve's tangent is not defined (a singular point of the curve)");
  }

  /// Newton on [F = 0, psi = 0, normal . (v - base) = sigma] from `v`.
  CurvePoint correct(Eigen::VectorXd v, const Eigen::VectorXd& base, const Eigen::VectorXd& normal,
                     double sigma, int iterations, const ToolControl& control, int* spent = nullptr) const {
    const double accuracy = s_.search.accuracy;
    for (int it = 0;; ++it) {
      const auto [G, DP] = system(v, control);
      const double c = normal.dot(difference(v, base)) - sigma;
      if (G.cwiseAbs().maxCoeff() <= accuracy && std::abs(c) <= accuracy) {
        if (spent) *spent = it;
        const auto model = modelAt_(v[k_], v[k_ + 1]);
        const ReturnMap map(*model, make_, section_);
        return {v[k_], v[k_ + 1], fixedPointAt(map, pointOf(v), s_.search, control)};
      }
      if (it >= iterations)
        throw ComputationError(
            format("the corrector did not converge in %d iterations (|Map^n(x) - x| = %.3g, "
                   "test function %.3g)",
                   iterations, G.head(k_).norm(), G[k_]));
      const Eigen::VectorXd dv = correctorStep(jacobian(v, DP, control), normal, G, c, s_.search.maxDistance);
      v += dv;
    }
  }

  /// Where watched quantity `which` changes sign between consecutive points a and b: the Illinois method
  /// along the chord from a to b.
  CurvePoint locate(const CurvePoint& a, const CurvePoint& b, std::size_t which,
                    const ToolControl& control) const {
    const auto value = [&](const CurvePoint& c) {
      return watched(c.fixedPoint.multipliers, s_.kind, s_.search.typeTolerance)[which].value;
    };
    const Eigen::VectorXd va = unknownsOf(a), chord = difference(unknownsOf(b), va);
    const Eigen::VectorXd normal = chord / chord.norm();
    CurvePoint lo = a, hi = b;
    double slo = 0, shi = chord.norm(), flo = value(lo), fhi = value(hi);
    int side = 0;
    while (shi - slo > s_.eventAccuracy) {
      double sigma = 0.5 * (slo + shi);
      const double q = (slo * fhi - shi * flo) / (fhi - flo);
      if (std::isfinite(q) && slo < q && q < shi) sigma = q;
      CurvePoint mid =
          correct(va + chord * (sigma / chord.norm()), va, normal, sigma, s_.search.maxIterations, control);
      const double fm = value(mid);
      if ((fm < 0) == (flo < 0)) {
        lo = std::move(mid), slo = sigma, flo = fm;
        if (side == +1) fhi /= 2;
        side = +1;
      } else {
        hi = std::move(mid), shi = sigma, fhi = fm;
        if (side == -1) flo /= 2;
        side = -1;
      }
      if (flo == 0 || fhi == 0) break;
    }
    return std::abs(fhi) < std::abs(flo) ? hi : lo;
  }

  bool inBox(double p, double q) const {
    return p >= s_.firstMin && p <= s_.firstMax && q >= s_.secondMin && q <= s_.secondMax;
  }

  /// One way along the curve from the start; returns why it ended.
  std::string trace(const CurvePoint& start, Eigen::VectorXd t, std::vector<CurvePoint>& out,
                    std::vector<CurveEvent>& events, const ToolControl& control,
                    const std::function<void(const CurvePoint&)>& onPoint) const {
    const double longest = s_.step, shortest = longest * std::ldexp(1.0, -14);
    const Eigen::VectorXd v0 = unknownsOf(start);
    CurvePoint last = start;
    Eigen::VectorXd vLast = v0;
    double h = longest, travelled = 0;
    for (long n = 0; n < s_.maxPoints; ++n) {
      std::string why;
      auto step = stepAlongCurve<CurvePoint>(
          vLast, t, h, shortest,
          [&](const Eigen::VectorXd& predicted, const Eigen::VectorXd& base, const Eigen::VectorXd& normal,
              double sigma) {
            int spent = 0;
            CurvePoint c = correct(predicted, base, normal, sigma, 10, control, &spent);
            return std::pair{std::move(c), spent};
          },
          [&](const CurvePoint& c) { return unknownsOf(c); },
          [&](const Eigen::VectorXd& v, const Eigen::VectorXd& w) { return difference(v, w); },
          [&](const Eigen::VectorXd& v, const Eigen::VectorXd& along) { return tangent(v, along, control); },
          why);
      if (!step)
        return format("no point within a step of %.3g along the curve (%s)",
                      h * std::ldexp(1.0, -std::ilogb(h / shortest)), why.c_str());
      CurvePoint& next = step->point;
      const Eigen::VectorXd v = unknownsOf(next);
      // a point outside the box: the point on the side it crossed instead, and the curve ends there
      if (!inBox(next.first, next.second)) {
        int coordinate = -1;
        double bound = 0;
        if (next.first < s_.firstMin) coordinate = k_, bound = s_.firstMin;
        if (next.first > s_.firstMax) coordinate = k_, bound = s_.firstMax;
        if (next.second < s_.secondMin) coordinate = k_ + 1, bound = s_.secondMin;
        if (next.second > s_.secondMax) coordinate = k_ + 1, bound = s_.secondMax;
        Eigen::VectorXd normal = Eigen::VectorXd::Zero(k_ + 2);
        normal[coordinate] = 1;
        const double w = (bound - vLast[coordinate]) / (v[coordinate] - vLast[coordinate]);
        try {
          CurvePoint side = correct(vLast + w * difference(v, vLast), vLast, normal,
                                    bound - vLast[coordinate], s_.search.maxIterations, control);
          noteEvents(last, side, events, control);
          out.push_back(side);
          if (onPoint) onPoint(side);
        } catch (const ComputationError&) {
        }
        return format("%s = %.12g reached", coordinate == k_ ? s_.first.c_str() : s_.second.c_str(), bound);
      }
      noteEvents(last, next, events, control);
      out.push_back(next);
      if (onPoint) onPoint(next);
      travelled += difference(v, vLast).norm();
      // a closed curve: back near the start after going round
      if (travelled > 4 * longest && difference(v, v0).norm() < 0.5 * step->h) return "the curve closes";
      last = std::move(next);
      vLast = v;
      t = step->tangent;
      h = nextStepLength(*step, longest);
      control.progress(
          std::min(1.0, static_cast<double>(out.size()) / static_cast<double>(2 * s_.maxPoints)));
    }
    return format("%ld points (bifurcation_curve.points)", s_.maxPoints);
  }

  void noteEvents(const CurvePoint& a, const CurvePoint& b, std::vector<CurveEvent>& events,
                  const ToolControl& control) const {
    const auto wa = watched(a.fixedPoint.multipliers, s_.kind, s_.search.typeTolerance);
    const auto wb = watched(b.fixedPoint.multipliers, s_.kind, s_.search.typeTolerance);
    for (std::size_t i = 0; i < std::min(wa.size(), wb.size()); ++i)
      if ((wa[i].value < 0) != (wb[i].value < 0)) events.push_back({wa[i].what, locate(a, b, i, control)});
  }

private:
  const ModelAt2& modelAt_;
  const IntegratorFactory& make_;
  const SectionSettings& section_;
  const BifurcationCurveSettings& s_;
  Eigen::VectorXd template_;
  std::unique_ptr<Model> model_; ///< at the start: the map's shape (which coordinates are angles)
  std::unique_ptr<ReturnMap> shape_;
  int k_ = 0;
};

} // namespace

BifurcationCurveResult bifurcationCurve(const ModelAt2& modelAt, const IntegratorFactory& make,
                                        const SectionSettings& section, double first, double second,
                                        const Eigen::VectorXd& point, const BifurcationCurveSettings& s,
                                        const ToolControl& control,
                                        const std::function<void(const CurvePoint&)>& onPoint,
                                        BifurcationCurveResult* partial) {
  if (!(s.step > 0) || !std::isfinite(s.step)) throw InputError("bifurcation_curve.step: must be positive");
  if (s.maxPoints < 1) throw InputError("bifurcation_curve.points: must be at least 1");
  if (!(s.firstMin < s.firstMax) || !(s.secondMin < s.secondMax))
    throw InputError("bifurcation_curve: each minimum must lie below its maximum");
  if (s.first == s.second)
    throw InputError("bifurcation_curve: the two parameters must differ (both " + s.first + ")");
  BifurcationCurveResult local;
  BifurcationCurveResult& r = partial ? *partial : local;
  r = {};
  const Tracer tracer(modelAt, make, section, s, first, second, point);
  const int k = tracer.k();
  if (point.size() < k)
    throw InputError(format("bifurcation_curve: the point has %d coordinates, the map %d",
                            static_cast<int>(point.size()), k));
  // the start, corrected onto the curve at this q
  Eigen::VectorXd v0(k + 2), alongQ = Eigen::VectorXd::Zero(k + 2), alongP = alongQ;
  v0.head(k) = point.head(k);
  v0[k] = first, v0[k + 1] = second;
  alongP[k] = 1, alongQ[k + 1] = 1;
  CurvePoint start;
  Eigen::VectorXd t0;
  try {
    start = tracer.correct(v0, v0, alongQ, 0, s.search.maxIterations, control);
    try {
      t0 = tracer.tangent(tracer.unknownsOf(start), alongQ, control);
    } catch (const ComputationError&) { // the curve runs along p here
      t0 = tracer.tangent(tracer.unknownsOf(start), alongP, control);
    }
  } catch (const ComputationError& e) {
    throw ComputationError(
        format("bifurcation_curve: no %s curve through %s = %.10g, %s = %.10g near the point "
               "given: %s",
               toString(s.kind), s.first.c_str(), first, s.second.c_str(), second, e.what()));
  }
  std::vector<CurvePoint> forward, backward;
  std::vector<CurveEvent> eventsForward, eventsBackward;
  std::string endForward, endBackward;
  const auto assemble = [&] {
    r.points.assign(backward.rbegin(), backward.rend());
    r.points.push_back(start);
    r.points.insert(r.points.end(), forward.begin(), forward.end());
    r.events.assign(eventsBackward.rbegin(), eventsBackward.rend());
    r.events.insert(r.events.end(), eventsForward.begin(), eventsForward.end());
    r.end = "one way: " + endForward + "; the other way: " + endBackward;
  };
  try {
    if (onPoint) onPoint(start);
    endForward = tracer.trace(start, t0, forward, eventsForward, control, onPoint);
    if (endForward != "the curve closes")
      endBackward = tracer.trace(start, -t0, backward, eventsBackward, control, onPoint);
  } catch (const Stopped&) {
    assemble();
    throw;
  }
  assemble();
  if (endForward == "the curve closes") r.end = "the curve closes";
  return r;
}

} // namespace rv
