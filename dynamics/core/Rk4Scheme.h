// Rk4Scheme.h -- the classical fourth-order Runge-Kutta step as one template, shared by the Rk4 integrator
// and the fused tangent steps of the templated fields (ModelWithField::tangentRk4, JetEvaluator::rk4) -- in
// core, below both, so that the method is written once; and the same step on arrays of doubles W at a time
// (Lanes.h), for large systems and orbits stacked on lanes. Reference: E. Hairer, S. P. Norsett, G. Wanner,
// Solving Ordinary Differential Equations I, §II.1.
#pragma once
#include "dynamics/core/Lanes.h"

#include <type_traits>

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

namespace detail {
// combine<T>(i) on elements i of arrays of n doubles: W at a time as LaneVector<W>, the rest one by one
template <int W, class Combine> [[gnu::always_inline]] inline void eachElement(long n, Combine&& combine) {
  const long whole = n / W * W;
  for (long i = 0; i < whole; i += W)
    combine.template operator()<LaneVector<W>>(i);
  for (long i = whole; i < n; ++i)
    combine.template operator()<double>(i);
}
template <class T> [[gnu::always_inline]] inline T loadAt(const double* p, long i) {
  if constexpr (std::is_same_v<T, double>)
    return p[i];
  else
    return T::load(p + i);
}
template <class T> [[gnu::always_inline]] inline void storeAt(double* p, long i, const T& v) {
  if constexpr (std::is_same_v<T, double>)
    p[i] = v;
  else
    v.store(p + i);
}
} // namespace detail

/// rk4Step on arrays of n doubles (field(const double* y, double* dy)), W elements at a time: each element
/// takes the Eigen expression's operations in its order (no fused multiply-add), so the state is the one
/// rk4Step gives, bit for bit. Compiled into a function for AVX2 or AVX-512, one register per W elements.
template <int W, class Field>
[[gnu::always_inline]] inline void rk4StepOnArrays(const Field& field, double h, long n, const double* y0,
                                                   const double* f0, double* k2, double* k3, double* k4,
                                                   double* tmp, double* y1) {
  using detail::eachElement, detail::loadAt, detail::storeAt;
  const auto plusScaled = [n, y0, tmp](double c, const double* k) { // tmp = y0 + c k
    eachElement<W>(n, [&]<class T>(long i) { storeAt(tmp, i, loadAt<T>(y0, i) + T(c) * loadAt<T>(k, i)); });
  };
  plusScaled(0.5 * h, f0);
  field(tmp, k2);
  plusScaled(0.5 * h, k2);
  field(tmp, k3);
  plusScaled(h, k3);
  field(tmp, k4);
  const double c = h / 6.0;
  eachElement<W>(n, [&]<class T>(long i) {
    const T sum = loadAt<T>(f0, i) + T(2.0) * loadAt<T>(k2, i) + T(2.0) * loadAt<T>(k3, i) + loadAt<T>(k4, i);
    storeAt(y1, i, loadAt<T>(y0, i) + T(c) * sum);
  });
}

} // namespace rv
