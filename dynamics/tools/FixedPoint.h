// FixedPoint.h -- fixed points of order n of a map (manual §2.3.4): zeros of F(x) = Map^n(x) - x by Newton's
// method or by gradient descent on |F|^2 / 2, both with the distance between consecutive points bounded;
// derivatives by finite differences or variational equations (ReturnMap). For 3D maps the "2D section" mode
// searches on the plane z = const (degenerate points of maps with an integral). The result carries the
// multipliers (eigenvalues of D Map^n) and the point's type.
//
// Newton with a bounded step: Dennis & Schnabel, Numerical Methods for Unconstrained Optimization and
// Nonlinear Equations (1983) ch. 6; where D Map^n - I has lost rank (a family of fixed points, as a map with
// integrals has them) the least-norm Gauss-Newton step of an underdetermined system (Deuflhard, Newton
// Methods for Nonlinear Problems (2004) §4.4; Ben-Israel 1966), which ends at the point of the family
// nearest the guess; classification of fixed points of maps: Kuznetsov, Elements of Applied
// Bifurcation Theory (2004) §1.5.
#pragma once
#include "dynamics/tools/ReturnMap.h"

#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace rv {

enum class FixedPointMethod { Newton, Gradient };

struct FixedPointSettings {
  FixedPointMethod method = FixedPointMethod::Newton;
  int maxIterations = 100;
  double accuracy = 1e-10;  ///< |Map^n(x) - x| at the fixed point
  double maxDistance = 0.1; ///< between consecutive points of the search
  bool section2D = false;   ///< 3D maps: search on the plane z = const (z of the guess)
  DerivativeSettings derivatives;
  double typeTolerance = 1e-6; ///< how close to the unit circle (or to +-1) a multiplier counts as on it
  /// Below this fraction of the largest (or below |Map^n(x) - x|, up to a tenth of the largest), a singular
  /// value of D Map^n - I counts as zero: the point lies on a family of fixed points (a map with integrals: a
  /// flow's relative equilibria), and Newton's step is the one of least norm, towards the nearest point of
  /// the family. Derivatives must be better than this (variational ones are; differences seldom).
  double rankTolerance = 1e-8;
};

/// One point of the search path.
struct SearchPoint {
  Eigen::VectorXd point;
  double residual = 0; ///< |Map^n(x) - x|
};

/// The type of a fixed point from its multipliers (Kuznetsov 2004, §1.5). A map that preserves area has
/// elliptic, hyperbolic, hyperbolic with reflection (a multiplier < -1) or parabolic (a multiplier +-1)
/// points; others also nodes and foci; a 3D map's unit multiplier (an integral) is set aside, and the general
/// case is stable, unstable or hyperbolic (saddle).
enum class FixedPointType {
  Elliptic,
  Hyperbolic,
  HyperbolicWithReflection,
  Parabolic,
  StableNode,
  UnstableNode,
  StableFocus,
  UnstableFocus,
  Stable,
  Unstable
};
/// "elliptic", "hyperbolic with reflection", ...: the one spelling the CLI, the GUI and the files use.
const char* toString(FixedPointType type);
/// Hyperbolic, with or without reflection: the points with separatrices.
bool isHyperbolic(FixedPointType type);

struct FixedPointResult {
  Eigen::VectorXd point;
  std::vector<std::complex<double>> multipliers;  ///< eigenvalues of D Map^n at the point
  Eigen::MatrixXd jacobian;                       ///< D Map^n at the point
  FixedPointType type = FixedPointType::Elliptic; ///< see classifyFixedPoint
  double residual = 0;
  /// The dimension of the family of fixed points the point lies on (the rank defect of D Map^n - I, see
  /// FixedPointSettings::rankTolerance); 0 for an isolated point.
  int family = 0;
  int iterations = 0;
  long evaluations = 0; ///< map evaluations spent
  std::vector<SearchPoint> path;
};

/// The type of a fixed point from its multipliers: 2D maps elliptic, hyperbolic, hyperbolic with reflection,
/// parabolic (a multiplier +-1), and for maps that do not preserve area stable / unstable node or focus. 3D
/// maps: a multiplier equal to 1 (an integral) is set aside and the other two classified as above; otherwise
/// elliptic (all on the unit circle), hyperbolic (some inside, some outside), stable or unstable. A point on
/// a `family` of fixed points of that dimension has as many unit multipliers along it: the `family`
/// multipliers nearest 1 are set aside first.
FixedPointType classifyFixedPoint(const std::vector<std::complex<double>>& multipliers, double tolerance,
                                  int family = 0);

/// Eigenvalues of a square matrix, sorted by decreasing modulus (then by imaginary part).
std::vector<std::complex<double>> multipliersOf(const Eigen::MatrixXd& jacobian);

/// A point already solved for (by a corrector that has the parameters among its unknowns): its image, the
/// multipliers and type at x as it is -- no Newton step, which at a fold would slide x along the direction
/// where Map^n(x) - x is flat.
FixedPointResult fixedPointAt(const ReturnMap& map, const Eigen::VectorXd& x,
                              const FixedPointSettings& settings, const ToolControl& control = {});

/// Searches a fixed point of `map` from `guess`. `onPoint` sees every point of the search path. Throws
/// ComputationError when the search does not converge in maxIterations (or leaves the region of allowed
/// motion), InputError for inconsistent settings, Stopped when asked to stop.
FixedPointResult findFixedPoint(const ReturnMap& map, const Eigen::VectorXd& guess,
                                const FixedPointSettings& settings, const ToolControl& control = {},
                                const std::function<void(const SearchPoint&)>& onPoint = {});

} // namespace rv
