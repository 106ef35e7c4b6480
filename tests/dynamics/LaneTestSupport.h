// LaneTestSupport.h -- what the lane tests check of every kernel (dynamics/core/LaneField.h).
#pragma once
#include "dynamics/core/LaneField.h"
#include "dynamics/core/Model.h"

#include <gtest/gtest.h>
#include <random>
#include <string>
#include <vector>

namespace rv::test {

/// A kernel's f and J w at random states equal, lane by lane, each lane's model alone (Model::tangentRhs),
/// bit for bit; `lanes` holds the model of each of the kernel's lanes.
inline void expectKernelRhsIsEachModelAlone(const LaneKernel& kernel, const std::vector<const Model*>& lanes,
                                            std::mt19937& random, const std::string& what) {
  std::uniform_real_distribution<double> u(-2, 2);
  const int width = kernel.width(), n = lanes.front()->dimension(), m = lanes.front()->info().coreDimension;
  ASSERT_EQ(static_cast<int>(lanes.size()), width) << what;
  std::vector<double> y(static_cast<std::size_t>(width * (n + m))), out(y.size());
  for (double& v : y)
    v = u(random);
  kernel.tangentRhs(y.data(), out.data());
  const auto at = [width](int component, int lane) {
    return static_cast<std::size_t>(component * width + lane);
  };
  for (int l = 0; l < width; ++l) {
    Eigen::VectorXd x(n), w(m), dx(n), dw(m);
    for (int c = 0; c < n; ++c)
      x[c] = y[at(c, l)];
    for (int i = 0; i < m; ++i)
      w[i] = y[at(n + i, l)];
    lanes[static_cast<std::size_t>(l)]->tangentRhs(x.data(), w.data(), 1, dx.data(), dw.data());
    for (int c = 0; c < n; ++c)
      EXPECT_EQ(out[at(c, l)], dx[c]) << what << ", lane " << l << " f" << c;
    for (int i = 0; i < m; ++i)
      EXPECT_EQ(out[at(n + i, l)], dw[i]) << what << ", lane " << l << " Jw" << i;
  }
}

} // namespace rv::test
