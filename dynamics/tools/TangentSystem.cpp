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
    for (int i = 0; i < m; ++i)
      info.stateNames.push_back("v" + std::to_string(j + 1) + "_" + std::to_string(i + 1));
  info.integralNames.clear();
  info.hasMeasure = false;
  return t;
}
} // namespace

TangentSystem::TangentSystem(const Model& base, int vectors)
    : detail::TangentInfo(makeTangentInfo(base, vectors)), Model(tangentInfo, base.parameters()), base_(base),
      n_(base.dimension()), m_(base.info().coreDimension), k_(vectors) {
  observables_ = base.observables(); // they read the base part of the state only: sections work unchanged
}

int TangentSystem::sheetOf(const Eigen::VectorXd& x, const MapPointSpec& spec) const {
  return base_.sheetOf(x.head(n_), spec);
}

void TangentSystem::rhs(const double* x, double* dx) const {
  base_.tangentRhs(x, x + n_, k_, dx, dx + n_);
}

bool TangentSystem::rk4Steps(Eigen::VectorXd& state, double h, long steps) const {
  return base_.tangentRk4(state.data(), state.data() + n_, k_, h, steps);
}

void TangentSystem::jacobian(const double*, double*) const {
  throw ComputationError("the Jacobian of the variational equations is not available");
}

} // namespace rv
