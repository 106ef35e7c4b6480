// Functions.h -- the elementary functions of the expression language on every scalar a field is evaluated
// with: double, Eigen's forward-mode AutoDiffScalar (Jacobians, tangent vectors) and the Taylor tape's
// recording scalar. One definition, used by the interpreter (Graph.h) and by the C++ generated from a model
// file (ModelCode.h). The piecewise ones (abs, sign, min, max) branch on the plain value (valueOf): a Taylor
// tape that records them is marked as branching.
#pragma once
#include "dynamics/core/TaylorTape.h"
#include "dynamics/core/ValueOf.h"

#include <cmath>
#include <type_traits>

namespace rv::expr::fn {

[[noreturn]] void notExpandable(const char* function);

template <class S> constexpr bool isDouble = std::is_same_v<S, double>;
template <class S> constexpr bool isRecording = std::is_same_v<S, taylor::Var>;

/// A scalar with derivatives: its value and d(f)/d(value) applied to the derivatives (AutoDiff).
template <class S> S chain(const S& x, double value, double slope) {
  return S(value, x.derivatives() * slope);
}

template <class S> S tan(const S& x) {
  if constexpr (isDouble<S>)
    return std::tan(x);
  else if constexpr (isRecording<S>)
    return sin(x) / cos(x);
  else {
    const double t = std::tan(x.value());
    return chain(x, t, 1 + t * t);
  }
}
template <class S> S asin(const S& x) {
  if constexpr (isDouble<S>)
    return std::asin(x);
  else if constexpr (isRecording<S>)
    notExpandable("asin");
  else
    return chain(x, std::asin(x.value()), 1 / std::sqrt(1 - x.value() * x.value()));
}
template <class S> S acos(const S& x) {
  if constexpr (isDouble<S>)
    return std::acos(x);
  else if constexpr (isRecording<S>)
    notExpandable("acos");
  else
    return chain(x, std::acos(x.value()), -1 / std::sqrt(1 - x.value() * x.value()));
}
template <class S> S atan(const S& x) {
  if constexpr (isDouble<S>)
    return std::atan(x);
  else if constexpr (isRecording<S>)
    notExpandable("atan");
  else
    return chain(x, std::atan(x.value()), 1 / (1 + x.value() * x.value()));
}
template <class S> S atan2(const S& y, const S& x) {
  if constexpr (isDouble<S>)
    return std::atan2(y, x);
  else if constexpr (isRecording<S>)
    notExpandable("atan2");
  else {
    const double r2 = y.value() * y.value() + x.value() * x.value();
    return S(std::atan2(y.value(), x.value()),
             y.derivatives() * (x.value() / r2) - x.derivatives() * (y.value() / r2));
  }
}
template <class S> S sinh(const S& x) {
  if constexpr (isDouble<S>)
    return std::sinh(x);
  else if constexpr (isRecording<S>)
    return (exp(x) - exp(-x)) * 0.5;
  else
    return chain(x, std::sinh(x.value()), std::cosh(x.value()));
}
template <class S> S cosh(const S& x) {
  if constexpr (isDouble<S>)
    return std::cosh(x);
  else if constexpr (isRecording<S>)
    return (exp(x) + exp(-x)) * 0.5;
  else
    return chain(x, std::cosh(x.value()), std::sinh(x.value()));
}
template <class S> S tanh(const S& x) {
  if constexpr (isDouble<S>)
    return std::tanh(x);
  else if constexpr (isRecording<S>) {
    const S e = exp(x * 2.0);
    return (e - 1.0) / (e + 1.0);
  } else {
    const double t = std::tanh(x.value());
    return chain(x, t, 1 - t * t);
  }
}
/// a^b for a non-constant exponent.
template <class S> S power(const S& a, const S& b) {
  if constexpr (isDouble<S>)
    return std::pow(a, b);
  else
    return exp(b * log(a));
}
template <class S> S abs(const S& x) {
  if constexpr (isDouble<S>)
    return std::abs(x);
  else
    return valueOf(x) < 0 ? S(-x) : x;
}
template <class S> S sign(const S& x) {
  const double v = valueOf(x);
  const double s = v > 0 ? 1.0 : (v < 0 ? -1.0 : 0.0);
  if constexpr (isDouble<S> || isRecording<S>)
    return S(s);
  else
    return S(s, x.derivatives() * 0.0);
}
template <class S> S min(const S& a, const S& b) {
  if constexpr (isDouble<S>)
    return std::fmin(a, b);
  else
    return valueOf(a) <= valueOf(b) ? a : b;
}
template <class S> S max(const S& a, const S& b) {
  if constexpr (isDouble<S>)
    return std::fmax(a, b);
  else
    return valueOf(a) >= valueOf(b) ? a : b;
}

} // namespace rv::expr::fn
