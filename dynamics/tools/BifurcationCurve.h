// BifurcationCurve.h -- the curve of a codimension-one bifurcation of a fixed point of order n (a fold, a
// period doubling, a Neimark-Sacker point) in the plane of two parameters (p, q): the defining system
//   F(x; p, q) = Map^n(x) - x = 0,   psi(x; p, q) = 0,
// psi the test function of the bifurcation on the multipliers m_i (eigenvalues of D Map^n): prod (m_i - 1)
// for a fold, prod (m_i + 1) for a period doubling, prod_{i<j} (m_i m_j - 1) for a Neimark-Sacker point
// (Kuznetsov, Elements of Applied Bifurcation Theory (2004) §10.2-10.3; Govaerts, Numerical Methods for
// Bifurcations of Dynamical Equilibria (2000) ch. 4), followed by pseudo-arclength continuation in the
// unknowns (x, p, q): a tangent predictor and a Newton corrector on the bordered system (Allgower & Georg,
// Introduction to Numerical Continuation Methods (1990) ch. 2). The derivatives of F in x are the map's
// (ReturnMap::linearize); those in p, q and all of psi's are central differences.
//
// Along the curve the remaining multipliers are watched for the codimension-two points where the curve
// meets another: another multiplier through -1 or +1 (a fold meets a period-doubling curve, ...), and on a
// Neimark-Sacker curve the strong resonances 1:1 ... 1:4 (Kuznetsov 2004, §9.5); each is located along the
// curve by the Illinois method.
#pragma once
#include "dynamics/tools/FixedPoint.h"

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace rv {

/// Which bifurcation a curve follows.
enum class CurveKind { Fold, PeriodDoubling, NeimarkSacker };
/// "fold", "period doubling", "Neimark-Sacker".
const char* toString(CurveKind kind);

struct BifurcationCurveSettings {
  CurveKind kind = CurveKind::Fold;
  std::string first, second; ///< the parameters: p (the one the bifurcation was found in) and q
  double step = 0.02;        ///< the longest step along the curve in (x, p, q)
  long maxPoints = 2000;     ///< each way from the start
  /// The box of the (p, q) plane the curve is followed in; it ends on the box's sides.
  double firstMin = -std::numeric_limits<double>::infinity(),
         firstMax = std::numeric_limits<double>::infinity();
  double secondMin = -std::numeric_limits<double>::infinity(),
         secondMax = std::numeric_limits<double>::infinity();
  double eventAccuracy = 1e-10; ///< of a located meeting point, along the curve
  FixedPointSettings search;    ///< accuracy (of F and psi), derivatives, type tolerance
};

/// A point of the curve.
struct CurvePoint {
  double first = 0, second = 0; ///< (p, q)
  FixedPointResult fixedPoint;  ///< the point, its multipliers and type
};

/// A codimension-two point where the curve meets another.
struct CurveEvent {
  std::string what; ///< "meets a period-doubling curve (another multiplier -1)", "1:3 resonance", ...
  CurvePoint at;
};

struct BifurcationCurveResult {
  std::vector<CurvePoint> points; ///< along the curve from one end to the other
  std::vector<CurveEvent> events;
  std::string end; ///< how each way ended: "q = 0.5 reached; p = -1.2 reached", "the curve closes", ...
};

/// The model at values (p, q) of the two parameters; InputError outside their ranges.
using ModelAt2 = std::function<std::unique_ptr<Model>(double first, double second)>;

/// Follows the curve through the point near `point` at (first, second) -- a located bifurcation of that kind
/// (the start is corrected onto the curve at this q) -- both ways until the box, maxPoints, the curve closing
/// or a step that finds no point (what was found stands; `end` says why). Throws ComputationError when the
/// start itself is not on such a curve, InputError for bad settings, Stopped when asked to stop (`partial`
/// holds what was found). `onPoint` sees each point as it is found.
BifurcationCurveResult bifurcationCurve(const ModelAt2& modelAt, const IntegratorFactory& makeIntegrator,
                                        const SectionSettings& section, double first, double second,
                                        const Eigen::VectorXd& point,
                                        const BifurcationCurveSettings& settings,
                                        const ToolControl& control = {},
                                        const std::function<void(const CurvePoint&)>& onPoint = {},
                                        BifurcationCurveResult* partial = nullptr);

} // namespace rv
