#include "dynamics/tools/ToolSettings.h"

namespace rv {

// Each table's defaults are read from a default-constructed settings struct: one declaration of each default.

const ParameterTable& fixedPointTable() {
  const FixedPointSettings d;
  static const ParameterTable t{
      {.id = "order",
       .label = "Order of FP",
       .defaultValue = 1,
       .min = 1,
       .max = 1e6,
       .description = "order n of the fixed point: a zero of Map^n(x) - x",
       .integer = true},
      {.id = "method",
       .label = "Method of FP finding",
       .defaultValue = d.method == FixedPointMethod::Newton ? 0.0 : 1.0,
       .min = 0,
       .max = 1,
       .description = "newton or gradient (descent on |Map^n(x) - x|^2)",
       .integer = true,
       .choices = {"newton", "gradient"}},
      {.id = "max_iterations",
       .label = "Max. number of iterations",
       .defaultValue = static_cast<double>(d.maxIterations),
       .min = 1,
       .max = 1e7,
       .description = "the search stops with a message after this many iterations",
       .integer = true},
      {.id = "accuracy",
       .label = "Accuracy of FP location",
       .defaultValue = d.accuracy,
       .min = 1e-300,
       .max = 1,
       .description = "the largest |Map^n(x) - x| accepted at the fixed point"},
      {.id = "max_distance",
       .label = "Max. distance between points",
       .defaultValue = d.maxDistance,
       .min = 1e-300,
       .max = 1e300,
       .description = "bound on the distance between consecutive points of the search"},
      {.id = "derivatives",
       .label = "Derivatives",
       .defaultValue = d.derivatives.method == DerivativeMethod::Variational ? 0.0 : 1.0,
       .min = 0,
       .max = 1,
       .description = "variational (along the orbit, with the section correction) or differences (numerical, "
                      "with the three controls below)",
       .integer = true,
       .choices = {"variational", "differences"}},
      {.id = "linear_region",
       .label = "Linear approximation region",
       .defaultValue = d.derivatives.linearRegion,
       .min = 1e-300,
       .max = 1,
       .description = "initial step of numerical differentiation"},
      {.id = "derivative_accuracy",
       .label = "Accuracy of derivatives finding",
       .defaultValue = d.derivatives.accuracy,
       .min = 1e-300,
       .max = 1,
       .description = "allowed |Map(x + dx) - Lin(x + dx)| at |dx| = the step"},
      {.id = "zero",
       .label = "Value of \"zero\"",
       .defaultValue = d.derivatives.zero,
       .min = 1e-300,
       .max = 1,
       .description = "the differentiation step may not shrink below this"},
      {.id = "section",
       .label = "Section",
       .defaultValue = d.section2D ? 0.0 : 1.0,
       .min = 0,
       .max = 1,
       .description = "3D maps: 2D searches on the plane z = const (degenerate points), 3D in space",
       .integer = true,
       .choices = {"2D", "3D"}},
      {.id = "type_tolerance",
       .label = "Type tolerance",
       .defaultValue = d.typeTolerance,
       .min = 0,
       .max = 1,
       .description = "how close to the unit circle (or to +-1) a multiplier counts as on it"},
      {.id = "path",
       .label = "Show all points",
       .defaultValue = 0,
       .min = 0,
       .max = 1,
       .description = "the result gives the whole search path (the map window always draws it)",
       .integer = true,
       .choices = {"no", "yes"}},
  };
  return t;
}

const ParameterTable& continuationTable() {
  const ContinuationSettings d;
  static const ParameterTable t{
      {.id = "method",
       .label = "Method",
       .defaultValue = static_cast<double>(d.method),
       .min = 0,
       .max = 1,
       .description = "natural: the parameter stepped (the manual's; stops where the family turns back); "
                      "arclength: pseudo-arclength, the parameter one of the unknowns (passes folds)",
       .integer = true,
       .choices = {"natural", "arclength"}},
      {.id = "step",
       .label = "Step",
       .defaultValue = d.step,
       .description = "signed step of the parameter (arclength: the longest step along the family, its sign "
                      "the parameter's first direction)"},
      {.id = "points",
       .label = "Maximal number of points",
       .defaultValue = static_cast<double>(d.maxPoints),
       .min = 2,
       .max = 1e7,
       .description = "arclength: the family ends after this many points (a closed family would not end)",
       .integer = true},
      {.id = "extrapolation",
       .label = "Extrapolation factor",
       .defaultValue = d.extrapolation,
       .min = -10,
       .max = 10,
       .description = "d in X_{n+1} = X_n + (X_n - X_{n-1}) d for the next guess"},
      {.id = "stop_at_type_change",
       .label = "Stop at FP type change",
       .defaultValue = d.stopAtTypeChange ? 1.0 : 0.0,
       .min = 0,
       .max = 1,
       .description = "stop the continuation where the type of the point changes",
       .integer = true,
       .choices = {"no", "yes"}},
      {.id = "switch",
       .label = "Switch at doubling",
       .defaultValue = static_cast<double>(d.switchAt),
       .min = 0,
       .max = 1000,
       .description = "0: the family itself; k: the family of doubled order born at its k-th period doubling "
                      "(branch switching), continued to the end of [start, to] on its side",
       .integer = true},
      {.id = "switch_distance",
       .label = "Switch distance",
       .defaultValue = d.switchDistance,
       .min = 1e-300,
       .max = 1e300,
       .description = "how far from the doubling the first point of doubled order is sought, along the flip "
                      "direction"},
      {.id = "bifurcation_accuracy",
       .label = "Accuracy of bifurcation value",
       .defaultValue = d.bifurcationAccuracy,
       .min = 1e-300,
       .max = 1,
       .description = "of the parameter value where the type changes"},
  };
  return t;
}

const ParameterTable& separatrixTable() {
  const SeparatrixSettings d;
  static const ParameterTable t{
      {.id = "branch",
       .label = "Separatrix number",
       .defaultValue = static_cast<double>(d.branch),
       .min = 1,
       .max = 4,
       .description = "1, 2: first multiplier (+v, -v); 3, 4: second (incoming when |multiplier| < 1)",
       .integer = true},
      {.id = "linear_region",
       .label = "Linear approximation region",
       .defaultValue = d.linearRegion,
       .min = 1e-300,
       .max = 1,
       .description = "length of the initial linear segment (halved until accurate)"},
      {.id = "linear_accuracy",
       .label = "Linear approximation accuracy",
       .defaultValue = d.linearAccuracy,
       .min = 1e-300,
       .max = 3.2,
       .description = "allowed angle (radians) between the eigenvector v and Map(v)"},
      {.id = "max_distance",
       .label = "Max. distance between points",
       .defaultValue = d.maxDistance,
       .min = 1e-300,
       .max = 1e300,
       .description = "between neighbouring points of the separatrix"},
      {.id = "max_angle",
       .label = "Max. angle of one iteration",
       .defaultValue = d.maxAngle,
       .min = 1e-300,
       .max = 3.2,
       .description = "largest turn (radians) between consecutive segments"},
      {.id = "min_angle_distance",
       .label = "Min. distance for angle control",
       .defaultValue = d.minAngleDistance,
       .min = 0,
       .max = 1e300,
       .description = "shorter segments are not refined for their angle"},
      {.id = "iterations",
       .label = "Iterations",
       .defaultValue = static_cast<double>(d.maxIterations),
       .min = 1,
       .max = 1e6,
       .description = "images of the fundamental segment",
       .integer = true},
      {.id = "points",
       .label = "Max. points",
       .defaultValue = static_cast<double>(d.maxPoints),
       .min = 2,
       .max = 1e9,
       .description = "the branch stops growing at this many points",
       .integer = true},
  };
  return t;
}

const ParameterTable& bifurcationTreeTable() {
  const BifurcationTreeSettings d;
  static const ParameterTable t{
      {.id = "accuracy",
       .label = "Accuracy of bifurcation value",
       .defaultValue = d.bifurcationAccuracy,
       .min = 1e-300,
       .max = 1,
       .description = "initial accuracy of the bifurcation value"},
      {.id = "region",
       .label = "Initial size of bifurcation region",
       .defaultValue = d.regionSize,
       .min = 1e-300,
       .max = 1e300,
       .description = "distance from the point to the first guess of doubled period"},
      {.id = "coefficient",
       .label = "Coefficient of decreasing of the step",
       .defaultValue = d.coefficient,
       .min = 1.000001,
       .max = 1e6,
       .description = "step, accuracy and region shrink by it at each doubling (Feigenbaum's constant)"},
      {.id = "levels",
       .label = "Levels",
       .defaultValue = static_cast<double>(d.maxLevels),
       .min = 0,
       .max = 30,
       .description = "period doublings followed at most",
       .integer = true},
  };
  return t;
}

const ParameterTable& bifurcationCurveTable() {
  const BifurcationCurveSettings d;
  constexpr double none = 1e300; // an open side of the box
  static const ParameterTable t{
      {.id = "kind",
       .label = "Bifurcation",
       .defaultValue = static_cast<double>(d.kind),
       .min = 0,
       .max = 2,
       .description =
           "the curve followed: where a multiplier is +1 (fold), -1 (period doubling) or a complex pair "
           "is on the unit circle (Neimark-Sacker); the start is the first such point of the "
           "continuation",
       .integer = true,
       .choices = {"fold", "period_doubling", "neimark_sacker"}},
      {.id = "step",
       .label = "Step",
       .defaultValue = d.step,
       .min = 1e-300,
       .max = 1e300,
       .description = "the longest step along the curve in (point, first parameter, second parameter)"},
      {.id = "points",
       .label = "Maximal number of points",
       .defaultValue = static_cast<double>(d.maxPoints),
       .min = 1,
       .max = 1e7,
       .description = "each way from the start",
       .integer = true},
      {.id = "first_min",
       .label = "Least first parameter",
       .defaultValue = -none,
       .description = "the box of the parameter plane the curve is followed in (1e300: open)"},
      {.id = "first_max", .label = "Largest first parameter", .defaultValue = none, .description = "the box"},
      {.id = "second_min",
       .label = "Least second parameter",
       .defaultValue = -none,
       .description = "the box"},
      {.id = "second_max",
       .label = "Largest second parameter",
       .defaultValue = none,
       .description = "the box"},
  };
  return t;
}

BifurcationCurveSettings bifurcationCurveSettings(const ParameterValues& v,
                                                  const FixedPointSettings& search) {
  BifurcationCurveSettings c;
  const std::string kind = v.choice("kind");
  c.kind = kind == "fold"              ? CurveKind::Fold
           : kind == "period_doubling" ? CurveKind::PeriodDoubling
                                       : CurveKind::NeimarkSacker;
  c.step = v["step"];
  c.maxPoints = static_cast<long>(v["points"]);
  c.firstMin = v["first_min"], c.firstMax = v["first_max"];
  c.secondMin = v["second_min"], c.secondMax = v["second_max"];
  c.search = search;
  return c;
}

const ParameterTable& gridTable() {
  const GridSettings d;
  static const ParameterTable t{
      {.id = "threads",
       .label = "Number of threads",
       .defaultValue = static_cast<double>(d.threads),
       .min = 1,
       .max = 256,
       .description = "threads evaluating the grid",
       .integer = true},
      {.id = "step_x",
       .label = "Step along X",
       .defaultValue = d.axes[0].step,
       .min = 1e-300,
       .max = 1e300,
       .description = "grid step along the first map coordinate"},
      {.id = "step_y",
       .label = "Step along Y",
       .defaultValue = d.axes[1].step,
       .min = 1e-300,
       .max = 1e300,
       .description = "grid step along the second map coordinate"},
      {.id = "step_z",
       .label = "Step along Z",
       .defaultValue = d.axes[2].step,
       .min = 1e-300,
       .max = 1e300,
       .description = "grid step along the third map coordinate (3D grids)"},
      {.id = "section",
       .label = "Section",
       .defaultValue = d.threeD ? 1.0 : 0.0,
       .min = 0,
       .max = 1,
       .description = "3D maps: 2D on the plane z = const, or 3D in space",
       .integer = true,
       .choices = {"2D", "3D"}},
      {.id = "z",
       .label = "Z of the 2D section",
       .defaultValue = d.zValue,
       .description = "third coordinate of the plane of a 2D grid of a 3D map"},
      {.id = "x_min",
       .label = "X min",
       .defaultValue = d.axes[0].min,
       .description = "grid range of a chart (first coordinate)"},
      {.id = "x_max",
       .label = "X max",
       .defaultValue = d.axes[0].max,
       .description = "grid range of a chart (first coordinate)"},
      {.id = "y_min",
       .label = "Y min",
       .defaultValue = d.axes[1].min,
       .description = "grid range of a chart (second coordinate)"},
      {.id = "y_max",
       .label = "Y max",
       .defaultValue = d.axes[1].max,
       .description = "grid range of a chart (second coordinate)"},
      {.id = "z_min",
       .label = "Z min",
       .defaultValue = d.axes[2].min,
       .description = "grid range of a 3D grid (third coordinate)"},
      {.id = "z_max",
       .label = "Z max",
       .defaultValue = d.axes[2].max,
       .description = "grid range of a 3D grid (third coordinate)"},
  };
  return t;
}

const ParameterTable& diagramTable() {
  static const ParameterTable t;
  return t;
}

FixedPointSettings fixedPointSettings(const ParameterValues& v) {
  FixedPointSettings s;
  s.method = v.choice("method") == "newton" ? FixedPointMethod::Newton : FixedPointMethod::Gradient;
  s.maxIterations = static_cast<int>(v["max_iterations"]);
  s.accuracy = v["accuracy"];
  s.maxDistance = v["max_distance"];
  s.section2D = v.choice("section") == "2D";
  s.derivatives.method = v.choice("derivatives") == "variational" ? DerivativeMethod::Variational
                                                                  : DerivativeMethod::FiniteDifferences;
  s.derivatives.linearRegion = v["linear_region"];
  s.derivatives.accuracy = v["derivative_accuracy"];
  s.derivatives.zero = v["zero"];
  s.typeTolerance = v["type_tolerance"];
  return s;
}

ContinuationSettings continuationSettings(const ParameterValues& v, const FixedPointSettings& search) {
  ContinuationSettings c;
  c.method = v.choice("method") == "arclength" ? ContinuationMethod::Arclength : ContinuationMethod::Natural;
  c.step = v["step"];
  c.maxPoints = static_cast<long>(v["points"]);
  c.switchAt = static_cast<int>(v["switch"]);
  c.switchDistance = v["switch_distance"];
  c.extrapolation = v["extrapolation"];
  c.stopAtTypeChange = v.choice("stop_at_type_change") == "yes";
  c.bifurcationAccuracy = v["bifurcation_accuracy"];
  c.search = search;
  return c;
}

SeparatrixSettings separatrixSettings(const ParameterValues& v, const FixedPointSettings& search) {
  SeparatrixSettings s;
  s.branch = static_cast<int>(v["branch"]);
  s.linearRegion = v["linear_region"];
  s.linearAccuracy = v["linear_accuracy"];
  s.maxDistance = v["max_distance"];
  s.maxAngle = v["max_angle"];
  s.minAngleDistance = v["min_angle_distance"];
  s.maxIterations = static_cast<int>(v["iterations"]);
  s.maxPoints = static_cast<long>(v["points"]);
  s.fixedPointAccuracy = search.accuracy;
  return s;
}

BifurcationTreeSettings bifurcationTreeSettings(const ParameterValues& v, const ContinuationSettings& c) {
  BifurcationTreeSettings t;
  t.continuation = c;
  t.bifurcationAccuracy = v["accuracy"];
  t.regionSize = v["region"];
  t.coefficient = v["coefficient"];
  t.maxLevels = static_cast<int>(v["levels"]);
  return t;
}

GridSettings gridSettings(const ParameterValues& v) {
  GridSettings g;
  g.threads = static_cast<int>(v["threads"]);
  g.axes[0].step = v["step_x"], g.axes[1].step = v["step_y"], g.axes[2].step = v["step_z"];
  g.threeD = v.choice("section") == "3D";
  g.zValue = v["z"];
  g.axes[0].min = v["x_min"], g.axes[0].max = v["x_max"];
  g.axes[1].min = v["y_min"], g.axes[1].max = v["y_max"];
  g.axes[2].min = v["z_min"], g.axes[2].max = v["z_max"];
  return g;
}

const ParameterTable& sweepOptionsTable() {
  static const ParameterTable t{
      {.id = "time",
       .label = "Time",
       .defaultValue = 100,
       .min = 1e-300,
       .max = 1e300,
       .description = "integration time of observable.* and reversal (maps: iterations)"},
      {.id = "statistic",
       .label = "Statistic",
       .defaultValue = 0,
       .min = 0,
       .max = 1,
       .description = "observable.*: the value at the end or the time average",
       .integer = true,
       .choices = {"end", "mean"}},
      {.id = "zero",
       .label = "Zero exponent bound",
       .defaultValue = 0.01,
       .min = 0,
       .max = 1e300,
       .description = "lyapunov.positive counts the exponents above this"},
      {.id = "orbit_points",
       .label = "Orbit points",
       .defaultValue = 100,
       .min = 1,
       .max = 100000,
       .description = "orbit: the map points kept per grid point",
       .integer = true},
      {.id = "transient",
       .label = "Transient",
       .defaultValue = 200,
       .min = 0,
       .max = 1e12,
       .description = "orbit: the map points dropped first",
       .integer = true},
      {.id = "coordinate",
       .label = "Coordinate",
       .defaultValue = 0,
       .min = 0,
       .max = 2,
       .description = "orbit: which map coordinate is kept (0: the first)",
       .integer = true},
      {.id = "max_order",
       .label = "Largest order",
       .defaultValue = 8,
       .min = 1,
       .max = 1000,
       .description = "fixedpoint.order: the orders tried, 1 to this",
       .integer = true},
      {.id = "radius",
       .label = "Radius",
       .defaultValue = 0.1,
       .min = 0,
       .max = 1e300,
       .description = "fixedpoint.order: how far from the grid point the periodic point may lie"},
      {.id = "chunk",
       .label = "Largest chunk",
       .defaultValue = 0,
       .min = 0,
       .max = 1e9,
       .description = "the most points handed to a thread or rank at once (0: automatic)",
       .integer = true},
      {.id = "lanes",
       .label = "Lanes",
       .defaultValue = 0,
       .min = 0,
       .max = 8,
       .description =
           "0: points on SIMD lanes, as many at once as the CPU's registers take (8 with AVX-512, else 4; "
           "`rollviz info` names the width), where the quantity can (megno and lyapunov numbers over a "
           "flow's initial points and parameters with rk4 or everhart at a fixed step, bit for bit the "
           "points one at a time); 4 or 8: "
           "that many; 1: one point at a time",
       .integer = true},
      {.id = "refine",
       .label = "Refinement levels",
       .defaultValue = 0,
       .min = 0,
       .max = 8,
       .description =
           "detail where regimes meet: after the grid, this many times halve the cells whose corners "
           "differ (each axis' count becomes (count - 1) 2^levels + 1 at the finest level)",
       .integer = true},
      {.id = "refine_threshold",
       .label = "Refinement threshold",
       .defaultValue = 0.05,
       .min = 0,
       .max = 1e300,
       .description =
           "refine: a cell is halved when two corners differ by more than this fraction of the "
           "quantity's range on the grid (any change of a categorical quantity, or a failed corner "
           "beside a computed one)"},
      {.id = "refine_by",
       .label = "Refine where",
       .defaultValue = 0,
       .min = 0,
       .max = 1,
       .description =
           "refine: change -- corners differ by more than refine_threshold; value -- corners lie on "
           "different sides of refine_at (regimes told apart by a value, as MEGNO's <Y> = 2 on tori "
           "against its growth in chaos: the chaotic sea, whose values differ from point to point, is "
           "not refined as a boundary); a failed corner beside a computed one either way",
       .integer = true,
       .choices = {"change", "value"}},
      {.id = "refine_at",
       .label = "Refine across",
       .defaultValue = 0,
       .description = "refine_by value: the value of the quantity that separates the regimes"},
  };
  return t;
}

} // namespace rv
