#include "dynamics/tools/Continuation.h"
#include "dynamics/tools/Bordered.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <optional>

namespace rv {

const char* toString(TypeChange::Kind kind) {
  switch (kind) {
  case TypeChange::Kind::MultiplierMinusOne:
    return "multiplier -1";
  case TypeChange::Kind::MultiplierPlusOne:
    return "multiplier +1";
  case TypeChange::Kind::Fold:
    return "fold";
  case TypeChange::Kind::NeimarkSacker:
    return "Neimark-Sacker";
  case TypeChange::Kind::Type:
    return "type";
  }
  return "type";
}

std::string describe(const TypeChange& change, const std::string& parameter) {
  if (change.kind == TypeChange::Kind::Fold)
    return format("fold at %s = %.12g: the family turns back, %s -> %s (multiplier +1)", parameter.c_str(),
                  change.parameter, toString(change.from), toString(change.to));
  return format("type change at %s = %.12g: %s -> %s (%s)", parameter.c_str(), change.parameter,
                toString(change.from), toString(change.to), toString(change.kind));
}

namespace {
// a 3D map's unit multiplier (an integral), left out of the tests; m.size() when none
std::size_t integralMultiplier(const std::vector<std::complex<double>>& m, double tol) {
  std::size_t skip = m.size();
  if (m.size() == 3)
    for (std::size_t i = 0; i < 3; ++i)
      if (std::abs(m[i] - 1.0) <= tol) skip = i;
  return skip;
}
bool hasComplexPair(FixedPointType t) {
  return t == FixedPointType::Elliptic || t == FixedPointType::StableFocus ||
         t == FixedPointType::UnstableFocus;
}
/// The flow's speed in its core components at a map point's state: how far the orbit through it is from an
/// equilibrium. Negative where the point has no state.
double coreSpeed(const Continuation::ModelAt& modelAt, const IntegratorFactory& make,
                 const SectionSettings& section, const ContinuationPoint& p) {
  try {
    const auto model = modelAt(p.parameter);
    const ReturnMap map(*model, make, section);
    const Eigen::VectorXd x = map.stateOf(p.fixedPoint.point);
    Eigen::VectorXd dx(x.size());
    model->rhs(x.data(), dx.data());
    const int core = model->info().coreDimension > 0 ? model->info().coreDimension : model->dimension();
    return dx.head(core).norm();
  } catch (const std::exception&) {
    return -1;
  }
}

/// Whether a flow's family of periodic orbits shrinks onto an equilibrium at its end, as a Lyapunov family
/// ends at its centre: there the orbit's size and the flow's speed along it vanish as the square root of the
/// distance to the parameter value where the equilibrium has the orbit's integrals, |f|^2 ~ a (p* - p). Two
/// extrapolations of |f|^2 to zero (from points at about two and four times the remaining distance) must
/// agree. Says so with the evidence, or nothing.
std::string shrinksOntoAnEquilibrium(const std::vector<ContinuationPoint>& points,
                                     const Continuation::ModelAt& modelAt, const IntegratorFactory& make,
                                     const SectionSettings& section, const std::string& parameter) {
  const std::size_t n = points.size();
  if (n < 4) return {};
  // the last monotone leg in the parameter
  const double sense = points[n - 1].parameter > points[n - 2].parameter ? 1.0 : -1.0;
  std::size_t first = n - 1;
  while (first > 0 && (points[first].parameter - points[first - 1].parameter) * sense > 0)
    --first;
  const double pEnd = points[n - 1].parameter, speedEnd = coreSpeed(modelAt, make, section, points[n - 1]);
  if (speedEnd < 0) return {};
  const double vEnd = speedEnd * speedEnd;
  const auto nearest = [&](double distance) {
    std::size_t best = first;
    for (std::size_t i = first; i + 1 < n; ++i)
      if (std::abs(std::abs(pEnd - points[i].parameter) - distance) <
          std::abs(std::abs(pEnd - points[best].parameter) - distance))
        best = i;
    return best;
  };
  const auto zeroFrom = [&](std::size_t i) -> std::optional<double> {
    const double speed = coreSpeed(modelAt, make, section, points[i]);
    const double v = speed * speed, dp = pEnd - points[i].parameter;
    if (speed < 0 || !(v > vEnd) || dp == 0) return std::nullopt;
    return pEnd + vEnd * dp / (v - vEnd);
  };
  const double leg = std::abs(pEnd - points[first].parameter);
  const auto rough = zeroFrom(nearest(leg / 2));
  if (!rough) return {};
  const double gap = std::abs(*rough - pEnd);
  if (!(gap < leg / 4)) return {};
  const auto twice = zeroFrom(nearest(2 * gap)), fourTimes = zeroFrom(nearest(4 * gap));
  if (!twice || !fourTimes || std::abs(*twice - *fourTimes) > 0.2 * gap) return {};
  return format(
      "; the orbit shrinks onto an equilibrium: the flow's speed at the point, %.3g, falls as the "
      "square root of the distance to %s = %.9g, where it vanishes -- the family of periodic orbits "
      "ends there at an equilibrium with the orbit's integrals (Lyapunov's centre)",
      speedEnd, parameter.c_str(), *twice);
}

} // namespace

double neimarkSackerTest(const std::vector<std::complex<double>>& m, double tol) {
  const std::size_t skip = integralMultiplier(m, tol);
  std::complex<double> product = 1;
  for (std::size_t i = 0; i < m.size(); ++i)
    for (std::size_t j = i + 1; j < m.size(); ++j)
      if (i != skip && j != skip) product *= m[i] * m[j] - 1.0;
  return product.real();
}

std::pair<double, double> bifurcationTests(const std::vector<std::complex<double>>& m, double tol) {
  const std::size_t skip = integralMultiplier(m, tol);
  std::complex<double> plus = 1, minus = 1;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (i != skip) minus *= m[i] + 1.0, plus *= m[i] - 1.0;
  return {minus.real(), plus.real()};
}

Eigen::VectorXd flipDirection(const Eigen::MatrixXd& J) {
  Eigen::EigenSolver<Eigen::MatrixXd> es(J);
  Eigen::Index best = 0;
  for (Eigen::Index i = 1; i < J.rows(); ++i)
    if (std::abs(es.eigenvalues()[i] + 1.0) < std::abs(es.eigenvalues()[best] + 1.0)) best = i;
  Eigen::VectorXd v = es.eigenvectors().col(best).real();
  return v / v.norm();
}

Continuation::Continuation(ModelAt modelAt, IntegratorFactory makeIntegrator, SectionSettings section,
                           double start, Eigen::VectorXd guess, ContinuationSettings settings)
    : modelAt_(std::move(modelAt)), make_(std::move(makeIntegrator)), section_(std::move(section)),
      start_(start), guess_(std::move(guess)), s_(std::move(settings)) {
  if (!(s_.step != 0) || !std::isfinite(s_.step)) throw InputError("--step: must be a nonzero number");
  if ((s_.to - start_) * s_.step < 0)
    throw InputError(format("--to: %g lies the other way from %s = %g for a step of %g", s_.to,
                            s_.parameter.c_str(), start_, s_.step));
  if (!(s_.bifurcationAccuracy > 0))
    throw InputError("continuation: the bifurcation accuracy must be positive");
  if (s_.maxPoints < 2) throw InputError("continuation: the number of points must be at least 2");
  modelAt_(s_.to); // rejects a finite value outside the parameter's range before any work
  startModel_ = modelAt_(start_);
  shape_ = std::make_unique<ReturnMap>(*startModel_, make_, section_);
  arcStep_ = std::abs(s_.step);
}

FixedPointResult Continuation::solveAt(double p, const Eigen::VectorXd& guess,
                                       const ToolControl& control) const {
  const auto model = modelAt_(p);
  const ReturnMap map(*model, make_, section_);
  FixedPointResult r = findFixedPoint(map, guess, s_.search, control);
  if (s_.minimalOrder && section_.order % 2 == 0) {
    // the partners of a point of minimal order n lie apart; a point of order n / 2 is its own partner
    SectionSettings half = section_;
    half.order /= 2;
    const ReturnMap halfMap(*model, make_, half);
    const double apart = halfMap.difference(halfMap(r.point, control), r.point).norm();
    if (apart <= 100 * s_.search.accuracy)
      throw ComputationError(format("the point found is of order %d (%g from its partner), not of order %d",
                                    half.order, apart, section_.order));
  }
  return r;
}

// ---- the arc: u = (x.head(k), p) ----

int Continuation::unknowns() const {
  return s_.search.section2D ? 2 : shape_->dimension();
}

Eigen::VectorXd Continuation::unknownsOf(const ContinuationPoint& c) const {
  const int k = unknowns();
  Eigen::VectorXd u(k + 1);
  u.head(k) = c.fixedPoint.point.head(k);
  u[k] = c.parameter;
  return u;
}

Eigen::VectorXd Continuation::pointOf(const Eigen::VectorXd& u) const {
  const int k = unknowns();
  Eigen::VectorXd x = points_.empty() ? guess_ : points_.front().fixedPoint.point;
  x.head(k) = u.head(k);
  return x;
}

Eigen::VectorXd Continuation::arcDifference(const Eigen::VectorXd& u, const Eigen::VectorXd& v) const {
  const int k = unknowns();
  Eigen::VectorXd d = u - v;
  d.head(k) = shape_->difference(pointOf(u), pointOf(v)).head(k);
  return d;
}

std::pair<Eigen::VectorXd, Eigen::MatrixXd> Continuation::residual(const Eigen::VectorXd& u,
                                                                   const ToolControl& control) const {
  const int k = unknowns();
  const double p = u[k];
  const Eigen::VectorXd x = pointOf(u);
  const auto imageAt = [&](double q) {
    const auto model = modelAt_(q);
    const ReturnMap map(*model, make_, section_);
    return map.difference(map(x, control), x).head(k).eval();
  };
  const auto model = modelAt_(p);
  const ReturnMap map(*model, make_, section_);
  const Linearization lin = map.linearize(x, s_.search.derivatives, control);
  Eigen::MatrixXd J(k, k + 1);
  J.leftCols(k) = lin.jacobian.topLeftCorner(k, k) - Eigen::MatrixXd::Identity(k, k);
  // dF/dp: central differences (a step near the cube root of the rounding), one-sided at the end of the
  // parameter's range
  const double h = 6e-6 * std::max(1.0, std::abs(p));
  std::optional<Eigen::VectorXd> up, down;
  try {
    up = imageAt(p + h);
  } catch (const InputError&) {
  }
  try {
    down = imageAt(p - h);
  } catch (const InputError&) {
  }
  const Eigen::VectorXd F = map.difference(lin.image, x).head(k);
  if (up && down)
    J.col(k) = (*up - *down) / (2 * h);
  else if (up || down)
    J.col(k) = up ? (*up - F) / h : (F - *down) / h;
  else
    throw ComputationError(
        format("%s = %.10g: no neighbouring value of the parameter is allowed", s_.parameter.c_str(), p));
  return {F, J};
}

Eigen::VectorXd Continuation::tangentAt(const Eigen::VectorXd& u, const Eigen::VectorXd& along,
                                        const ToolControl& control) const {
  return curveTangent(
      residual(u, control).second, along,
      "the family's tangent is not defined (a branch point: the derivative of Map^n(x) - x in "
      "(x, parameter) loses rank)");
}

Continuation::Corrected Continuation::correct(Eigen::VectorXd u, const Eigen::VectorXd& base,
                                              const Eigen::VectorXd& normal, double sigma, int iterations,
                                              const ToolControl& control) const {
  const int k = unknowns();
  for (int it = 0;; ++it) {
    const auto [F, J] = residual(u, control);
    const double g = normal.dot(arcDifference(u, base)) - sigma;
    if (F.norm() <= s_.search.accuracy && std::abs(g) <= s_.search.accuracy) {
      // the point at this parameter, its multipliers and type, as it is (see fixedPointAt)
      const auto model = modelAt_(u[k]);
      const ReturnMap map(*model, make_, section_);
      return {{u[k], fixedPointAt(map, pointOf(u), s_.search, control)}, it};
    }
    if (it >= iterations)
      throw ComputationError(format("the corrector did not converge in %d iterations (|Map^n(x) - x| = %.3g)",
                                    iterations, F.norm()));
    const Eigen::VectorXd du = correctorStep(J, normal, F, g, s_.search.maxDistance);
    u += du;
  }
}

std::string Continuation::whyItEnds(const ToolControl& control) const {
  const int k = unknowns();
  const ContinuationPoint& last = points_.back();
  const auto& m = last.fixedPoint.multipliers;
  std::string out;
  if (!m.empty()) {
    const auto nearest = *std::min_element(
        m.begin(), m.end(), [](auto a, auto b) { return std::abs(a - 1.0) < std::abs(b - 1.0); });
    out = std::abs(nearest - 1.0) < 1e-3
              ? format("a multiplier is near +1 there (%.6g%+.6gi): a fold or a branch point", nearest.real(),
                       nearest.imag())
              : format("not a fold (no multiplier near +1: the nearest is %.6g%+.6gi)", nearest.real(),
                       nearest.imag());
  }
  if (!arc_.empty()) {
    const Eigen::VectorXd& t = arc_.back().tangent;
    const double slope = t.head(k).norm() / std::abs(t[k]);
    out += format("; the family turns away from %s (|dx/d%s| = %.3g)", s_.parameter.c_str(),
                  s_.parameter.c_str(), slope);
  }
  if (!modelAt_(last.parameter)->isMap())
    out += shrinksOntoAnEquilibrium(points_, modelAt_, make_, section_, s_.parameter);
  // how the map's points complete into states near the last one: not at all (the edge of the region of
  // allowed motion), or by a derivative that loses rank (a pole of the section's coordinates, as the origin
  // of polar coordinates: many map points, one state)
  try {
    const auto model = modelAt_(last.parameter);
    const ReturnMap map(*model, make_, section_);
    const Eigen::VectorXd& x = last.fixedPoint.point;
    const Eigen::VectorXd state = map.stateOf(x);
    Eigen::MatrixXd completion(state.size(), k);
    for (int i = 0; i < k; ++i) {
      const double d = 1e-6 * std::max(1.0, std::abs(x[i]));
      Eigen::VectorXd up = x, down = x;
      up[i] += d, down[i] -= d;
      for (const auto& y : {up, down})
        if (!map.allowed(y))
          return out +
                 format("; the points %.1g from it have no state: the family reaches the edge of the region "
                        "of allowed motion",
                        d);
      completion.col(i) = (map.stateOf(up) - map.stateOf(down)) / (2 * d);
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(completion);
    const auto& sv = svd.singularValues();
    const double ratio = sv[k - 1] / sv[0];
    out += format("; the completion of map points into states has singular values %.3g .. %.3g", sv[k - 1],
                  sv[0]);
    if (ratio < 0.1)
      out += " there: it nears a loss of rank, a singular point (a pole) of the section's coordinates";
  } catch (const std::exception&) {
  }
  (void)control;
  return out;
}

bool Continuation::arclengthStep(const ToolControl& control) {
  const ArcPoint last = arc_.back();
  const ContinuationPoint& lastPoint = points_.back();
  const double longest = std::abs(s_.step), shortest = longest * std::ldexp(1.0, -14);
  std::string why;
  const double first = std::min(arcStep_, longest);
  auto next = stepAlongCurve<ContinuationPoint>(
      last.u, last.tangent, first, shortest,
      [&](const Eigen::VectorXd& predicted, const Eigen::VectorXd& base, const Eigen::VectorXd& normal,
          double sigma) {
        Corrected c = correct(predicted, base, normal, sigma, 10, control);
        return std::pair{std::move(c.point), c.iterations};
      },
      [&](const ContinuationPoint& c) { return unknownsOf(c); },
      [&](const Eigen::VectorXd& v, const Eigen::VectorXd& w) { return arcDifference(v, w); },
      [&](const Eigen::VectorXd& v, const Eigen::VectorXd& along) { return tangentAt(v, along, control); },
      why);
  if (!next)
    throw ComputationError(format("no point within an arclength step of %.3g (%s): %s",
                                  first * std::ldexp(1.0, -std::ilogb(first / shortest)), why.c_str(),
                                  whyItEnds(control).c_str()));
  const Eigen::VectorXd& tangent = next->tangent;
  arcStep_ = nextStepLength(*next, longest);

  // the window between the start value and the finite value: a point past either end is replaced by the
  // point at that end (the guess interpolated between the last two), and the family ends there
  const double p = next->point.parameter, q = lastPoint.parameter;
  const double toward = s_.to - start_;
  for (const double bound : {s_.to, start_}) {
    const bool past = bound == s_.to ? (p - s_.to) * toward >= 0 : (p - start_) * toward < 0;
    if (!past) continue;
    const double w = (bound - q) / (p - q);
    const Eigen::VectorXd guess =
        lastPoint.fixedPoint.point +
        w * shape_->difference(next->point.fixedPoint.point, lastPoint.fixedPoint.point);
    points_.push_back({bound, solveAt(bound, guess, control)});
    arc_.push_back({unknownsOf(points_.back()), tangent});
    end_ = bound == s_.to ? format("reached %s = %.12g", s_.parameter.c_str(), s_.to)
                          : format("the family turned back and returned to the start value %s = %.12g",
                                   s_.parameter.c_str(), start_);
    return false;
  }
  points_.push_back(std::move(next->point));
  arc_.push_back({unknownsOf(points_.back()), tangent});
  return true;
}

std::unique_ptr<Continuation> Continuation::doubledFamily(const TypeChange& doubling, double distance,
                                                          ContinuationSettings settings,
                                                          const ToolControl& control) const {
  if (doubling.kind != TypeChange::Kind::MultiplierMinusOne)
    throw InputError("branch switching: the change at " + s_.parameter + " = " +
                     std::to_string(doubling.parameter) + " is no period doubling (" +
                     toString(doubling.kind) + ")");
  if (!(distance > 0)) throw InputError("branch switching: the distance must be positive");
  SectionSettings doubled = section_;
  doubled.order *= 2;
  settings.parameter = s_.parameter;
  settings.minimalOrder = true;
  const double pStar = doubling.parameter, lo = std::min(start_, s_.to), hi = std::max(start_, s_.to);
  // a probe of order 2n at the doubling: its corrector, with the parameter among the unknowns, finds the
  // doubled family on the plane through the point across the flip direction
  ContinuationSettings probeSettings = settings;
  probeSettings.to = pStar + std::abs(settings.step);
  probeSettings.step = std::abs(settings.step);
  const Continuation probe(modelAt_, make_, doubled, pStar, doubling.at.fixedPoint.point, probeSettings);
  const int k = probe.unknowns();
  const Eigen::VectorXd v = flipDirection(doubling.at.fixedPoint.jacobian.topLeftCorner(k, k));
  Eigen::VectorXd base(k + 1), normal = Eigen::VectorXd::Zero(k + 1);
  base.head(k) = doubling.at.fixedPoint.point.head(k);
  base[k] = pStar;
  normal.head(k) = v;
  std::optional<ContinuationPoint> first;
  std::string why;
  for (const double f : {1.0, 0.5, 2.0, 0.25, 4.0}) {
    try {
      const double d = f * distance;
      ContinuationPoint p =
          probe.correct(base + d * normal, base, normal, d, s_.search.maxIterations, control).point;
      // the point of order 2n must not be the parent itself (of order n)
      const auto model = modelAt_(p.parameter);
      const ReturnMap parent(*model, make_, section_);
      if (parent.difference(parent(p.fixedPoint.point, control), p.fixedPoint.point).norm() <=
          100 * s_.search.accuracy)
        throw ComputationError("the point found is of order " + std::to_string(section_.order));
      first = std::move(p);
      break;
    } catch (const ComputationError& e) {
      why = e.what();
    } catch (const InputError& e) {
      why = e.what();
    }
  }
  if (!first)
    throw ComputationError(
        format("no point of order %d near the period doubling at %s = %.12g within %g of its "
               "point along the flip direction (%s)",
               doubled.order, s_.parameter.c_str(), pStar, 4 * distance, why.c_str()));
  // continued to the end of the window on the side where it lives
  const double p0 = first->parameter;
  settings.to = p0 >= pStar ? hi : lo;
  if (std::abs(settings.to - p0) <= 1e-12 * std::max(1.0, std::abs(p0)))
    throw ComputationError(
        format("the family of order %d born at %s = %.12g lies outside %s in [%.12g, %.12g]", doubled.order,
               s_.parameter.c_str(), pStar, s_.parameter.c_str(), lo, hi));
  settings.step = std::copysign(std::abs(settings.step), settings.to - p0);
  auto family =
      std::make_unique<Continuation>(modelAt_, make_, doubled, p0, first->fixedPoint.point, settings);
  family->points_.push_back(*first);
  if (settings.method == ContinuationMethod::Arclength) {
    // onward: away from the parent, along the flip direction
    const Eigen::VectorXd u = family->unknownsOf(*first);
    const double side = normal.dot(family->arcDifference(u, base)) >= 0 ? 1 : -1;
    family->arc_.push_back({u, family->tangentAt(u, side * normal, control)});
  }
  return family;
}

// ---- locating a change between two points ----

TypeChange Continuation::locate(std::size_t ia, std::size_t ib, bool fold, const ToolControl& control) const {
  const ContinuationPoint& a = points_[ia];
  const ContinuationPoint& b = points_[ib];
  const double tol = s_.search.typeTolerance;
  // which test function: 1 the -1 test, 2 the +1 test, 3 the Neimark-Sacker test, 0 the type itself
  const auto testOf = [&](const ContinuationPoint& c, int which) {
    const auto& m = c.fixedPoint.multipliers;
    if (which == 3) return neimarkSackerTest(m, tol);
    const auto t = bifurcationTests(m, tol);
    return which == 1 ? t.first : t.second;
  };
  TypeChange change{.from = a.fixedPoint.type, .to = b.fixedPoint.type};
  const auto changesSign = [&](int which) { return (testOf(a, which) < 0) != (testOf(b, which) < 0); };
  int which = 0;
  if (fold)
    which = 2, change.kind = TypeChange::Kind::Fold;
  else if (changesSign(1))
    which = 1, change.kind = TypeChange::Kind::MultiplierMinusOne;
  else if (changesSign(2))
    which = 2, change.kind = TypeChange::Kind::MultiplierPlusOne;
  else if (changesSign(3) && hasComplexPair(a.fixedPoint.type) && hasComplexPair(b.fixedPoint.type))
    which = 3, change.kind = TypeChange::Kind::NeimarkSacker;
  else
    change.kind = TypeChange::Kind::Type;

  // the position of a point between a and b: the parameter (natural), or the distance along the chord from a
  // to b (arclength: the chord crosses a fold, where the parameter does not go on)
  const bool arc = s_.method == ContinuationMethod::Arclength;
  const Eigen::VectorXd ua = unknownsOf(a),
                        chord = arc ? arcDifference(unknownsOf(b), ua) : Eigen::VectorXd();
  const Eigen::VectorXd normal = arc ? (chord / chord.norm()).eval() : Eigen::VectorXd();
  const auto positionOf = [&](const ContinuationPoint& c) {
    return arc ? normal.dot(arcDifference(unknownsOf(c), ua)) : c.parameter;
  };
  const auto solveAtPosition = [&](double sigma, double w) {
    if (!arc) {
      const Eigen::VectorXd guess = a.fixedPoint.point + w * (b.fixedPoint.point - a.fixedPoint.point);
      return ContinuationPoint{sigma, solveAt(sigma, guess, control)};
    }
    return correct(ua + w * chord, ua, normal, sigma, s_.search.maxIterations, control).point;
  };
  const auto value = [&](const ContinuationPoint& c) { return which ? testOf(c, which) : 0.0; };

  ContinuationPoint lo = a, hi = b;
  double slo = positionOf(lo), shi = positionOf(hi);
  const double s0 = slo, s1 = shi;
  double flo = value(lo), fhi = value(hi);
  int side = 0;
  while (std::abs(shi - slo) > s_.bifurcationAccuracy) {
    double sigma = 0.5 * (slo + shi);
    if (which) { // Illinois step, kept inside the bracket
      const double q = (slo * fhi - shi * flo) / (fhi - flo);
      if (std::isfinite(q) && std::min(slo, shi) < q && q < std::max(slo, shi)) sigma = q;
    }
    ContinuationPoint mid = solveAtPosition(sigma, (sigma - s0) / (s1 - s0));
    const bool withLo = which ? (value(mid) < 0) == (flo < 0) : mid.fixedPoint.type == lo.fixedPoint.type;
    if (withLo) {
      lo = std::move(mid), slo = sigma;
      if (which) flo = value(lo);
      if (side == +1) fhi /= 2;
      side = +1;
    } else {
      hi = std::move(mid), shi = sigma;
      if (which) fhi = value(hi);
      if (side == -1) flo /= 2;
      side = -1;
    }
    if (which && (flo == 0 || fhi == 0)) break;
  }
  change.at = (which && std::abs(fhi) < std::abs(flo)) ? hi : lo;
  if (!which) change.at = hi; // the first point of the new type
  change.parameter = change.at.parameter;
  return change;
}

bool Continuation::noteChanges(const std::function<void(const TypeChange&)>& onChange,
                               const ToolControl& control) {
  const std::size_t ib = points_.size() - 1;
  const ContinuationPoint& b = points_[ib];
  // a fold: the tangent's parameter component changes sign between the last two points
  const int k = unknowns();
  const bool fold = s_.method == ContinuationMethod::Arclength && ib >= 1 &&
                    (arc_[ib - 1].tangent[k] < 0) != (arc_[ib].tangent[k] < 0);
  // a step that lands on a parabolic point is between types: compare with the last definite one
  while (lastDefinite_ + 1 < points_.size() &&
         points_[lastDefinite_].fixedPoint.type == FixedPointType::Parabolic)
    ++lastDefinite_;
  const ContinuationPoint& a = points_[lastDefinite_];
  // between types: a parabolic point, or one with its multipliers on the unit circle where the family was a
  // focus (the map does not preserve area: the moment of a Neimark-Sacker bifurcation)
  const FixedPointType ta = a.fixedPoint.type, tb = b.fixedPoint.type;
  const bool between = tb == FixedPointType::Parabolic ||
                       (tb == FixedPointType::Elliptic &&
                        (ta == FixedPointType::StableFocus || ta == FixedPointType::UnstableFocus));
  const bool typeChange = !between && ta != tb && ta != FixedPointType::Parabolic;
  bool noted = false;
  if (fold || typeChange) {
    changes_.push_back(fold ? locate(ib - 1, ib, true, control) : locate(lastDefinite_, ib, false, control));
    if (onChange) onChange(changes_.back());
    noted = true;
  }
  if (!between) lastDefinite_ = ib;
  return noted;
}

bool Continuation::run(const ToolControl& control,
                       const std::function<void(const ContinuationPoint&)>& onPoint,
                       const std::function<void(const TypeChange&)>& onChange) {
  if (doubled_) return doubled_->run(control, onPoint, onChange);
  // switching: this family's points are not the result, its changes are (they say where the switch is)
  if (!runFamily(control, s_.switchAt > 0 ? std::function<void(const ContinuationPoint&)>() : onPoint,
                 onChange))
    return false;
  if (s_.switchAt <= 0) return true;
  std::vector<const TypeChange*> doublings;
  for (const auto& t : changes_)
    if (t.kind == TypeChange::Kind::MultiplierMinusOne) doublings.push_back(&t);
  if (static_cast<int>(doublings.size()) < s_.switchAt)
    throw ComputationError(format("continuation.switch = %d: the family in %s has %d period doubling%s (%s)",
                                  s_.switchAt, s_.parameter.c_str(), static_cast<int>(doublings.size()),
                                  doublings.size() == 1 ? "" : "s", end_.c_str()));
  ContinuationSettings next = s_;
  next.switchAt = 0;
  doubled_ =
      doubledFamily(*doublings[static_cast<std::size_t>(s_.switchAt - 1)], s_.switchDistance, next, control);
  return doubled_->run(control, onPoint, onChange);
}

bool Continuation::runFamily(const ToolControl& control,
                             const std::function<void(const ContinuationPoint&)>& onPoint,
                             const std::function<void(const TypeChange&)>& onChange) {
  if (finished_) return true;
  const bool arclength = s_.method == ContinuationMethod::Arclength;
  const auto reportProgress = [&](double p) {
    progress_ = std::max({progress_, std::clamp((p - start_) / (s_.to - start_), 0.0, 1.0),
                          static_cast<double>(points_.size()) / static_cast<double>(s_.maxPoints)});
    control.progress(std::min(1.0, progress_));
  };
  try {
    if (points_.empty()) {
      points_.push_back({start_, solveAt(start_, guess_, control)});
      if (arclength) {
        // the first tangent points the parameter the step's way
        Eigen::VectorXd along = Eigen::VectorXd::Zero(unknowns() + 1);
        along[unknowns()] = s_.step > 0 ? 1 : -1;
        arc_.push_back({unknownsOf(points_.back()), tangentAt(unknownsOf(points_.back()), along, control)});
      }
    }
    if (!firstReported_) { // the start, found above or given (doubledFamily)
      firstReported_ = true;
      if (onPoint) onPoint(points_.front());
    }
    while (true) {
      const ContinuationPoint& last = points_.back();
      if (!arclength && std::abs(last.parameter - s_.to) <= 1e-12 * std::max(1.0, std::abs(s_.to))) {
        end_ = format("reached %s = %.12g", s_.parameter.c_str(), s_.to);
        break;
      }
      if (arclength && static_cast<long>(points_.size()) >= s_.maxPoints) {
        end_ = format("%ld points (continuation.points)", s_.maxPoints);
        break;
      }
      bool goesOn = true;
      if (arclength) {
        goesOn = arclengthStep(control);
      } else {
        // the next value on the grid start + k step (no accumulated rounding; a grid point within a
        // hundredth of a step, such as the last point itself when the step is near the parameter's rounding,
        // is passed over), the last step shortened to land on the finite value; a step that finds no point is
        // halved (up to 8 times) before the family is given up
        double k = std::floor((last.parameter - start_) / s_.step) + 1;
        if ((start_ + k * s_.step - last.parameter) / s_.step < 0.01) k += 1;
        const double stepped = start_ + k * s_.step;
        double p = (s_.to - stepped) * s_.step > 1e-9 * s_.step * s_.step ? stepped : s_.to;
        std::optional<ContinuationPoint> next;
        for (int halving = 0; !next; ++halving) {
          Eigen::VectorXd guess = last.fixedPoint.point;
          if (points_.size() >= 2 && points_[points_.size() - 2].parameter != last.parameter) {
            const ContinuationPoint& before = points_[points_.size() - 2];
            guess += shape_->difference(last.fixedPoint.point, before.fixedPoint.point) * s_.extrapolation *
                     (p - last.parameter) / (last.parameter - before.parameter);
          }
          try {
            next = ContinuationPoint{p, solveAt(p, guess, control)};
          } catch (const ComputationError&) {
            if (halving == 8) throw;
            p = 0.5 * (last.parameter + p);
          }
        }
        points_.push_back(std::move(*next));
      }
      if (onPoint) onPoint(points_.back());
      const bool changed = noteChanges(onChange, control);
      reportProgress(points_.back().parameter);
      if (changed && s_.stopAtTypeChange) {
        end_ = "stopped at the change of type (continuation.stop_at_type_change)";
        break;
      }
      if (!goesOn) break;
      if (control.stopRequested()) throw Stopped{}; // a map's point may take no poll of its own
    }
  } catch (const Stopped&) {
    return false;
  } catch (const ComputationError& e) {
    const double at = points_.empty() ? start_ : points_.back().parameter;
    std::string hint;
    if (!arclength && points_.size() >= 2) {
      if (!modelAt_(at)->isMap())
        hint = shrinksOntoAnEquilibrium(points_, modelAt_, make_, section_, s_.parameter);
      if (hint.empty())
        hint = " (where a family turns back in the parameter, continuation.method = arclength follows it)";
    }
    throw ComputationError(format("continuation in %s after %s = %.10g: %s%s", s_.parameter.c_str(),
                                  s_.parameter.c_str(), at, e.what(), hint.c_str()));
  }
  finished_ = true;
  return true;
}

} // namespace rv
