// LaneField.h -- what a model offers to integrate W trajectories at once (dynamics/core/Lanes.h; W = 4 or 8):
// a kernel bound to W models that evaluates their right-hand sides with the derivatives along tangent
// vectors in one pass, and takes RK4 steps of W orbits with their tangent vectors in one compiled loop.
// Models with a templated field (ModelWithField) that declare `static constexpr bool kLaneField = true` (a
// field with no branch on a value) have it; the batched tools (dynamics/tools/MegnoLanes.h, LyapunovLanes.h)
// get it through laneKernelFor.
//
// The lanes may hold different models of one class: a sweep over a parameter puts its points side by side.
// A model whose field reads parameters declares them as `template <class T> struct Coefficients` (members of
// type T only) with `coefficients()` and a static `field(coefficients, x, dx)`; the lanes then read one
// coefficient per lane (dynamics/models/Lorenz.h). A model without it runs lanes of equal parameters only.
// Declare such a field [[gnu::always_inline]]: the kernel then compiles it whole for AVX2 (GCC leaves a large
// function out of line, compiled for baseline x86-64). A large field (more than
// ModelWithField::kInlinedFieldDimension components: the rolling bodies) is compiled for 0 and 1 tangent
// direction only and runs its recorded JetProgram for the other counts (compiledFor says which are compiled).
#pragma once
#include "dynamics/core/Lanes.h"

#include <memory>
#include <vector>

namespace rv {

class Model;

/// The model of each lane (4 or 8): models of one class, the first the one asked.
using LaneModels = std::vector<const Model*>;

/// The fields of W models bound together: what the batched tools call at each step.
class LaneKernel {
public:
  virtual ~LaneKernel() = default;
  /// W: how many lanes.
  virtual int width() const = 0;
  /// f(x) and J(x) V for k tangent vectors at W states at once, component-major: x[c * W + l] for the n
  /// state components and then the m core components of each vector, vector after vector (m = coreDimension;
  /// TangentSystem's layout, lane by lane), out likewise (f, then J V). Lane l computes with the l-th model:
  /// each lane is what Model::tangentRhs gives alone, bit for bit. k = 0: f alone, each lane Model::rhs's.
  /// False, changing nothing, where k is outside the fixed counts (as tangentRk4).
  virtual bool tangentRhs(const double* x, int k, double* out) const = 0;
  /// Advances W orbits, each with k tangent vectors in core coordinates, by `steps` classical RK4 steps of h:
  /// y holds, component-major (y[j * W + l]), each lane's state laid out as TangentSystem's (x,
  /// then the k vectors column after column). Each lane is what Model::tangentRk4 gives its orbit alone, bit
  /// for bit. False, changing nothing, where k is outside the fixed counts of tangentRk4; steps = 0 only
  /// asks.
  virtual bool tangentRk4(double* y, int k, double h, long steps) const = 0;
  /// Whether k tangent vectors run code compiled for this CPU's vector extension: what the batched tools take
  /// lanes for. Where not (a count a recorded field interprets, JetProgram.h), one orbit at a time is as fast
  /// or faster, and the tools run them so; the kernel still computes it, bit for bit.
  virtual bool compiledFor(int k) const {
    (void)k;
    return true;
  }
};

class LaneField {
public:
  virtual ~LaneField() = default;
  /// The kernel of `models` (4 or 8, each of this model's class), or nullptr where they cannot go together:
  /// no lane kernel, a map, models of another class, different parameters of a model without Coefficients.
  virtual std::unique_ptr<LaneKernel> laneKernel(const LaneModels& models) const = 0;
};

/// The kernel that integrates the orbits of `models` (one per orbit, 1 to kMaxLanes; the last fills the lanes
/// left over) together, 4 lanes wide for up to 4 orbits, else 8; nullptr where they cannot go on lanes.
std::unique_ptr<LaneKernel> laneKernelFor(const std::vector<const Model*>& models);

} // namespace rv
