// TangentSystem.h -- a model together with k tangent vectors in its core coordinates: the variational
// equations V' = J(x) V of a flow (or V -> J(x) V for a map), with the model's exact Jacobian. Any integrator
// integrates it.
#pragma once
#include "dynamics/core/Model.h"

#include <memory>

namespace rv {

namespace detail {
struct TangentInfo {
  ModelInfo tangentInfo;
};
} // namespace detail

class TangentSystem final : private detail::TangentInfo, public Model {
public:
  /// State: the base state (n components), then k tangent vectors of the core dimension m, column after
  /// column.
  TangentSystem(const Model& base, int vectors);
  void rhs(const double* x, double* dx) const override;
  /// Not needed by any tool; throws.
  void jacobian(const double* x, double* jac) const override;
  /// The base model's sheet of the base part of the state.
  int sheetOf(const Eigen::VectorXd& x, const MapPointSpec& spec) const override;

  /// Advances `state` (this system's layout) by `steps` RK4 steps of h through the base model's fused path
  /// (Model::tangentRk4): what Rk4 on this system computes, a few times faster. False, changing nothing,
  /// where the base model has none; steps = 0 only asks.
  bool rk4Steps(Eigen::VectorXd& state, double h, long steps) const;

  const Model& base() const { return base_; }
  int vectors() const { return k_; }
  int core() const { return m_; }

private:
  const Model& base_;
  int n_, m_, k_;
};

} // namespace rv
