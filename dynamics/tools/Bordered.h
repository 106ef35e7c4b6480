// Bordered.h -- the linear algebra of pseudo-arclength continuation, shared by the families of fixed points
// (Continuation.h) and the bifurcation curves (BifurcationCurve.h): a system of m equations in m + 1
// unknowns, its derivative J (m x (m + 1)) bordered by one more row (Keller, Numerical solution of
// bifurcation and nonlinear eigenvalue problems (1977); Allgower & Georg, Introduction to Numerical
// Continuation Methods (1990) §2.1-2.2).
#pragma once
#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

namespace rv {

/// The unit tangent of the solution curve: the null vector of J, oriented along `along` (the bordered system
/// [J; along^T] t = (0, 1)). ComputationError `why` where that system is singular (J of rank below m, a
/// branch point, or `along` orthogonal to the curve).
Eigen::VectorXd curveTangent(const Eigen::MatrixXd& J, const Eigen::VectorXd& along, const char* why);

/// One Newton step of the corrector on [F(v) = 0, normal . (v - base) = sigma]: the solution d of
/// [J; normal^T] d = -(F, g), g the constraint's residual, shortened to `maxDistance`. ComputationError when
/// the bordered matrix is singular.
Eigen::VectorXd correctorStep(const Eigen::MatrixXd& J, const Eigen::VectorXd& normal,
                              const Eigen::VectorXd& F, double g, double maxDistance);

} // namespace rv

namespace rv {

/// A step taken along a solution curve.
template <class Point> struct CurveStep {
  Point point;
  Eigen::VectorXd tangent; ///< there, oriented as the step went
  double h = 0;            ///< the step's length
  int iterations = 0;      ///< the corrector's
};

/// One pseudo-arclength step from unknowns `u` with unit tangent `t`: the point corrected from u + h t on the
/// plane t . (v - u) = h, accepted when it moved at most 2h and its tangent turned by less than acos 0.8
/// (else it may have jumped to another curve), else h halves; nullopt, the last reason in `why`, once h would
/// fall below `shortest`. `correct(predicted, base, normal, sigma) -> {Point, iterations}` (throws
/// ComputationError, or InputError when a parameter leaves its range), `unknowns(Point)`, `difference(v, w)`
/// (angles mod 2 pi) and `tangent(v, along)` are the curve's own.
template <class Point, class Correct, class Unknowns, class Difference, class Tangent>
std::optional<CurveStep<Point>> stepAlongCurve(const Eigen::VectorXd& u, const Eigen::VectorXd& t, double h,
                                               double shortest, const Correct& correct,
                                               const Unknowns& unknowns, const Difference& difference,
                                               const Tangent& tangent, std::string& why) {
  for (;; h /= 2) {
    try {
      auto [point, iterations] = correct(u + h * t, u, t, h);
      const Eigen::VectorXd v = unknowns(point);
      const double moved = difference(v, u).norm();
      if (moved > 2 * h)
        throw ComputationError(format("the corrector moved %.3g for a step of %.3g", moved, h));
      Eigen::VectorXd next = tangent(v, t);
      if (next.dot(t) < 0.8 && h > shortest)
        throw ComputationError(
            format("the tangent turned by %.0f degrees in one step",
                   std::acos(std::clamp(next.dot(t), -1.0, 1.0)) * 180 / std::numbers::pi));
      return CurveStep<Point>{std::move(point), std::move(next), h, iterations};
    } catch (const ComputationError& e) {
      why = e.what();
    } catch (const InputError& e) {
      why = e.what();
    }
    if (h / 2 < shortest) return std::nullopt;
  }
}

/// The length of the next step: longer (up to `longest`) after a corrector that needed at most 3 iterations,
/// shorter after one that needed 7 or more.
template <class Point> double nextStepLength(const CurveStep<Point>& step, double longest) {
  return step.iterations <= 3 ? std::min(1.5 * step.h, longest) : step.iterations >= 7 ? step.h / 2 : step.h;
}

} // namespace rv
