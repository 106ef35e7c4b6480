// Continuation.h -- a family of fixed points followed in one parameter (manual §2.3.5), by one of two
// methods:
//  - natural: the parameter stepped, the guess extrapolated from the last two points,
//    X_{n+1} = X_n + (X_n - X_{n-1}) d (the manual's method; it stops where the family turns back);
//  - arclength: pseudo-arclength continuation, the parameter one of the unknowns u = (x, p): a tangent
//    predictor u + h t, a Newton corrector on the bordered system [F(u) = 0, t . (u - u_pred) = 0], the step
//    h shortened when the corrector labours or fails and grown back when it is easy (Keller, Numerical
//    solution of bifurcation and nonlinear eigenvalue problems (1977); Allgower & Georg, Introduction to
//    Numerical Continuation Methods (1990) ch. 2). It passes folds, where the tangent's parameter component
//    changes sign.
// Multipliers at every point; a change of type, or a fold, is located by the secant-bisection (Illinois)
// method on the test functions det(DP + I) (a multiplier through -1: period doubling), det(DP - I) (through
// +1: a fold) and prod_{i<j} (m_i m_j - 1) (a complex pair through the unit circle: Neimark-Sacker), along
// the parameter (natural) or along the arc (arclength), or by bisection on the type when none changes sign
// (Kuznetsov, Elements of Applied Bifurcation Theory (2004) §10.2; Allgower & Georg (1990) ch. 1, 8).
#pragma once
#include "dynamics/tools/FixedPoint.h"

#include <memory>

namespace rv {

/// How the family is followed (see the file's header).
enum class ContinuationMethod { Natural, Arclength };

struct ContinuationSettings {
  std::string parameter; ///< id of the model parameter continued
  double to = 0;         ///< finite value of the parameter
  /// Signed. Natural: the parameter's step. Arclength: the longest step along the family in (x, p), its sign
  /// the parameter's initial direction.
  double step = 0.01;
  ContinuationMethod method = ContinuationMethod::Natural;
  long maxPoints = 10000; ///< the family ends after this many points (a closed family never ends otherwise)
  /// Branch switching: 0 follows the family itself; k >= 1 follows, once it ends, the family of doubled order
  /// born at its k-th located period doubling instead (its points are the ones reported; see doubledFamily),
  /// the first point `switchDistance` from the doubling along the flip direction.
  int switchAt = 0;
  double switchDistance = 0.05;
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
  /// How it was located: a multiplier through -1 (period doubling), through +1 (the family goes on), a fold
  /// (a multiplier through +1 where the family turns back in the parameter: arclength only), a complex pair
  /// through the unit circle (Neimark-Sacker), or the type alone.
  enum class Kind { MultiplierMinusOne, MultiplierPlusOne, Fold, NeimarkSacker, Type };
  double parameter = 0;
  FixedPointType from = FixedPointType::Elliptic, to = FixedPointType::Elliptic;
  Kind kind = Kind::Type;
  ContinuationPoint at; ///< the fixed point at the located value
};
/// "multiplier -1", "multiplier +1", "fold", "Neimark-Sacker", "type".
const char* toString(TypeChange::Kind kind);
/// "type change at K = 1.5: elliptic -> hyperbolic with reflection (multiplier -1)": what the CLI and the GUI
/// report, `parameter` the continued parameter's id.
std::string describe(const TypeChange& change, const std::string& parameter);

/// The test functions prod(lambda_i + 1) and prod(lambda_i - 1) over the multipliers (a 3D map's unit
/// multiplier, when it has one, is left out): they change sign where a multiplier passes -1 or +1.
std::pair<double, double> bifurcationTests(const std::vector<std::complex<double>>& multipliers,
                                           double tolerance);
/// The test function prod_{i<j} (lambda_i lambda_j - 1) (the same multiplier left out): it changes sign where
/// a complex pair crosses the unit circle (and where two real multipliers pass a product of 1).
double neimarkSackerTest(const std::vector<std::complex<double>>& multipliers, double tolerance);

/// The real unit eigenvector of the multiplier nearest -1 of a fixed point's derivative: the direction in
/// which the points of doubled order leave it at a period doubling.
Eigen::VectorXd flipDirection(const Eigen::MatrixXd& jacobian);

class Continuation {
public:
  /// The model at a value of the parameter (throws InputError outside its range).
  using ModelAt = std::function<std::unique_ptr<Model>(double value)>;
  /// From the fixed point near `guess` at parameter value `start`, toward settings.to. `section.order` is the
  /// fixed point's order.
  Continuation(ModelAt modelAt, IntegratorFactory makeIntegrator, SectionSettings section, double start,
               Eigen::VectorXd guess, ContinuationSettings settings);

  /// Goes on from where it stopped; true when finished (at the finite value, at a type change when asked
  /// to stop there, or -- arclength -- where the family turns back past the start or after maxPoints; end()
  /// says which), false when stopped on request. Throws ComputationError when a step finds no point.
  bool run(const ToolControl& control, const std::function<void(const ContinuationPoint&)>& onPoint = {},
           const std::function<void(const TypeChange&)>& onChange = {});

  const std::vector<ContinuationPoint>& points() const { return points_; }
  /// The family of doubled order it switched to (settings.switchAt), once it has; nullptr before.
  const Continuation* doubled() const { return doubled_.get(); }
  const std::vector<TypeChange>& changes() const { return changes_; }
  const ContinuationSettings& settings() const { return s_; }
  /// Branch switching: the family of order 2n born at `doubling`, a located period doubling of this family.
  /// Its first point is found at `distance` from the doubling's point along flipDirection, the parameter free
  /// (so super- and subcritical doublings alike: Kuznetsov 2004, §10.3.3); it is then continued with
  /// `settings` (method, step, accuracy) to the end of this family's window [start, finite value] on the side
  /// where it lives; natural continuation accepts only points of minimal order 2n. ComputationError when no
  /// such point is found (nor at 2, 4 times or a half, a quarter of the distance).
  std::unique_ptr<Continuation> doubledFamily(const TypeChange& doubling, double distance,
                                              ContinuationSettings settings,
                                              const ToolControl& control) const;
  /// Why the family ended ("reached a = 2", "turned back past the start value ...", ...); empty while
  /// running.
  const std::string& end() const { return end_; }
  /// The fixed point at parameter value p from a guess (a model is built for p). Throws ComputationError when
  /// none is found, or (settings.minimalOrder) when the point found has half the order.
  FixedPointResult solveAt(double p, const Eigen::VectorXd& guess, const ToolControl& control) const;

private:
  /// A point on the arc: the unknowns u = (x.head(k), p), the unit tangent there.
  struct ArcPoint {
    Eigen::VectorXd u, tangent;
  };
  /// Where a step went and what the corrector spent.
  struct Corrected {
    ContinuationPoint point;
    int iterations = 0;
  };
  int unknowns() const; ///< k: the map's dimension, or 2 in the 2D-section mode
  Eigen::VectorXd unknownsOf(const ContinuationPoint& c) const;
  Eigen::VectorXd
  pointOf(const Eigen::VectorXd& u) const; ///< the map point of u (z of the start: 2D section)
  Eigen::VectorXd arcDifference(const Eigen::VectorXd& u,
                                const Eigen::VectorXd& v) const; ///< angles mod 2 pi
  /// F(u) = Map^n(x) - x (k rows) and its derivative [DP - I | dF/dp], dF/dp by central differences.
  std::pair<Eigen::VectorXd, Eigen::MatrixXd> residual(const Eigen::VectorXd& u,
                                                       const ToolControl& control) const;
  /// The unit null vector of dF at u, oriented along `along`.
  Eigen::VectorXd tangentAt(const Eigen::VectorXd& u, const Eigen::VectorXd& along,
                            const ToolControl& control) const;
  /// Newton on [F(u) = 0, normal . (u - base) = sigma] from `predicted`, at most `iterations` steps; the
  /// point found, with its multipliers.
  Corrected correct(Eigen::VectorXd predicted, const Eigen::VectorXd& base, const Eigen::VectorXd& normal,
                    double sigma, int iterations, const ToolControl& control) const;
  /// Why the family cannot be followed past the last point, with the evidence: whether a multiplier is near
  /// +1 (a fold), how steeply the family turns away from the parameter, and whether the map's points stop
  /// completing into states (the edge of the region of allowed motion) or complete ever faster (a singular
  /// point of the section's coordinates).
  std::string whyItEnds(const ToolControl& control) const;
  /// The family itself, up to its end (run() without the switch).
  bool runFamily(const ToolControl& control, const std::function<void(const ContinuationPoint&)>& onPoint,
                 const std::function<void(const TypeChange&)>& onChange);
  /// One arclength step from the last point; false when the family ended (end_ says why).
  bool arclengthStep(const ToolControl& control);
  /// Locates the change between consecutive points a and b (indices into points_).
  TypeChange locate(std::size_t a, std::size_t b, bool fold, const ToolControl& control) const;
  /// Whether a change (or a fold) lies between the last definite point and the newest; records and reports
  /// it.
  bool noteChanges(const std::function<void(const TypeChange&)>& onChange, const ToolControl& control);
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
  std::vector<ArcPoint> arc_;             ///< arclength: parallel to points_
  std::unique_ptr<Continuation> doubled_; ///< settings.switchAt: the family switched to
  double arcStep_ = 0;                    ///< arclength: the current step
  std::size_t lastDefinite_ = 0;          ///< the last point whose type is not parabolic (between types)
  bool finished_ = false, firstReported_ = false;
  std::string end_;
  double progress_ = 0;
};

} // namespace rv
