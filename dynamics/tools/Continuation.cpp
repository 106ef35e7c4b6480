#include "dynamics/tools/Continuation.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"

#include <cmath>
#include <optional>

namespace rv {

const char* toString(TypeChange::Kind kind) {
  switch (kind) {
  case TypeChange::Kind::MultiplierMinusOne:
    return "multiplier -1";
  case TypeChange::Kind::MultiplierPlusOne:
    return "multiplier +1";
  case TypeChange::Kind::Type:
    return "type";
  }
  return "type";
}

std::string describe(const TypeChange& change, const std::string& parameter) {
  return format("type change at %s = %.12g: %s -> %s (%s)", parameter.c_str(), change.parameter,
                toString(change.from), toString(change.to), toString(change.kind));
}

std::pair<double, double> bifurcationTests(const std::vector<std::complex<double>>& m, double tol) {
  std::size_t skip = m.size();
  if (m.size() == 3)
    for (std::size_t i = 0; i < 3; ++i)
      if (std::abs(m[i] - 1.0) <= tol) skip = i;
  std::complex<double> plus = 1, minus = 1;
  for (std::size_t i = 0; i < m.size(); ++i)
    if (i != skip) minus *= m[i] + 1.0, plus *= m[i] - 1.0;
  return {minus.real(), plus.real()};
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
  modelAt_(s_.to); // rejects a finite value outside the parameter's range before any work
  startModel_ = modelAt_(start_);
  shape_ = std::make_unique<ReturnMap>(*startModel_, make_, section_);
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

TypeChange Continuation::locate(const ContinuationPoint& a, const ContinuationPoint& b,
                                const ToolControl& control) const {
  const double tol = s_.search.typeTolerance;
  const auto tests = [&](const ContinuationPoint& c) {
    return bifurcationTests(c.fixedPoint.multipliers, tol);
  };
  const auto [ma, pa] = tests(a);
  const auto [mb, pb] = tests(b);
  TypeChange change{.from = a.fixedPoint.type, .to = b.fixedPoint.type};
  int which = 0; // 1: the -1 test, 2: the +1 test, 0: the type itself
  if ((ma < 0) != (mb < 0))
    which = 1, change.kind = TypeChange::Kind::MultiplierMinusOne;
  else if ((pa < 0) != (pb < 0))
    which = 2, change.kind = TypeChange::Kind::MultiplierPlusOne;
  else
    change.kind = TypeChange::Kind::Type;
  const auto value = [&](const ContinuationPoint& c) {
    const auto t = tests(c);
    return which == 1 ? t.first : t.second;
  };
  ContinuationPoint lo = a, hi = b;
  double flo = which ? value(lo) : 0, fhi = which ? value(hi) : 0;
  int side = 0;
  while (std::abs(hi.parameter - lo.parameter) > s_.bifurcationAccuracy) {
    double p = 0.5 * (lo.parameter + hi.parameter);
    if (which) { // Illinois step, kept inside the bracket
      const double q = (lo.parameter * fhi - hi.parameter * flo) / (fhi - flo);
      if (std::isfinite(q) && std::min(lo.parameter, hi.parameter) < q &&
          q < std::max(lo.parameter, hi.parameter))
        p = q;
    }
    const double w = (p - lo.parameter) / (hi.parameter - lo.parameter);
    const Eigen::VectorXd guess = lo.fixedPoint.point + w * (hi.fixedPoint.point - lo.fixedPoint.point);
    ContinuationPoint mid{p, solveAt(p, guess, control)};
    const bool withLo = which ? (value(mid) < 0) == (flo < 0) : mid.fixedPoint.type == lo.fixedPoint.type;
    if (withLo) {
      lo = std::move(mid);
      if (which) flo = value(lo);
      if (side == +1) fhi /= 2;
      side = +1;
    } else {
      hi = std::move(mid);
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

bool Continuation::run(const ToolControl& control,
                       const std::function<void(const ContinuationPoint&)>& onPoint,
                       const std::function<void(const TypeChange&)>& onChange) {
  if (finished_) return true;
  try {
    if (points_.empty()) {
      points_.push_back({start_, solveAt(start_, guess_, control)});
      if (onPoint) onPoint(points_.back());
    }
    while (true) {
      const ContinuationPoint& last = points_.back();
      if (std::abs(last.parameter - s_.to) <= 1e-12 * std::max(1.0, std::abs(s_.to))) break;
      // the next value on the grid start + k step (no accumulated rounding; a grid point within a hundredth
      // of a step, such as the last point itself when the step is near the parameter's rounding, is passed
      // over), the last step shortened to land on the finite value; a step that finds no point is halved (up
      // to 8 times) before the family is given up
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
      if (onPoint) onPoint(points_.back());
      // a step that lands on a parabolic point is between types: compare with the last definite one
      const ContinuationPoint& b = points_.back();
      while (lastDefinite_ + 1 < points_.size() &&
             points_[lastDefinite_].fixedPoint.type == FixedPointType::Parabolic)
        ++lastDefinite_;
      const ContinuationPoint& a = points_[lastDefinite_];
      if (b.fixedPoint.type != FixedPointType::Parabolic && a.fixedPoint.type != b.fixedPoint.type &&
          a.fixedPoint.type != FixedPointType::Parabolic) {
        changes_.push_back(locate(a, b, control));
        if (onChange) onChange(changes_.back());
        if (s_.stopAtTypeChange) break;
      }
      if (b.fixedPoint.type != FixedPointType::Parabolic) lastDefinite_ = points_.size() - 1;
      control.progress(std::min(1.0, (b.parameter - start_) / (s_.to - start_)));
    }
  } catch (const Stopped&) {
    return false;
  } catch (const ComputationError& e) {
    const double at = points_.empty() ? start_ : points_.back().parameter;
    throw ComputationError(format("continuation in %s after %s = %.10g: %s", s_.parameter.c_str(),
                                  s_.parameter.c_str(), at, e.what()));
  }
  finished_ = true;
  return true;
}

} // namespace rv
