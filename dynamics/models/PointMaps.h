// PointMaps.h -- explicit point maps, models of kind Map: rhs() is the map itself, jacobian() its derivative,
// so that every tool that works on a Poincare map works on them too.
// References: M. Henon, A two-dimensional mapping with a strange attractor, Comm. Math. Phys. 50 (1976) 69;
//             B. V. Chirikov, A universal instability of many-dimensional oscillator systems, Phys. Rep. 52
//             (1979).
#pragma once
#include "dynamics/core/ModelWithField.h"

#include <numbers>

namespace rv {

/// x' = 1 - a x^2 + y, y' = b x; the Jacobian determinant is -b (area-preserving at b = -1).
class HenonMap final : public ModelWithField<HenonMap, 2> {
public:
  explicit HenonMap(const ParameterValues& params);
  static const ModelInfo& staticInfo();
  template <class S> void field(const Vec<S>& x, Vec<S>& out) const {
    out[0] = 1.0 - a_ * x[0] * x[0] + x[1];
    out[1] = b_ * x[0];
  }

private:
  double a_, b_;
};

/// p' = p + K sin(theta), theta' = theta + p', both mod 2 pi; coordinates (theta, p).
class StandardMap final : public ModelWithField<StandardMap, 2> {
public:
  explicit StandardMap(const ParameterValues& params);
  static const ModelInfo& staticInfo();
  template <class S> void field(const Vec<S>& x, Vec<S>& out) const {
    using std::sin;
    const S p = x[1] + K_ * sin(x[0]);
    out[0] = wrap(x[0] + p);
    out[1] = wrap(p);
  }
  /// v mod 2 pi into [0, 2 pi) (the derivative passes through unchanged).
  template <class S> static S wrap(const S& v) {
    constexpr double twoPi = 2 * std::numbers::pi;
    return v - twoPi * std::floor(valueOf(v) / twoPi);
  }

private:
  double K_;
};

// compiled once, in PointMaps.cpp: constructing the model elsewhere does not compile its kernels again
// (ModelWithField.h)
extern template class ModelWithField<HenonMap, 2>;
extern template class ModelWithField<StandardMap, 2>;

} // namespace rv
