#include "dynamics/tools/Separatrix.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <list>

namespace rv {

namespace {

double angleBetween(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const double c = a.dot(b) / (a.norm() * b.norm());
  return std::acos(std::clamp(c, -1.0, 1.0));
}

struct Node {
  double t;            ///< level + s: the point is F^level(y(s))
  Eigen::VectorXd pos; ///< in canonical coordinates
};

} // namespace

SeparatrixResult growSeparatrix(const ReturnMap& map, const FixedPointResult& fp, const SeparatrixSettings& s,
                                const ToolControl& control,
                                const std::function<void(const std::vector<Eigen::VectorXd>&)>& onPoints) {
  if (map.dimension() != 2) throw InputError("separatrix: separatrices are drawn for 2D maps only");
  if (s.branch < 1 || s.branch > 4) throw InputError("separatrix: the branch number is 1, 2, 3 or 4");
  if (!(s.linearRegion > 0) || !(s.linearAccuracy > 0) || !(s.maxDistance > 0) || !(s.maxAngle > 0) ||
      s.segmentPoints < 2 || s.maxIterations < 1)
    throw InputError("separatrix: the region, accuracy, distance, angle and counts must be positive");
  if (!isHyperbolic(fp.type))
    throw ComputationError(std::string("separatrix: the fixed point is ") + toString(fp.type) +
                           ", not hyperbolic");

  SeparatrixResult r;
  Eigen::EigenSolver<Eigen::MatrixXd> es(fp.jacobian);
  const int which = s.branch <= 2 ? 0 : 1;
  // eigenvalues in the order of fp.multipliers (decreasing modulus)
  Eigen::Index idx = 0;
  for (Eigen::Index i = 0; i < 2; ++i)
    if (std::abs(es.eigenvalues()[i] - fp.multipliers[which]) <
        std::abs(es.eigenvalues()[idx] - fp.multipliers[which]))
      idx = i;
  const double lambda = es.eigenvalues()[idx].real();
  Eigen::VectorXd v = es.eigenvectors().col(idx).real();
  v /= v.norm();
  if (v[0] < 0 || (v[0] == 0 && v[1] < 0)) v = -v; // odd branches leave with increasing first coordinate
  if (s.branch % 2 == 0) v = -v;
  r.multiplier = lambda, r.unstable = std::abs(lambda) > 1, r.direction = v;

  // the step along the branch: the map (or its inverse), twice when the multiplier is negative so that the
  // branch maps onto itself rather than onto its partner
  const ReturnMap forward = r.unstable ? map : map.inverse();
  const int repeat = lambda < 0 ? 2 : 1;
  double Lambda = r.unstable ? std::abs(lambda) : 1 / std::abs(lambda);
  Lambda = std::pow(Lambda, repeat);
  const auto F = [&](Eigen::VectorXd x) {
    for (int i = 0; i < repeat; ++i)
      x = forward(x, control);
    return map.canonical(x);
  };
  const Eigen::VectorXd& xs = fp.point;

  // the linear segment: shrink until the image of x* + delta v leaves along v
  double delta = s.linearRegion;
  for (;; delta /= 2) {
    if (delta < s.fixedPointAccuracy)
      throw ComputationError(format("separatrix: no linear region found down to %g (the eigenvector is not "
                                    "reproduced to %g rad); refine the fixed point or relax the accuracy",
                                    s.fixedPointAccuracy, s.linearAccuracy));
    try {
      const Eigen::VectorXd w = map.difference(F(xs + delta * v), xs);
      if (angleBetween(w, v) <= s.linearAccuracy) break;
    } catch (const ComputationError&) {
    }
  }
  r.linearRegion = delta;
  const auto seed = [&](double s01) { return Eigen::VectorXd(xs + delta * std::pow(Lambda, s01) * v); };
  const auto pointAt = [&](double t) {
    const int level = static_cast<int>(std::floor(t));
    Eigen::VectorXd x = map.canonical(seed(t - level));
    for (int k = 0; k < level; ++k)
      x = F(x);
    return x;
  };

  std::vector<Node> curve;
  for (int j = 0; j < s.segmentPoints; ++j) {
    const double t = static_cast<double>(j) / s.segmentPoints;
    curve.push_back({t, map.canonical(seed(t))});
  }
  std::size_t levelStart = 0;
  const auto emit = [&](std::size_t from) {
    std::vector<Eigen::VectorXd> batch;
    for (std::size_t i = from; i < curve.size(); ++i)
      batch.push_back(curve[i].pos);
    for (auto& p : batch)
      r.points.push_back(p);
    if (onPoints && !batch.empty()) onPoints(batch);
  };
  emit(0);
  r.stoppedBecause = "iterations";
  try {
    for (int level = 1; level <= s.maxIterations; ++level) {
      // the images of the previous level, then refinement of the new stretch (and its junction)
      std::vector<Node> next;
      for (std::size_t i = levelStart; i < curve.size(); ++i)
        next.push_back({curve[i].t + 1, F(curve[i].pos)});
      const std::size_t junction = curve.size() - 1; // the last point of the previous level
      curve.insert(curve.end(), next.begin(), next.end());
      levelStart = junction + 1;
      for (int pass = 0; pass < 60; ++pass) {
        std::vector<double> inserts;
        for (std::size_t i = junction; i + 1 < curve.size(); ++i) {
          const Eigen::VectorXd d = map.difference(curve[i + 1].pos, curve[i].pos);
          bool split = d.norm() > s.maxDistance;
          if (!split && i + 2 < curve.size()) {
            const Eigen::VectorXd e = map.difference(curve[i + 2].pos, curve[i + 1].pos);
            split = d.norm() > s.minAngleDistance && e.norm() > s.minAngleDistance &&
                    angleBetween(d, e) > s.maxAngle;
          }
          if (split && curve[i + 1].t - curve[i].t > 1e-13)
            inserts.push_back(0.5 * (curve[i].t + curve[i + 1].t));
        }
        if (inserts.empty()) break;
        if (control.stopRequested()) throw Stopped{};
        std::vector<Node> merged(curve.begin(), curve.begin() + junction);
        std::size_t k = 0;
        for (std::size_t i = junction; i < curve.size(); ++i) {
          merged.push_back(curve[i]);
          if (k < inserts.size() && i + 1 < curve.size() && inserts[k] < curve[i + 1].t)
            merged.push_back({inserts[k], pointAt(inserts[k])}), ++k;
        }
        curve.swap(merged);
        if (static_cast<long>(curve.size()) >= s.maxPoints) break;
      }
      emit(r.points.size());
      control.progress(std::min(1.0, std::max(static_cast<double>(level) / s.maxIterations,
                                              static_cast<double>(curve.size()) / s.maxPoints)));
      if (static_cast<long>(curve.size()) >= s.maxPoints) {
        r.stoppedBecause = "points";
        break;
      }
      if (control.stopRequested()) throw Stopped{};
    }
  } catch (const Stopped&) {
    r.stoppedBecause = "stopped";
  } catch (const ComputationError& e) {
    r.stoppedBecause = e.what(); // e.g. the branch left the region of allowed motion: keep what was grown
  }
  // points inserted into the junction stretch after it was emitted are in `curve`; return the curve itself
  r.points.clear();
  for (const Node& n : curve)
    r.points.push_back(n.pos), r.parameters.push_back(n.t);
  return r;
}

} // namespace rv
