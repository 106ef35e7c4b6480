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
  J_.resize(m_, m_);
  observables_ = base.observables(); // they read the base part of the state only: sections work unchanged
}

int TangentSystem::sheetOf(const Eigen::VectorXd& x, const MapPointSpec& spec) const {
  return base_.sheetOf(x.head(n_), spec);
}

void TangentSystem::rhs(const double* x, double* dx) const {
  base_.rhs(x, dx);
  // the core block of the Jacobian (the core evolves on its own, so it is all that tangent vectors need)
  base_.coreJacobian(x, J_.data()); // row-major m x m
  // dV = J V by plain loops: the sizes are tiny and a general matrix product costs more in dispatch than in
  // work
  const double* J = J_.data();
  for (int c = 0; c < k_; ++c) {
    const double* v = x + n_ + c * m_;
    double* dv = dx + n_ + c * m_;
    for (int i = 0; i < m_; ++i) {
      double sum = 0;
      for (int l = 0; l < m_; ++l)
        sum += J[i * m_ + l] * v[l];
      dv[i] = sum;
    }
  }
}

void TangentSystem::jacobian(const double*, double*) const {
  throw ComputationError("the Jacobian of the variational equations is not available");
}

} // namespace rv
