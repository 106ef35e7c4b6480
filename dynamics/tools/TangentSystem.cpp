#include "dynamics/tools/TangentSystem.h"

#include "dynamics/core/Errors.h"

namespace rv {

namespace {
detail::TangentInfo makeTangentInfo(const Model& base, int k) {
  detail::TangentInfo t{base.info()};
  ModelInfo& info = t.tangentInfo;
  info.id = base.info().id + "+tangent";
  const int m = base.info().coreDimension;
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < m; ++i) info.stateNames.push_back("v" + std::to_string(j + 1) + "_" + std::to_string(i + 1));
  info.integralNames.clear();
  info.hasMeasure = false;
  return t;
}
} // namespace

TangentSystem::TangentSystem(const Model& base, int vectors)
    : detail::TangentInfo(makeTangentInfo(base, vectors)), Model(tangentInfo, base.parameters()), base_(base),
      n_(base.dimension()), m_(base.info().coreDimension), k_(vectors) {
  J_.resize(m_, m_);
}

void TangentSystem::rhs(const double* x, double* dx) const {
  base_.rhs(x, dx);
  // the core block of the Jacobian (the core evolves on its own, so it is all that tangent vectors need)
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> J(J_.data(), m_, m_);
  base_.coreJacobian(x, J_.data());
  const Eigen::Map<const Eigen::MatrixXd> V(x + n_, m_, k_);
  Eigen::Map<Eigen::MatrixXd> dV(dx + n_, m_, k_);
  dV.noalias() = J * V;
}

void TangentSystem::jacobian(const double*, double*) const {
  throw ComputationError("the Jacobian of the variational equations is not available");
}

} // namespace rv
