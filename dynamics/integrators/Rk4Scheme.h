// Rk4Scheme.h -- the classical fourth-order Runge-Kutta step as one template, shared by the Rk4 integrator
// and the fused tangent steps of models with a templated field (ModelWithField::tangentRk4), so that the
// method is written once. Reference: E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential
// Equations I, §II.1.
#pragma once

namespace rv {

/// One step of y' = f(y) over h from y0, given f0 = f(y0): y1 and the stages k2..k4 (tmp is scratch). `field`
/// is called as field(const Y& y, Y& dy); with fixed-size vectors and an inlinable field the whole step
/// compiles to straight-line code.
template <class Y, class Field>
inline void rk4Step(const Field& field, double h, const Y& y0, const Y& f0, Y& k2, Y& k3, Y& k4, Y& tmp,
                    Y& y1) {
  tmp = y0 + (0.5 * h) * f0;
  field(tmp, k2);
  tmp = y0 + (0.5 * h) * k2;
  field(tmp, k3);
  tmp = y0 + h * k3;
  field(tmp, k4);
  y1 = y0 + (h / 6.0) * (f0 + 2.0 * k2 + 2.0 * k3 + k4);
}

} // namespace rv
