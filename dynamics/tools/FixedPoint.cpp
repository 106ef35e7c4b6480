#include "dynamics/tools/FixedPoint.h"

#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace rv {

std::vector<std::complex<double>> multipliersOf(const Eigen::MatrixXd& jacobian) {
  Eigen::EigenSolver<Eigen::MatrixXd> es(jacobian, false);
  std::vector<std::complex<double>> m(es.eigenvalues().data(), es.eigenvalues().data() + jacobian.rows());
  std::sort(m.begin(), m.end(), [](auto a, auto b) {
    return std::abs(a) != std::abs(b) ? std::abs(a) > std::abs(b) : a.imag() > b.imag();
  });
  return m;
}

const char* toString(FixedPointType type) {
  switch (type) {
  case FixedPointType::Elliptic:
    return "elliptic";
  case FixedPointType::Hyperbolic:
    return "hyperbolic";
  case FixedPointType::HyperbolicWithReflection:
    return "hyperbolic with reflection";
  case FixedPointType::Parabolic:
    return "parabolic";
  case FixedPointType::StableNode:
    return "stable node";
  case FixedPointType::UnstableNode:
    return "unstable node";
  case FixedPointType::StableFocus:
    return "stable focus";
  case FixedPointType::UnstableFocus:
    return "unstable focus";
  case FixedPointType::Stable:
    return "stable";
  case FixedPointType::Unstable:
    return "unstable";
  }
  return "unknown";
}

bool isHyperbolic(FixedPointType type) {
  return type == FixedPointType::Hyperbolic || type == FixedPointType::HyperbolicWithReflection;
}

namespace {

using T = FixedPointType;

T classifyPair(std::complex<double> a, std::complex<double> b, double tol) {
  const bool complexPair = std::abs(a.imag()) > tol;
  if (complexPair) {
    const double r = std::abs(a);
    if (std::abs(r - 1) <= tol) return T::Elliptic;
    return r < 1 ? T::StableFocus : T::UnstableFocus;
  }
  const double x = a.real(), y = b.real();
  if (std::abs(std::abs(x) - 1) <= tol || std::abs(std::abs(y) - 1) <= tol) return T::Parabolic;
  const double big = std::abs(x) > std::abs(y) ? x : y, small = std::abs(x) > std::abs(y) ? y : x;
  if (std::abs(big) > 1 && std::abs(small) < 1) return big < 0 ? T::HyperbolicWithReflection : T::Hyperbolic;
  return std::abs(big) < 1 ? T::StableNode : T::UnstableNode;
}

/// The step of Newton's method for F(x) = 0 with the derivative A: A^-1 F where A is regular; where it has
/// lost rank, the least-squares step of least norm A^+ F with A's smaller singular values taken as zero --
/// the Gauss-Newton step of an underdetermined system, which converges quadratically to the point of a
/// family of solutions nearest the guess (Deuflhard, Newton Methods for Nonlinear Problems (2004) §4.4;
/// Ben-Israel, J. Math. Anal. Appl. 15 (1966) 243-252), where the inverse would step along the family as far
/// as the rounding dictates. A singular value counts as zero below `tolerance` times the largest, or below
/// the residual |F|: a map that keeps integrals C has dC (D Map - I) = dC(x) - dC(Map(x)) = O(|F|), so off
/// its family of fixed points the matrix is singular but for O(|F|), which is also the size of the linear
/// model's own error there; at a regular point those singular values stay finite while |F| -> 0, so the
/// steps become Newton's. A singular value above a tenth of the largest always counts (far from any fixed
/// point, where |F| exceeds them all, the step stays Newton's).
class NewtonStep {
public:
  static constexpr double kResolved = 0.1;
  NewtonStep(const Eigen::MatrixXd& A, double tolerance, double residual)
      : svd_(A, Eigen::ComputeThinU | Eigen::ComputeThinV) {
    const double largest = svd_.singularValues().size() ? svd_.singularValues()[0] : 0.0;
    svd_.setThreshold(largest > 0 ? std::max(tolerance, std::min(residual / largest, kResolved)) : tolerance);
    if (svd_.rank() == A.cols()) lu_.compute(A);
  }
  int rank() const { return static_cast<int>(svd_.rank()); }
  Eigen::VectorXd solve(const Eigen::VectorXd& F) const {
    return rank() == svd_.cols() ? Eigen::VectorXd(lu_.solve(F)) : Eigen::VectorXd(svd_.solve(F));
  }

private:
  Eigen::JacobiSVD<Eigen::MatrixXd> svd_;
  Eigen::FullPivLU<Eigen::MatrixXd> lu_;
};

} // namespace

FixedPointType classifyFixedPoint(const std::vector<std::complex<double>>& multipliers, double tol,
                                  int family) {
  std::vector<std::complex<double>> m = multipliers;
  // along a family of fixed points the map is the identity: its unit multipliers say nothing of the type
  for (int k = 0; k < family && m.size() > 1; ++k)
    m.erase(std::min_element(m.begin(), m.end(),
                             [](auto a, auto b) { return std::abs(a - 1.0) < std::abs(b - 1.0); }));
  if (m.size() == 1) {
    const double r = std::abs(m[0]);
    return std::abs(r - 1) <= tol ? T::Parabolic : r < 1 ? T::Stable : T::Unstable;
  }
  if (m.size() == 2) return classifyPair(m[0], m[1], tol);
  if (m.size() == 3) {
    // a unit multiplier (an integral, or the direction along a family) is set aside
    for (int i = 0; i < 3; ++i)
      if (std::abs(m[i] - 1.0) <= tol) {
        std::vector<std::complex<double>> rest;
        for (int j = 0; j < 3; ++j)
          if (j != i) rest.push_back(m[j]);
        return classifyPair(rest[0], rest[1], tol);
      }
  }
  int inside = 0, outside = 0;
  for (auto z : m) {
    const double r = std::abs(z);
    if (r < 1 - tol) ++inside;
    if (r > 1 + tol) ++outside;
  }
  if (inside && outside) return T::Hyperbolic;
  if (inside) return T::Stable;
  if (outside) return T::Unstable;
  return T::Elliptic;
}

FixedPointResult fixedPointAt(const ReturnMap& map, const Eigen::VectorXd& x, const FixedPointSettings& s,
                              const ToolControl& control) {
  const long evaluationsBefore = map.evaluations();
  const Linearization lin = map.linearize(x, s.derivatives, control);
  FixedPointResult r;
  r.point = map.alignTo(x, lin.image);
  r.residual = map.difference(lin.image, x).norm();
  r.jacobian = lin.jacobian;
  r.multipliers = multipliersOf(r.jacobian);
  r.type = classifyFixedPoint(r.multipliers, s.typeTolerance);
  r.evaluations = map.evaluations() - evaluationsBefore;
  r.path.push_back({x, r.residual});
  return r;
}

FixedPointResult findFixedPoint(const ReturnMap& map, const Eigen::VectorXd& guess,
                                const FixedPointSettings& s, const ToolControl& control,
                                const std::function<void(const SearchPoint&)>& onPoint) {
  const int d = map.dimension();
  if (guess.size() != d)
    throw InputError(format("--guess: the map of %s has %d coordinates, the guess has %d",
                            map.model().info().id.c_str(), d, static_cast<int>(guess.size())));
  if (s.maxIterations < 1)
    throw InputError("fixed point: the maximal number of iterations must be at least 1");
  if (!(s.accuracy > 0) || !(s.maxDistance > 0))
    throw InputError("fixed point: the accuracy and the maximal distance must be positive");
  if (s.section2D && d != 3) throw InputError("fixed point: the 2D section mode needs a 3D map");
  const int k = s.section2D ? 2 : d; // the unknowns: all coordinates, or x and y at fixed z
  const long evaluationsBefore = map.evaluations();

  FixedPointResult r;
  Eigen::VectorXd x = guess;
  const auto record = [&](const Eigen::VectorXd& p, double residual) {
    r.path.push_back({p, residual});
    if (onPoint) onPoint(r.path.back());
  };
  const auto residualAt = [&](const Eigen::VectorXd& p) {
    return map.difference(map(p, control), p).head(k).norm();
  };
  for (int it = 0;; ++it) {
    const Linearization lin = map.linearize(x, s.derivatives, control);
    const Eigen::VectorXd F = map.difference(lin.image, x).head(k);
    const Eigen::MatrixXd A = lin.jacobian.topLeftCorner(k, k) - Eigen::MatrixXd::Identity(k, k);
    double residual = F.norm();
    record(x, residual);
    const NewtonStep newton(A, s.rankTolerance, residual);
    if (residual <= s.accuracy) {
      // converged: up to two more Newton steps, kept only while they reduce the residual
      for (int polish = 0; polish < 2 && s.method == FixedPointMethod::Newton && newton.rank() > 0;
           ++polish) {
        Eigen::VectorXd y = x;
        y.head(k) -= newton.solve(map.difference(map(x, control), x).head(k));
        const double ry = residualAt(y);
        if (!(ry < residual)) break;
        x = y, residual = ry;
        record(x, residual);
      }
      // angles in the range the map itself gives them (l in (-pi, pi], theta in [0, 2 pi), ...)
      r.point = map.alignTo(x, lin.image);
      r.residual = residual;
      r.iterations = it;
      r.jacobian = lin.jacobian;
      r.family = k - newton.rank();
      break;
    }
    if (it >= s.maxIterations)
      throw ComputationError(format("fixed point: no convergence in %d iterations (|Map^%d(x) - x| = %.3g, "
                                    "accuracy %.3g)",
                                    s.maxIterations, map.order(), residual, s.accuracy));
    Eigen::VectorXd dx;
    if (s.method == FixedPointMethod::Newton) {
      if (newton.rank() == 0)
        throw ComputationError("fixed point: D Map^n - I vanishes (Map^n is the identity to first order "
                               "here); try the gradient method");
      dx = -newton.solve(F);
    } else {
      // steepest descent on |F|^2 / 2, the step where its linear model vanishes, halved until it decreases
      const Eigen::VectorXd g = A.transpose() * F;
      if (g.norm() == 0) throw ComputationError("fixed point: the gradient of |Map^n(x) - x| vanishes");
      dx = -(0.5 * residual * residual / g.squaredNorm()) * g;
    }
    if (dx.norm() > s.maxDistance) dx *= s.maxDistance / dx.norm();
    if (s.method == FixedPointMethod::Gradient) {
      for (int halving = 0;; ++halving) {
        Eigen::VectorXd y = x;
        y.head(k) += dx;
        double ry = std::numeric_limits<double>::infinity();
        try {
          ry = residualAt(y);
        } catch (const ComputationError&) {
        }
        if (ry < residual || halving == 40) break;
        dx /= 2;
      }
    }
    x.head(k) += dx;
  }
  r.multipliers = multipliersOf(r.jacobian);
  r.type = classifyFixedPoint(r.multipliers, s.typeTolerance, r.family);
  r.evaluations = map.evaluations() - evaluationsBefore;
  return r;
}

} // namespace rv
