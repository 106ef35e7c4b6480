// ValueOf.h -- the plain value of a scalar that may carry derivatives, for a field's branch decisions
// (wrapping an angle, the piecewise functions of the expression language): on its own, so that the expression
// machinery reads it without the templated-field machinery (ModelWithField.h). The Taylor tape's recording
// scalar has its own (TaylorTape.h: a branch marks the tape).
#pragma once

namespace Eigen {
template <typename DerivativeType> class AutoDiffScalar;
} // namespace Eigen

namespace rv {

inline double valueOf(double v) {
  return v;
}
template <class D> double valueOf(const Eigen::AutoDiffScalar<D>& v) {
  return v.value();
}

} // namespace rv
