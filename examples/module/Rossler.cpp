#include "Rossler.h"

namespace rossler {

const rv::ModelInfo& Rossler::staticInfo() {
  static const rv::ModelInfo info{
      .id = "rossler",
      .title = "Roessler system (a module's model)",
      .reference = "O. E. Roessler, Phys. Lett. A 57 (1976) 397-398",
      .parameters =
          {
              {.id = "a",
               .label = "a",
               .defaultValue = 0.2,
               .min = -10,
               .max = 10,
               .description = "the growth of the oscillation in (x, y)"},
              {.id = "b",
               .label = "b",
               .defaultValue = 0.2,
               .min = -10,
               .max = 10,
               .description = "the constant feed of z"},
              {.id = "c",
               .label = "c",
               .defaultValue = 5.7,
               .min = -100,
               .max = 100,
               .description = "where z is switched on by x"},
          },
      .stateNames = {"x", "y", "z"},
      .coreDimension = 3,
      // the half-plane y = 0, x > 0 (crossed upwards): the classic section of the spiral attractor
      .section = "y",
  };
  return info;
}

Rossler::Rossler(const rv::ParameterValues& p)
    : ModelWithField(staticInfo(), p), a_(p["a"]), b_(p["b"]), c_(p["c"]) {
  addStandardObservables();
  addObservable("divergence", "the trace of the Jacobian, a + x - c: the exponents sum to its time average",
                [a = a_, c = c_](double, const double* x) { return a + x[0] - c; });
}

} // namespace rossler
