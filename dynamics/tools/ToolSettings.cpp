#include "dynamics/tools/ToolSettings.h"

namespace rv {

const SettingsTable<FixedPointSettings>& fixedPointSettingsTable() {
  using S = FixedPointSettings;
  using T = SettingsTable<S>;
  static const T t{
      T::Field{{.id = "order", // read where the map is made (scenes/SceneTools.h)
                .label = "Order of FP",
                .defaultValue = 1,
                .min = 1,
                .max = 1e6,
                .description = "order n of the fixed point: a zero of Map^n(x) - x",
                .integer = true}},
      T::choice(&S::method,
                {.id = "method",
                 .label = "Method of FP finding",
                 .description = "newton or gradient (descent on |Map^n(x) - x|^2)",
                 .choices = {"newton", "gradient"}},
                std::vector{FixedPointMethod::Newton, FixedPointMethod::Gradient}),
      T::number(&S::maxIterations,
                {.id = "max_iterations",
                 .label = "Max. number of iterations",
                 .min = 1,
                 .max = 1e7,
                 .description = "the search stops with a message after this many iterations"}),
      T::number(&S::accuracy, {.id = "accuracy",
                               .label = "Accuracy of FP location",
                               .min = 1e-300,
                               .max = 1,
                               .description = "the largest |Map^n(x) - x| accepted at the fixed point"}),
      T::number(&S::maxDistance,
                {.id = "max_distance",
                 .label = "Max. distance between points",
                 .min = 1e-300,
                 .max = 1e300,
                 .description = "bound on the distance between consecutive points of the search"}),
      T::choice(
          [](S & s) -> auto& { return s.derivatives.method; },
          {.id = "derivatives",
           .label = "Derivatives",
           .description = "variational (along the orbit, with the section correction) or differences "
                          "(numerical, with the three controls below)",
           .choices = {"variational", "differences"}},
          std::vector{DerivativeMethod::Variational, DerivativeMethod::FiniteDifferences}),
      T::number([](S & s) -> auto& { return s.derivatives.linearRegion; },
                {.id = "linear_region",
                 .label = "Linear approximation region",
                 .min = 1e-300,
                 .max = 1,
                 .description = "initial step of numerical differentiation"}),
      T::number([](S & s) -> auto& { return s.derivatives.accuracy; },
                {.id = "derivative_accuracy",
                 .label = "Accuracy of derivatives finding",
                 .min = 1e-300,
                 .max = 1,
                 .description = "allowed |Map(x + dx) - Lin(x + dx)| at |dx| = the step"}),
      T::number([](S & s) -> auto& { return s.derivatives.zero; },
                {.id = "zero",
                 .label = "Value of \"zero\"",
                 .min = 1e-300,
                 .max = 1,
                 .description = "the differentiation step may not shrink below this"}),
      T::choice(
          &S::section2D,
          {.id = "section",
           .label = "Section",
           .description = "3D maps: 2D searches on the plane z = const (degenerate points), 3D in space",
           .choices = {"2D", "3D"}},
          std::vector{true, false}),
      T::number(&S::typeTolerance,
                {.id = "type_tolerance",
                 .label = "Type tolerance",
                 .min = 0,
                 .max = 1,
                 .description = "how close to the unit circle (or to +-1) a multiplier counts as on it"}),
      T::Field{{.id = "path", // read by the front ends that show the result
                .label = "Show all points",
                .defaultValue = 0,
                .min = 0,
                .max = 1,
                .description = "the result gives the whole search path (the map window always draws it)",
                .integer = true,
                .choices = {"no", "yes"}}},
  };
  return t;
}

const SettingsTable<ContinuationSettings>& continuationSettingsTable() {
  using S = ContinuationSettings;
  using T = SettingsTable<S>;
  static const T t{
      T::choice(&S::method,
                {.id = "method",
                 .label = "Method",
                 .description =
                     "natural: the parameter stepped (the manual's; stops where the family turns "
                     "back); arclength: pseudo-arclength, the parameter one of the unknowns (passes "
                     "folds)",
                 .choices = {"natural", "arclength"}},
                std::vector{ContinuationMethod::Natural, ContinuationMethod::Arclength}),
      T::number(&S::step,
                {.id = "step",
                 .label = "Step",
                 .description = "signed step of the parameter (arclength: the longest step along the family, "
                                "its sign the parameter's first direction)"}),
      T::number(&S::maxPoints,
                {.id = "points",
                 .label = "Maximal number of points",
                 .min = 2,
                 .max = 1e7,
                 .description =
                     "arclength: the family ends after this many points (a closed family would not "
                     "end)"}),
      T::number(&S::extrapolation,
                {.id = "extrapolation",
                 .label = "Extrapolation factor",
                 .min = -10,
                 .max = 10,
                 .description = "d in X_{n+1} = X_n + (X_n - X_{n-1}) d for the next guess"}),
      T::choice(&S::stopAtTypeChange,
                {.id = "stop_at_type_change",
                 .label = "Stop at FP type change",
                 .description = "stop the continuation where the type of the point changes",
                 .choices = {"no", "yes"}},
                std::vector{false, true}),
      T::number(&S::switchAt,
                {.id = "switch",
                 .label = "Switch at doubling",
                 .min = 0,
                 .max = 1000,
                 .description =
                     "0: the family itself; k: the family of doubled order born at its k-th period "
                     "doubling (branch switching), continued to the end of [start, to] on its side"}),
      T::number(&S::switchDistance,
                {.id = "switch_distance",
                 .label = "Switch distance",
                 .min = 1e-300,
                 .max = 1e300,
                 .description = "how far from the doubling the first point of doubled order is sought, along "
                                "the flip direction"}),
      T::number(&S::bifurcationAccuracy, {.id = "bifurcation_accuracy",
                                          .label = "Accuracy of bifurcation value",
                                          .min = 1e-300,
                                          .max = 1,
                                          .description = "of the parameter value where the type changes"}),
  };
  return t;
}

const SettingsTable<SeparatrixSettings>& separatrixSettingsTable() {
  using S = SeparatrixSettings;
  using T = SettingsTable<S>;
  static const T t{
      T::number(
          &S::branch,
          {.id = "branch",
           .label = "Separatrix number",
           .min = 1,
           .max = 4,
           .description = "1, 2: first multiplier (+v, -v); 3, 4: second (incoming when |multiplier| < 1)"}),
      T::number(&S::linearRegion,
                {.id = "linear_region",
                 .label = "Linear approximation region",
                 .min = 1e-300,
                 .max = 1,
                 .description = "length of the initial linear segment (halved until accurate)"}),
      T::number(&S::linearAccuracy,
                {.id = "linear_accuracy",
                 .label = "Linear approximation accuracy",
                 .min = 1e-300,
                 .max = 3.2,
                 .description = "allowed angle (radians) between the eigenvector v and Map(v)"}),
      T::number(&S::maxDistance, {.id = "max_distance",
                                  .label = "Max. distance between points",
                                  .min = 1e-300,
                                  .max = 1e300,
                                  .description = "between neighbouring points of the separatrix"}),
      T::number(&S::maxAngle, {.id = "max_angle",
                               .label = "Max. angle of one iteration",
                               .min = 1e-300,
                               .max = 3.2,
                               .description = "largest turn (radians) between consecutive segments"}),
      T::number(&S::minAngleDistance, {.id = "min_angle_distance",
                                       .label = "Min. distance for angle control",
                                       .min = 0,
                                       .max = 1e300,
                                       .description = "shorter segments are not refined for their angle"}),
      T::number(&S::maxIterations, {.id = "iterations",
                                    .label = "Iterations",
                                    .min = 1,
                                    .max = 1e6,
                                    .description = "images of the fundamental segment"}),
      T::number(&S::maxPoints, {.id = "points",
                                .label = "Max. points",
                                .min = 2,
                                .max = 1e9,
                                .description = "the branch stops growing at this many points"}),
  };
  return t;
}

const SettingsTable<BifurcationTreeSettings>& bifurcationTreeSettingsTable() {
  using S = BifurcationTreeSettings;
  using T = SettingsTable<S>;
  static const T t{
      T::number(&S::bifurcationAccuracy, {.id = "accuracy",
                                          .label = "Accuracy of bifurcation value",
                                          .min = 1e-300,
                                          .max = 1,
                                          .description = "initial accuracy of the bifurcation value"}),
      T::number(&S::regionSize,
                {.id = "region",
                 .label = "Initial size of bifurcation region",
                 .min = 1e-300,
                 .max = 1e300,
                 .description = "distance from the point to the first guess of doubled period"}),
      T::number(&S::coefficient,
                {.id = "coefficient",
                 .label = "Coefficient of decreasing of the step",
                 .min = 1.000001,
                 .max = 1e6,
                 .description = "step, accuracy and region shrink by it at each doubling (Feigenbaum's "
                                "constant)"}),
      T::number(&S::maxLevels, {.id = "levels",
                                .label = "Levels",
                                .min = 0,
                                .max = 30,
                                .description = "period doublings followed at most"}),
  };
  return t;
}

const SettingsTable<BifurcationCurveSettings>& bifurcationCurveSettingsTable() {
  using S = BifurcationCurveSettings;
  using T = SettingsTable<S>;
  constexpr double none = 1e300; // an open side of the box (the struct's infinity)
  static const T t{
      T::choice(&S::kind,
                {.id = "kind",
                 .label = "Bifurcation",
                 .description =
                     "the curve followed: where a multiplier is +1 (fold), -1 (period doubling) or a complex "
                     "pair is on the unit circle (Neimark-Sacker); the start is the first such point of the "
                     "continuation",
                 .choices = {"fold", "period_doubling", "neimark_sacker"}},
                std::vector{CurveKind::Fold, CurveKind::PeriodDoubling, CurveKind::NeimarkSacker}),
      T::number(
          &S::step,
          {.id = "step",
           .label = "Step",
           .min = 1e-300,
           .max = 1e300,
           .description = "the longest step along the curve in (point, first parameter, second parameter)"}),
      T::number(&S::maxPoints, {.id = "points",
                                .label = "Maximal number of points",
                                .min = 1,
                                .max = 1e7,
                                .description = "each way from the start"}),
      T::number(&S::firstMin,
                {.id = "first_min",
                 .label = "Least first parameter",
                 .description = "the box of the parameter plane the curve is followed in (1e300: open)"},
                -none),
      T::number(&S::firstMax,
                {.id = "first_max", .label = "Largest first parameter", .description = "the box"}, none),
      T::number(&S::secondMin,
                {.id = "second_min", .label = "Least second parameter", .description = "the box"}, -none),
      T::number(&S::secondMax,
                {.id = "second_max", .label = "Largest second parameter", .description = "the box"}, none),
  };
  return t;
}

const SettingsTable<GridSettings>& gridSettingsTable() {
  using S = GridSettings;
  using T = SettingsTable<S>;
  // the grid's axes: axis k's step, least and largest value
  const auto step = [](std::size_t k) {
    return [k](S & s) -> auto& {
      return s.axes[k].step;
    };
  };
  const auto least = [](std::size_t k) {
    return [k](S & s) -> auto& {
      return s.axes[k].min;
    };
  };
  const auto largest = [](std::size_t k) {
    return [k](S & s) -> auto& {
      return s.axes[k].max;
    };
  };
  static const T t{
      T::number(&S::threads, {.id = "threads",
                              .label = "Number of threads",
                              .min = 1,
                              .max = 256,
                              .description = "threads evaluating the grid"}),
      T::number(step(0), {.id = "step_x",
                          .label = "Step along X",
                          .min = 1e-300,
                          .max = 1e300,
                          .description = "grid step along the first map coordinate"}),
      T::number(step(1), {.id = "step_y",
                          .label = "Step along Y",
                          .min = 1e-300,
                          .max = 1e300,
                          .description = "grid step along the second map coordinate"}),
      T::number(step(2), {.id = "step_z",
                          .label = "Step along Z",
                          .min = 1e-300,
                          .max = 1e300,
                          .description = "grid step along the third map coordinate (3D grids)"}),
      T::choice(&S::threeD,
                {.id = "section",
                 .label = "Section",
                 .description = "3D maps: 2D on the plane z = const, or 3D in space",
                 .choices = {"2D", "3D"}},
                std::vector{false, true}),
      T::number(&S::zValue, {.id = "z",
                             .label = "Z of the 2D section",
                             .description = "third coordinate of the plane of a 2D grid of a 3D map"}),
      T::number(least(0),
                {.id = "x_min", .label = "X min", .description = "grid range of a chart (first coordinate)"}),
      T::number(largest(0),
                {.id = "x_max", .label = "X max", .description = "grid range of a chart (first coordinate)"}),
      T::number(
          least(1),
          {.id = "y_min", .label = "Y min", .description = "grid range of a chart (second coordinate)"}),
      T::number(
          largest(1),
          {.id = "y_max", .label = "Y max", .description = "grid range of a chart (second coordinate)"}),
      T::number(
          least(2),
          {.id = "z_min", .label = "Z min", .description = "grid range of a 3D grid (third coordinate)"}),
      T::number(
          largest(2),
          {.id = "z_max", .label = "Z max", .description = "grid range of a 3D grid (third coordinate)"}),
  };
  return t;
}

const ParameterTable& diagramTable() {
  static const ParameterTable t;
  return t;
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
