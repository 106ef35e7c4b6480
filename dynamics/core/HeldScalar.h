// HeldScalar.h -- the Eigen::NumTraits of a scalar that Eigen's fixed-size vectors only hold while a model's
// templated field computes on it (Lanes and Jet of Lanes.h, taylor::Var of TaylorTape.h): the field does the
// arithmetic, Eigen none of its own. One definition for all of them.
#pragma once
#include <Eigen/Core>

namespace rv {

/// The traits of a held scalar S whose operations cost `Cost` double operations each (Eigen's cost model).
template <class S, int Cost> struct HeldScalarTraits : Eigen::NumTraits<double> {
  using Real = S;
  using NonInteger = S;
  using Nested = S;
  using Literal = S;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1,
    AddCost = Cost,
    MulCost = Cost
  };
};

} // namespace rv
