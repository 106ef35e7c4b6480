// Lorenz.h -- the Lorenz system, a reference flow with known Lyapunov exponents (0.906, 0, -14.572 at the
// classical parameters; their sum is -(sigma + 1 + beta) exactly).
// Reference: E. N. Lorenz, Deterministic nonperiodic flow, J. Atmos. Sci. 20 (1963) 130-141.
#pragma once
#include "dynamics/core/ModelWithField.h"

namespace rv {

class Lorenz final : public ModelWithField<Lorenz, 3> {
public:
  explicit Lorenz(const ParameterValues& params);
  static const ModelInfo& staticInfo();
  static constexpr bool kLaneField = true; ///< no branch on a value: runs on lanes (Lanes.h)

  /// The parameters the field reads, as T: double, or one per lane (LaneField.h).
  template <class T> struct Coefficients { T sigma, rho, beta; };
  const Coefficients<double>& coefficients() const { return c_; }

  template <class S, class T>
  [[gnu::always_inline]] static void field(const Coefficients<T>& c, const Vec<S>& x, Vec<S>& dx) {
    dx[0] = c.sigma * (x[1] - x[0]);
    dx[1] = x[0] * (c.rho - x[2]) - x[1];
    dx[2] = x[0] * x[1] - c.beta * x[2];
  }
  template <class S> void field(const Vec<S>& x, Vec<S>& dx) const { field(c_, x, dx); }

private:
  Coefficients<double> c_;
};

// compiled once, in Lorenz.cpp: constructing the model elsewhere does not compile its kernels again
// (ModelWithField.h)
extern template class ModelWithField<Lorenz, 3>;

} // namespace rv
