#include "dynamics/tools/BifurcationTree.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <optional>

namespace rv {

std::vector<double> BifurcationTreeResult::ratios() const {
  std::vector<double> r;
  for (std::size_t k = 2; k < doublings.size(); ++k)
    r.push_back((doublings[k - 1].parameter - doublings[k - 2].parameter) /
                (doublings[k].parameter - doublings[k - 1].parameter));
  return r;
}

BifurcationTreeResult bifurcationTree(
    const Continuation::ModelAt& modelAt, const IntegratorFactory& make, const SectionSettings& section,
    double start, const Eigen::VectorXd& guess, const BifurcationTreeSettings& s, const ToolControl& control,
    const std::function<void(const TreeBranch&, const ContinuationPoint&)>& onPoint,
    const std::function<void(const PeriodDoubling&)>& onDoubling, BifurcationTreeResult* partial) {
  if (!(s.coefficient > 1)) throw InputError("bifurcation tree: the coefficient must exceed 1");
  if (!(s.regionSize > 0) || !(s.bifurcationAccuracy > 0))
    throw InputError("bifurcation tree: the region size and the accuracy must be positive");
  BifurcationTreeResult local;
  BifurcationTreeResult& result = partial ? *partial : local;
  ContinuationSettings cs = s.continuation;
  cs.stopAtTypeChange = true;
  cs.method = ContinuationMethod::Natural; // each family up to its doubling: the parameter goes one way
  cs.switchAt = 0;                         // the tree switches by itself
  cs.bifurcationAccuracy = s.bifurcationAccuracy;
  SectionSettings sec = section;
  double p0 = start, region = s.regionSize;
  Eigen::VectorXd x0 = guess;
  for (int level = 0; level <= s.maxLevels; ++level) {
    Continuation c(modelAt, make, sec, p0, x0, cs);
    result.branches.push_back(TreeBranch{.level = level, .order = sec.order});
    const auto addPoint = [&](const ContinuationPoint& p) {
      TreeBranch& b = result.branches.back();
      if (level == 0 && b.points.empty() && p.fixedPoint.type != FixedPointType::Elliptic)
        throw ComputationError(std::string("bifurcation tree: the initial point is ") +
                               toString(p.fixedPoint.type) +
                               ", not elliptic; start the tree from an elliptic point");
      b.points.push_back(p);
      if (onPoint) onPoint(b, p);
    };
    // past the first doubling a family that cannot be followed (Map^n of a long orbit no longer computable
    // in double precision, a step that finds no point) ends the tree: what was found stands
    try {
      if (!c.run(control, addPoint)) throw Stopped{};
    } catch (const ComputationError& e) {
      if (level == 0) throw;
      result.end = format("the order-%d family could not be followed: %s", sec.order, e.what());
      break;
    }
    if (c.changes().empty()) {
      result.end = format("the finite value %s = %.12g is reached", cs.parameter.c_str(), cs.to);
      break;
    }
    const TypeChange& t = c.changes().back();
    if (t.kind != TypeChange::Kind::MultiplierMinusOne) { // e.g. a saddle-node: nothing doubles
      result.end = format("the order-%d family changes type at %s = %.12g without doubling (%s -> %s)",
                          sec.order, cs.parameter.c_str(), t.parameter, toString(t.from), toString(t.to));
      break;
    }
    const PeriodDoubling d{level, sec.order, t.parameter, t.at.fixedPoint.point};
    result.doublings.push_back(d);
    if (onDoubling) onDoubling(d);
    if (level == s.maxLevels) {
      result.end = format("%d doublings followed (bifurcation_tree.levels)", s.maxLevels + 1);
      break;
    }
    // the next value lies about (last gap) / coefficient further on: it must stand out of the rounding of
    // the parameter and of the accuracy the next level would ask for
    const double rounding =
        64 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t.parameter));
    const double nextAccuracy = std::max(cs.bifurcationAccuracy / s.coefficient, rounding);
    if (result.doublings.size() >= 2) {
      const double gap = std::abs(d.parameter - result.doublings[result.doublings.size() - 2].parameter);
      if (gap / s.coefficient < 100 * nextAccuracy) {
        result.end = format("the next bifurcation value (about %.3g past %.12g) could not be told apart in "
                            "double precision",
                            gap / s.coefficient, d.parameter);
        break;
      }
    }
    // the doubled points, a little past the bifurcation, along the eigenvector of the -1 multiplier
    const double p1 = t.parameter + cs.step / s.coefficient;
    if ((cs.to - p1) * cs.step <= 0) {
      result.end = format("the finite value %s = %.12g is reached", cs.parameter.c_str(), cs.to);
      break;
    }
    SectionSettings doubled = sec;
    doubled.order = 2 * sec.order;
    ContinuationSettings next = cs;
    next.minimalOrder = true;
    next.step /= s.coefficient;
    next.bifurcationAccuracy = nextAccuracy;
    const Continuation probe(modelAt, make, doubled, p1, t.at.fixedPoint.point, next);
    const Eigen::VectorXd v = flipDirection(t.at.fixedPoint.jacobian);
    std::optional<FixedPointResult> found;
    for (double f : {1.0, -1.0, 2.0, 0.5, 4.0, 0.25}) {
      try {
        found = probe.solveAt(p1, t.at.fixedPoint.point + f * region * v, control);
        break;
      } catch (const ComputationError&) {
      }
    }
    if (!found) {
      result.end =
          format("no point of order %d found near the period doubling at %s = %.12g within %g of the "
                 "point",
                 doubled.order, cs.parameter.c_str(), t.parameter, 4 * region);
      break;
    }
    sec = doubled;
    p0 = p1;
    x0 = found->point;
    cs = next;
    region /= s.coefficient;
  }
  return result;
}

} // namespace rv
