// OneLane.h -- one orbit of a system of W orbits stacked component-major (component c of lane l at
// c * W + l, LaneStack.h) seen as a system of its own. A method whose steps run on lanes but whose setup
// reads the whole state (Adams's adaptive starter) runs that setup orbit by orbit on these views: the stacked
// field is computed lane by lane, so a view's field is, bit for bit, the field of that orbit alone.
#pragma once
#include "dynamics/core/Model.h"

#include <Eigen/Core>
#include <string>

namespace rv {

/// The info of a system built on `base` (its kind and parameters), of `dimension` components y0, y1, ...
/// with no integrals or measure of its own, named `id`.
ModelInfo derivedSystemInfo(const ModelInfo& base, const std::string& id, int dimension);

namespace detail {
struct OneLaneInfo {
  ModelInfo laneInfo;
};
} // namespace detail

/// Lane `lane` of `stacked`, which holds `width` orbits. The other lanes hold `others` (a stacked state, e.g.
/// the one the run starts from) while this lane's field is computed. Not thread-safe: one integrator at a
/// time (it keeps the stacked state it evaluates).
class OneLane final : private detail::OneLaneInfo, public Model {
public:
  OneLane(const Model& stacked, int width, int lane, const Eigen::VectorXd& others);
  void rhs(const double* x, double* dx) const override;
  /// Not available (the views are stepped by explicit methods).
  void jacobian(const double*, double*) const override;
  /// This lane's components of a stacked vector.
  Eigen::VectorXd of(const Eigen::VectorXd& stacked) const;
  /// Writes `orbit` into this lane's components of `stacked`.
  void put(const Eigen::VectorXd& orbit, Eigen::Ref<Eigen::VectorXd> stacked) const;

private:
  const Model& stacked_;
  int width_, lane_;
  mutable Eigen::VectorXd in_, out_;
};

} // namespace rv
