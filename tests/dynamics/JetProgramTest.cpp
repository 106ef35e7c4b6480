// JetProgramTest.cpp -- the recorded fields (dynamics/core/JetProgram.h) against the compiled ones: a rolling
// body's tangent vectors and Jacobians from its program equal Eigen's AutoDiff on its templated field bit for
// bit, and the interpreter on Lorenz's recorded field equals Lorenz's compiled lane kernels (Jet on lanes,
// inlined) and its AutoDiff path, lane by lane, bit for bit.
#include "dynamics/core/JetProgram.h"
#include "dynamics/models/BallOnEllipsoid.h"
#include "dynamics/models/EllipsoidOnPlane.h"
#include "dynamics/models/Lorenz.h"
#include "tests/dynamics/TestSupport.h"

#include <gtest/gtest.h>
#include <random>
#include <unsupported/Eigen/AutoDiff>
#include <vector>

namespace rv {
namespace {

// f and J V by AutoDiff on the model's compiled field (what ModelWithField computed before the programs)
template <class Body, int K>
void autoDiffTangents(const Body& body, const Eigen::VectorXd& x, const Eigen::MatrixXd& V,
                      Eigen::VectorXd& f, Eigen::MatrixXd& JV) {
  constexpr int N = Body::kDim, M = Body::kCore;
  using D = Eigen::Matrix<double, K, 1>;
  using AD = Eigen::AutoDiffScalar<D>;
  Eigen::Matrix<AD, N, 1> xa, fa;
  for (int i = 0; i < N; ++i) {
    D seed = D::Zero();
    if (i < M)
      for (int c = 0; c < K; ++c)
        seed[c] = V(i, c);
    xa[i] = AD(x[i], seed);
  }
  body.field(xa, fa);
  f.resize(N);
  JV.resize(M, K);
  for (int i = 0; i < N; ++i)
    f[i] = fa[i].value();
  for (int i = 0; i < M; ++i)
    for (int c = 0; c < K; ++c)
      JV(i, c) = fa[i].derivatives()[c];
}

template <class Body, int K> void expectProgramIsAutoDiff(const Body& body, const char* what) {
  constexpr int N = Body::kDim, M = Body::kCore;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 5; ++trial) {
    Eigen::VectorXd x(N);
    for (int i = 0; i < N; ++i)
      x[i] = u(random);
    x[5] = 2; // gamma3 (or the ball's contact normal) well away from 0
    Eigen::MatrixXd V(M, K);
    for (int i = 0; i < V.size(); ++i)
      V.data()[i] = u(random);
    Eigen::VectorXd f, dx(N);
    Eigen::MatrixXd JV, dV(M, K);
    autoDiffTangents<Body, K>(body, x, V, f, JV);
    body.tangentRhs(x.data(), V.data(), K, dx.data(), dV.data());
    for (int i = 0; i < N; ++i)
      EXPECT_EQ(dx[i], f[i]) << what << " f" << i;
    for (int i = 0; i < M * K; ++i)
      EXPECT_EQ(dV.data()[i], JV.data()[i]) << what << " JV" << i;
  }
}

TEST(JetProgram, ARollingBodysTangentsAreAutoDiffOnItsCompiledFieldBitForBit) {
  const EllipsoidOnPlane rattleback(ParameterValues(EllipsoidOnPlane::staticInfo().parameters));
  expectProgramIsAutoDiff<EllipsoidOnPlane, 1>(rattleback, "rattleback, 1 vector");
  expectProgramIsAutoDiff<EllipsoidOnPlane, 6>(rattleback, "rattleback, 6 vectors");
  // a ball whose field has a term that vanishes with its coefficient (c2 = 0: no division by x2^3) and one
  // that has it (c3)
  ParameterValues p(BallOnEllipsoid::staticInfo().parameters);
  p.set("c2", 0.0);
  p.set("c3", 0.02);
  const BallOnEllipsoid ball(p);
  expectProgramIsAutoDiff<BallOnEllipsoid, 4>(ball, "ball on an ellipsoid, 4 vectors");
}

TEST(JetProgram, JacobiansInPassesOfSixDirectionsAreAutoDiffsBitForBit) {
  const EllipsoidOnPlane body(ParameterValues(EllipsoidOnPlane::staticInfo().parameters));
  constexpr int N = EllipsoidOnPlane::kDim, M = EllipsoidOnPlane::kCore;
  Eigen::VectorXd x(N);
  for (int i = 0; i < N; ++i)
    x[i] = 0.1 * (i + 1) - 0.7;
  x[5] = 1.5;
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
  Eigen::Matrix<AD, N, 1> xa, fa;
  for (int i = 0; i < N; ++i)
    xa[i] = AD(x[i], N, i);
  body.field(xa, fa);
  Eigen::Matrix<double, N, N, Eigen::RowMajor> J;
  body.jacobian(x.data(), J.data());
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      EXPECT_EQ(J(i, j), fa[i].derivatives()[j]) << i << ", " << j;
  Eigen::Matrix<double, M, M, Eigen::RowMajor> core;
  body.coreJacobian(x.data(), core.data());
  for (int i = 0; i < M; ++i)
    for (int j = 0; j < M; ++j)
      EXPECT_EQ(core(i, j), fa[i].derivatives()[j]) << i << ", " << j;
  // the program keeps a rolling body's working set small: a slot is used again once its value is dead
  const JetProgram& program = body.jetProgram();
  EXPECT_GT(program.code().size(), 200u);
  EXPECT_LT(program.slotCount(), static_cast<int>(program.code().size()) / 4);
}

// Lorenz's field recorded with its coefficients as inputs (its own models compile it instead)
JetProgram recordedLorenz() {
  using jet_recording::Var;
  JetProgram program;
  {
    JetRecording recording(program, 3, 3);
    const Lorenz::Coefficients<jet_recording::Constant> c{program.coefficient(0), program.coefficient(1),
                                                          program.coefficient(2)};
    Eigen::Matrix<Var, 3, 1> x, dx;
    for (int i = 0; i < 3; ++i)
      x[i] = program.input(i);
    Lorenz::field(c, x, dx);
    for (int i = 0; i < 3; ++i)
      program.setOutput(i, dx[i]);
  }
  program.finish();
  return program;
}

TEST(JetProgram, TheInterpreterOnLorenzIsItsCompiledLaneKernelAndAutoDiffBitForBit) {
  const JetProgram program = recordedLorenz();
  std::vector<std::unique_ptr<Model>> models;
  std::vector<const Model*> lanes;
  std::vector<std::array<double, 3>> coefficients;
  std::vector<const double*> perLane;
  for (int l = 0; l < 4; ++l) {
    models.push_back(test::makeModel("lorenz", {{"rho", 20.0 + 3 * l}, {"sigma", 10 - 0.5 * l}}));
    lanes.push_back(models.back().get());
    const auto& c = dynamic_cast<const Lorenz&>(*models.back()).coefficients();
    coefficients.push_back({c.sigma, c.rho, c.beta});
  }
  for (const auto& c : coefficients)
    perLane.push_back(c.data());
  const std::vector<double> constants = program.bindConstants(perLane);
  const auto kernel = laneKernelFor(lanes);
  ASSERT_TRUE(kernel);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-10, 10);
  for (const int k : {0, 1, 3}) {
    std::vector<double> y(static_cast<std::size_t>(4 * (3 + 3 * k))), compiled(y.size()),
        interpreted(y.size());
    for (double& v : y)
      v = u(random);
    ASSERT_TRUE(kernel->tangentRhs(y.data(), k, compiled.data()));
    runJetProgram(program, constants.data(), 4, k, y.data(), y.data() + 12, 3, interpreted.data(),
                  interpreted.data() + 12, 3);
    for (std::size_t i = 0; i < y.size(); ++i)
      EXPECT_EQ(interpreted[i], compiled[i]) << "k = " << k << ", element " << i;
    if (k == 0) continue;
    std::vector<double> stepped = y, steppedHere = y;
    ASSERT_TRUE(kernel->tangentRk4(stepped.data(), k, 0.01, 50));
    rk4JetProgram(program, constants.data(), 4, k, 3, steppedHere.data(), 0.01, 50);
    for (std::size_t i = 0; i < y.size(); ++i)
      EXPECT_EQ(steppedHere[i], stepped[i]) << "RK4, k = " << k << ", element " << i;
    // one orbit: lane 2 alone, against the model's AutoDiff path
    std::vector<double> x(3), V(static_cast<std::size_t>(3 * k)), dx(3), dV(V.size()), dxHere(3),
        dVHere(V.size());
    for (int i = 0; i < 3; ++i)
      x[static_cast<std::size_t>(i)] = y[static_cast<std::size_t>(i * 4 + 2)];
    for (int i = 0; i < 3 * k; ++i)
      V[static_cast<std::size_t>(i)] = y[static_cast<std::size_t>((3 + i) * 4 + 2)];
    lanes[2]->tangentRhs(x.data(), V.data(), k, dx.data(), dV.data());
    const std::vector<double> one = program.bindConstants({perLane[2]});
    runJetProgram(program, one.data(), 1, k, x.data(), V.data(), 3, dxHere.data(), dVHere.data(), 3);
    EXPECT_EQ(dxHere, dx) << "k = " << k;
    EXPECT_EQ(dVHere, dV) << "k = " << k;
  }
}

TEST(JetProgram, MoreDirectionsThanOnePassCarriesGiveEachDirectionsDerivative) {
  const JetProgram program = recordedLorenz();
  const std::array<double, 3> c{10, 28, 8.0 / 3};
  const std::vector<double> constants = program.bindConstants({c.data()});
  const std::array<double, 3> x{1, -2, 20};
  // nine directions in two passes against each one alone
  std::vector<double> V(27), dx(3), dV(27);
  for (std::size_t i = 0; i < V.size(); ++i)
    V[i] = 0.1 * static_cast<double>(i) - 1;
  runJetProgram(program, constants.data(), 1, 9, x.data(), V.data(), 3, dx.data(), dV.data(), 3);
  for (int d = 0; d < 9; ++d) {
    std::array<double, 3> one{}, alone{};
    runJetProgram(program, constants.data(), 1, 1, x.data(), V.data() + 3 * d, 3, one.data(), alone.data(),
                  3);
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(dV[static_cast<std::size_t>(3 * d + i)], alone[static_cast<std::size_t>(i)])
          << d << ", " << i;
    EXPECT_EQ(std::vector<double>(one.begin(), one.end()), dx);
  }
}

TEST(JetProgram, AFieldThatLeavesAnOutputUnwrittenIsRefused) {
  JetProgram program;
  {
    JetRecording recording(program, 2, 0);
    program.setOutput(1, program.input(0) * 2.0);
  }
  EXPECT_THROW(program.finish(), std::logic_error);
}

} // namespace
} // namespace rv
