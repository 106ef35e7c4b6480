// Continuation.h -- a family of fixed points followed in one parameter (manual §2.3.5): natural-parameter
// continuation with the guess extrapolated from the last two points, X_{n+1} = X_n + (X_n - X_{n-1}) d;
// multipliers at every step; a change of type is located by the secant-bisection (Illinois) method on the
// test functions det(DP + I) (a multiplier through -1: period doubling) and det(DP - I) (through +1), or by
// bisection on the type when neither changes sign (Kuznetsov, Elements of Applied Bifurcation Theory (2004)
// §10.2; Allgower & Georg, Introduction to Numerical Continuation Methods (1990) ch. 1).
#pragma once
#include "dynamics/tools/FixedPoint.h"

#include <memory>

namespace rv {

struct ContinuationSettings {
  std::string parameter;    ///< id of the model parameter continued
  double to = 0;            ///< finite value of the parameter
  double step = 0.01;       ///< signed
  double extrapolation = 1; ///< d
  bool stopAtTypeChange = false;
  double bifurcationAccuracy = 1e-10; ///< of the parameter value of a located type change
  /// Accept only points whose minimal order is the family's (an even order): a point that is also a fixed
  /// point of half the order is the parent of a doubled family counted twice, and the step is retried
  /// shorter.
  bool minimalOrder = false;
  FixedPointSettings search;
};

/// A point of the family.
struct ContinuationPoint {
  double parameter = 0;
  FixedPointResult fixedPoint;
};

/// A located change of type between two steps.
struct TypeChange {
  /// How it was located: a multiplier through -1 (period doubling), through +1, or the type alone.
  enum class Kind { MultiplierMinusOne, MultiplierPlusOne, Type };
  double parameter = 0;
  FixedPointType from = FixedPointType::Elliptic, to = FixedPointType::Elliptic;
  Kind kind = Kind::Type;
  ContinuationPoint at; ///< the fixed point at the located value
};
/// "multiplier -1", "multiplier +1", "type".
const char* toString(TypeChange::Kind kind);
/// "type change at K = 1.5: elliptic -> hyperbolic with reflection (multiplier -1)": what the CLI and the GUI
/// report, `parameter` the continued parameter's id.
std::string describe(const TypeChange& change, const std::string& parameter);

/// The test functions prod(lambda_i + 1) and prod(lambda_i - 1) over the multipliers (a 3D map's unit
/// multiplier, when it has one, is left out): they change sign where a multiplier passes -1 or +1.
std::pair<double, double> bifurcationTests(const std::vector<std::complex<double>>& multipliers,
                                           double tolerance);

class Continuation {
public:
  /// The model at a value of the parameter (throws InputError outside its range).
  using ModelAt = std::function<std::unique_ptr<Model>(double value)>;
  /// From the fixed point near `guess` at parameter value `start`, toward settings.to. `section.order` is the
  /// fixed point's order.
  Continuation(ModelAt modelAt, IntegratorFactory makeIntegrator, SectionSettings section, double start,
               Eigen::VectorXd guess, ContinuationSettings settings);

  /// Goes on from where it stopped; true when finished (at the finite value, or at a type change when asked
  /// to stop there), false when stopped on request. Throws ComputationError when a step finds no point.
  bool run(const ToolControl& control, const std::function<void(const ContinuationPoint&)>& onPoint = {},
           const std::function<void(const TypeChange&)>& onChange = {});

  const std::vector<ContinuationPoint>& points() const { return points_; }
  const std::vector<TypeChange>& changes() const { return changes_; }
  const ContinuationSettings& settings() const { return s_; }
  /// The fixed point at parameter value p from a guess (a model is built for p). Throws ComputationError when
  /// none is found, or (settings.minimalOrder) when the point found has half the order.
  FixedPointResult solveAt(double p, const Eigen::VectorXd& guess, const ToolControl& control) const;

private:
  TypeChange locate(const ContinuationPoint& a, const ContinuationPoint& b, const ToolControl& control) const;
  ModelAt modelAt_;
  IntegratorFactory make_;
  SectionSettings section_;
  double start_;
  Eigen::VectorXd guess_;
  ContinuationSettings s_;
  std::unique_ptr<Model> startModel_;
  std::unique_ptr<ReturnMap> shape_; ///< which coordinates are angles, for differences
  std::vector<ContinuationPoint> points_;
  std::vector<TypeChange> changes_;
  std::size_t lastDefinite_ = 0; ///< the last point whose type is not parabolic (between types)
  bool finished_ = false;
};

} // namespace rv
