// LaneTestSupport.h -- what the lane tests check of every kernel (dynamics/core/LaneField.h).
#pragma once
#include "dynamics/core/LaneField.h"
#include "dynamics/core/Model.h"
#include "tests/dynamics/TestSupport.h"

#include <gtest/gtest.h>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace rv::test {

/// A kernel's f and J V (k tangent vectors) at random states equal, lane by lane, each lane's model alone
/// (Model::tangentRhs), bit for bit; `lanes` holds the model of each of the kernel's lanes.
inline void expectKernelRhsIsEachModelAlone(const LaneKernel& kernel, const std::vector<const Model*>& lanes,
                                            std::mt19937& random, const std::string& what, int k = 1) {
  std::uniform_real_distribution<double> u(-2, 2);
  const int width = kernel.width(), n = lanes.front()->dimension(), m = lanes.front()->info().coreDimension;
  ASSERT_EQ(static_cast<int>(lanes.size()), width) << what;
  std::vector<double> y(static_cast<std::size_t>(width * (n + m * k))), out(y.size());
  for (double& v : y)
    v = u(random);
  ASSERT_TRUE(kernel.tangentRhs(y.data(), k, out.data())) << what << ", k = " << k;
  const auto at = [width](int component, int lane) {
    return static_cast<std::size_t>(component * width + lane);
  };
  for (int l = 0; l < width; ++l) {
    Eigen::VectorXd x(n), V(m * k), dx(n), dV(m * k);
    for (int c = 0; c < n; ++c)
      x[c] = y[at(c, l)];
    for (int i = 0; i < m * k; ++i)
      V[i] = y[at(n + i, l)];
    lanes[static_cast<std::size_t>(l)]->tangentRhs(x.data(), V.data(), k, dx.data(), dV.data());
    for (int c = 0; c < n; ++c)
      EXPECT_EQ(out[at(c, l)], dx[c]) << what << ", k = " << k << ", lane " << l << " f" << c;
    for (int i = 0; i < m * k; ++i)
      EXPECT_EQ(out[at(n + i, l)], dV[i]) << what << ", k = " << k << ", lane " << l << " JV" << i;
  }
}

/// Rattlebacks of eight shapes and turns (b2, psi): the sweep ellipsoid_lyapunov.json's points.
inline std::vector<std::unique_ptr<Model>> rattlebacks() {
  std::vector<std::unique_ptr<Model>> models;
  for (int l = 0; l < 8; ++l)
    models.push_back(makeModel("ellipsoid_on_plane", {{"b2", 0.3 + 0.12 * l}, {"psi", -0.3 + 0.08 * l}}));
  return models;
}

/// The first `count` of `models` (all of them: -1), as the lanes' models.
inline std::vector<const Model*> pointers(const std::vector<std::unique_ptr<Model>>& models,
                                          long count = -1) {
  std::vector<const Model*> p;
  for (const auto& m : models)
    if (count < 0 || static_cast<long>(p.size()) < count) p.push_back(m.get());
  return p;
}

} // namespace rv::test
