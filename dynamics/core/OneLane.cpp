#include "dynamics/core/OneLane.h"

#include "dynamics/core/Errors.h"

#include <stdexcept>

namespace rv {

ModelInfo derivedSystemInfo(const ModelInfo& base, const std::string& id, int dimension) {
  ModelInfo info = base;
  info.id = id;
  info.stateNames.clear();
  for (int i = 0; i < dimension; ++i)
    info.stateNames.push_back("y" + std::to_string(i));
  info.coreDimension = dimension;
  info.integralNames.clear();
  info.hasMeasure = false;
  return info;
}

OneLane::OneLane(const Model& stacked, int width, int lane, const Eigen::VectorXd& others)
    : detail::OneLaneInfo{derivedSystemInfo(stacked.info(),
                                            stacked.info().id + " lane " + std::to_string(lane),
                                            width > 0 ? stacked.dimension() / width : 0)},
      Model(laneInfo, stacked.parameters()), stacked_(stacked), width_(width), lane_(lane), in_(others),
      out_(others.size()) {
  if (width < 1 || lane < 0 || lane >= width || stacked.dimension() % width != 0 ||
      others.size() != stacked.dimension())
    throw std::logic_error("OneLane: lane " + std::to_string(lane) + " of " + std::to_string(width) +
                           " does not fit a stacked state of " + std::to_string(stacked.dimension()));
}

void OneLane::rhs(const double* x, double* dx) const {
  const int n = dimension();
  for (int c = 0; c < n; ++c)
    in_[c * width_ + lane_] = x[c];
  stacked_.rhs(in_.data(), out_.data());
  for (int c = 0; c < n; ++c)
    dx[c] = out_[c * width_ + lane_];
}

void OneLane::jacobian(const double*, double*) const {
  throw ComputationError("the Jacobian of " + info().id + " is not available");
}

Eigen::VectorXd OneLane::of(const Eigen::VectorXd& stacked) const {
  Eigen::VectorXd orbit(dimension());
  for (int c = 0; c < dimension(); ++c)
    orbit[c] = stacked[c * width_ + lane_];
  return orbit;
}

void OneLane::put(const Eigen::VectorXd& orbit, Eigen::Ref<Eigen::VectorXd> stacked) const {
  for (int c = 0; c < dimension(); ++c)
    stacked[c * width_ + lane_] = orbit[c];
}

} // namespace rv
