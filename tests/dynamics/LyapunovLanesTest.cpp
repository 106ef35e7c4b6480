// Lyapunov exponents on lanes (dynamics/tools/LyapunovLanes.h) and lanes of different parameters
// (LaneField.h's Coefficients): the lane kernels with one Lorenz model per lane equal each model's scalar
// tangent right-hand side and fused RK4 bit for bit; four orbits at four values of rho give each the scalar
// run's exponents bit for bit (an interval that is not a whole number of steps, taken alone, included); runs
// that converge early stop as alone; an orbit that blows up fails as it fails alone; what cannot go on lanes
// (the perturbed method, another integrator, too many exponents, lanes of two classes) says so. The
// rattleback (ellipsoid_on_plane, Coefficients of the body and its surface) on lanes: its kernel equals each
// model alone, and everhart at a fixed step (each lane's corrector converging on its own) gives each of eight
// (b2, psi) the scalar run's six exponents bit for bit, and so does adams (its starter run lane by lane). The
// paraboloid (paraboloid_on_plane, its Surface<T> of p, q, h) the same with everhart.
#include "dynamics/tools/LyapunovLanes.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/LaneField.h"
#include "dynamics/integrators/Adams.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Merson.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/models/BodyState.h"
#include "tests/dynamics/LaneTestSupport.h"
#include "tests/dynamics/TestSupport.h"

#include <gtest/gtest.h>
#include <random>

namespace rv {
namespace {

std::vector<std::unique_ptr<Model>> lorenzAt(const std::vector<double>& rhos) {
  std::vector<std::unique_ptr<Model>> models;
  for (double rho : rhos)
    models.push_back(test::makeModel("lorenz", {{"rho", rho}, {"sigma", 10 + rho / 100}}));
  return models;
}

using test::pointers;
using test::rattlebacks;

TEST(LyapunovLanes, KernelsWithAModelPerLaneEqualEachModelAloneBitForBit) {
  const auto all = lorenzAt({0.5, 13.9, 28, 250, 1, 24.5, 99, 160});
  const auto every = pointers(all);
  for (long count : {4, 8}) { // four lanes (AVX2) and eight (AVX-512)
    const std::vector<const Model*> models(every.begin(), every.begin() + count);
    const auto kernel = laneKernelFor(models);
    ASSERT_NE(kernel, nullptr);
    const int width = kernel->width();
    ASSERT_EQ(width, static_cast<int>(count));
    std::mt19937 random(11);
    std::uniform_real_distribution<double> u(-3, 3);
    const int n = 3, m = 3;
    test::expectKernelRhsIsEachModelAlone(*kernel, models, random, std::to_string(width) + " lanes");
    // fused RK4 with 1, 2 and 3 tangent vectors
    for (int k = 1; k <= 3; ++k) {
      const int size = n + m * k;
      std::vector<double> stacked(static_cast<std::size_t>(width * size));
      std::vector<Eigen::VectorXd> alone(width, Eigen::VectorXd(size));
      for (int l = 0; l < width; ++l)
        for (int j = 0; j < size; ++j)
          stacked[static_cast<std::size_t>(j * width + l)] = alone[static_cast<std::size_t>(l)][j] =
              j < n ? u(random) * 5 : u(random);
      ASSERT_TRUE(kernel->tangentRk4(stacked.data(), k, 1e-3, 700)) << k;
      for (int l = 0; l < width; ++l) {
        Eigen::VectorXd& a = alone[static_cast<std::size_t>(l)];
        ASSERT_TRUE(models[static_cast<std::size_t>(l)]->tangentRk4(a.data(), a.data() + n, k, 1e-3, 700));
        for (int j = 0; j < size; ++j)
          EXPECT_EQ(stacked[static_cast<std::size_t>(j * width + l)], a[j]) << "k " << k << " lane " << l;
      }
    }
    EXPECT_FALSE(kernel->tangentRk4(nullptr, 4, 1e-3, 0)) << "more vectors than the core dimension";
  }
}

TEST(LyapunovLanes, ValuesOfRhoGiveEachTheScalarRunsExponentsBitForBit) {
  const auto models = lorenzAt({10, 24, 28, 160, 5, 20, 35, 99});
  const IntegratorFactory rk4 = [] { return std::make_unique<Rk4>(0.002); };
  LyapunovSettings s;
  s.maxTime = 30.001; // the last interval, 0.001, is not a whole number of steps: each run takes it alone
  s.interval = 0.5;
  std::vector<Eigen::VectorXd> x0s;
  for (int l = 0; l < 8; ++l)
    x0s.push_back(Eigen::Vector3d(1 + l, 1, 20 - l));
  ASSERT_TRUE(lyapunovRunsOnLanes(pointers(models), rk4, s));
  const auto lanes = lyapunovOnLanes(pointers(models), rk4, x0s, s); // eight lanes
  ASSERT_TRUE(lanes.has_value());
  ASSERT_EQ(lanes->size(), 8u);
  for (std::size_t l = 0; l < 8; ++l) {
    ASSERT_FALSE((*lanes)[l].failure) << l;
    const LyapunovResult alone = lyapunovExponents(*models[l], rk4, x0s[l], s);
    EXPECT_EQ((*lanes)[l].result.last.exponents, alone.last.exponents) << "rho lane " << l;
    EXPECT_EQ((*lanes)[l].result.last.time, alone.last.time) << l;
  }
  // rho = 28 is chaotic, rho = 10 settles on a fixed point: the largest exponent says so already at t = 30
  EXPECT_GT((*lanes)[2].result.last.exponents[0], 0.5);
  EXPECT_LT((*lanes)[0].result.last.exponents[0], 0);
  // fewer orbits than lanes, two exponents of each, estimates compared for an early stop
  s.count = 2, s.successes = 3, s.accuracy = 0.05, s.estimateEvery = 4;
  const std::vector<const Model*> two{models[0].get(), models[3].get()};
  const std::vector<Eigen::VectorXd> twoStarts{x0s[0], x0s[3]};
  const auto pair = lyapunovOnLanes(two, rk4, twoStarts, s);
  ASSERT_TRUE(pair.has_value());
  ASSERT_EQ(pair->size(), 2u);
  for (std::size_t l = 0; l < 2; ++l) {
    const LyapunovResult alone = lyapunovExponents(*two[l], rk4, twoStarts[l], s);
    EXPECT_EQ((*pair)[l].result.converged, alone.converged) << l;
    EXPECT_EQ((*pair)[l].result.last.exponents, alone.last.exponents) << l;
    EXPECT_EQ((*pair)[l].result.last.time, alone.last.time) << l;
  }
  EXPECT_TRUE((*pair)[0].result.converged) << "pick settings under which the fixed point converges early";
}

TEST(LyapunovLanes, AnOrbitThatBlowsUpFailsAsAloneAndTheOthersKeepTheirExponents) {
  // Henon-Heiles above the escape energy 1/6: an orbit leaving through a saddle runs off to infinity
  const auto model = test::makeModel("henon_heiles", {});
  const IntegratorFactory rk4 = [] { return std::make_unique<Rk4>(0.01); };
  const IntegratorFactory everhart = [] { return std::make_unique<Everhart>(0.02, 15, 12); };
  LyapunovSettings s;
  s.maxTime = 40, s.interval = 1;
  const auto state = [](double e, double y, double py) {
    Eigen::VectorXd x(4);
    x << 0, y, std::sqrt(std::max(0.0, 2 * e - py * py - y * y + 2 * y * y * y / 3)), py;
    return x;
  };
  const std::vector<Eigen::VectorXd> x0s{state(0.1, 0.1, 0.1), state(0.3, 0.6, 0.3), state(0.1, -0.2, 0.05)};
  for (const auto& method : {rk4, everhart}) {
    const auto lanes = lyapunovOnLanes(std::vector<const Model*>(3, model.get()), method, x0s, s);
    ASSERT_TRUE(lanes.has_value());
    int failed = 0;
    for (std::size_t l = 0; l < x0s.size(); ++l) {
      std::string aloneFailure;
      LyapunovResult alone;
      try {
        alone = lyapunovExponents(*model, method, x0s[l], s);
      } catch (const ComputationError& e) {
        aloneFailure = e.what();
      }
      std::string laneFailure;
      if ((*lanes)[l].failure) {
        try {
          std::rethrow_exception((*lanes)[l].failure);
        } catch (const ComputationError& e) {
          laneFailure = e.what();
        }
      }
      EXPECT_EQ(laneFailure, aloneFailure) << l;
      failed += aloneFailure.empty() ? 0 : 1;
      if (aloneFailure.empty()) {
        EXPECT_EQ((*lanes)[l].result.last.exponents, alone.last.exponents) << l;
      }
    }
    EXPECT_EQ(failed, 1) << "the orbit above the escape energy should blow up, the others not";
  }
}

TEST(LyapunovLanes, WhatCannotGoOnLanesSaysSo) {
  const auto models = lorenzAt({10, 28});
  const auto ps = pointers(models);
  const IntegratorFactory rk4 = [] { return std::make_unique<Rk4>(0.01); };
  const IntegratorFactory merson = [] { return std::make_unique<Merson>(0.01, 1e-9, 1e-12, 1.0); };
  LyapunovSettings s;
  const IntegratorFactory everhart = [] { return std::make_unique<Everhart>(0.01, 15, 12); };
  const IntegratorFactory adaptive = [] { return std::make_unique<Everhart>(0.01, 15, 12, 1e-9); };
  EXPECT_TRUE(lyapunovRunsOnLanes(ps, rk4, s));
  EXPECT_TRUE(lyapunovRunsOnLanes(ps, everhart, s));
  EXPECT_TRUE(lyapunovRunsOnLanes(
      ps, [] { return std::make_unique<Adams>(0.01, 8); }, s));
  EXPECT_TRUE(lyapunovRunsOnLanes(ps, merson, s)) << "an error control of each lane's own";
  EXPECT_FALSE(lyapunovRunsOnLanes(ps, adaptive, s)) << "an adaptive step: each run alone";
  s.mode = LyapunovSettings::Mode::Perturbed;
  EXPECT_FALSE(lyapunovRunsOnLanes(ps, rk4, s));
  const auto hh = test::makeModel("henon_heiles", {});
  EXPECT_FALSE(lyapunovRunsOnLanes({models[0].get(), hh.get()}, rk4, {})) << "two classes";
  const auto map = test::makeModel("standard_map", {});
  EXPECT_FALSE(lyapunovRunsOnLanes({map.get()}, rk4, {})) << "a map";
}

// the lane kernels of the first 4 and of all 8 models, with 1, 3 and 6 tangent directions, against each alone
void expectKernelsAreEachModelAlone(const std::vector<std::unique_ptr<Model>>& all, const std::string& what) {
  const auto every = pointers(all);
  std::mt19937 random(5);
  for (long count : {4, 8}) {
    const std::vector<const Model*> models(every.begin(), every.begin() + count);
    const auto kernel = laneKernelFor(models);
    ASSERT_NE(kernel, nullptr);
    for (int k : {1, 3, models.front()->info().coreDimension}) // up to every direction of the core
      test::expectKernelRhsIsEachModelAlone(*kernel, models, random, std::to_string(count) + " " + what, k);
  }
}

TEST(LyapunovLanes, RattlebackKernelsWithAModelPerLaneEqualEachModelAloneBitForBit) {
  expectKernelsAreEachModelAlone(rattlebacks(), "rattlebacks");
}

// paraboloids of eight heights and turns (h, delta): the paraboloid's Surface<T> runs on lanes too
std::vector<std::unique_ptr<Model>> paraboloids() {
  std::vector<std::unique_ptr<Model>> models;
  for (int l = 0; l < 8; ++l)
    models.push_back(test::makeModel("paraboloid_on_plane",
                                     {{"h", 0.3 + 0.07 * l}, {"delta", 0.05 * l}, {"q", 1.5 + 0.1 * l}}));
  return models;
}

TEST(LyapunovLanes, ParaboloidKernelsWithAModelPerLaneEqualEachModelAloneBitForBit) {
  expectKernelsAreEachModelAlone(paraboloids(), "paraboloids");
}

// `starts`: one state per model (none: rigid bodies' states on the plane)
void expectExponentsAreTheScalarRuns(const std::vector<std::unique_ptr<Model>>& models,
                                     const IntegratorFactory& everhart,
                                     std::vector<Eigen::VectorXd> starts = {}) {
  LyapunovSettings s;
  s.maxTime = 6.5; // a last interval of half the others
  s.interval = 1;
  std::vector<Eigen::VectorXd> x0s = std::move(starts);
  for (int l = static_cast<int>(x0s.size()); l < 8; ++l)
    x0s.push_back(body_state::fromMomentumAndVertical(Eigen::Vector3d(0.01 * l, 0, -0.3),
                                                      Eigen::Vector3d(0, 0.02 + 0.01 * l, 1).normalized()));
  // a rolling body's whole spectrum runs one orbit at a time (its lanes interpret six directions, slower than
  // one orbit's compiled AutoDiff pass: LaneKernel::compiledFor); the largest exponent, what a sweep asks,
  // runs on lanes
  ASSERT_FALSE(lyapunovRunsOnLanes(pointers(models), everhart, s));
  s.count = 1;
  ASSERT_TRUE(lyapunovRunsOnLanes(pointers(models), everhart, s));
  const auto lanes = lyapunovOnLanes(pointers(models), everhart, x0s, s);
  ASSERT_TRUE(lanes.has_value());
  ASSERT_EQ(lanes->size(), 8u);
  for (std::size_t l = 0; l < 8; ++l) {
    ASSERT_FALSE((*lanes)[l].failure) << l;
    const LyapunovResult alone = lyapunovExponents(*models[l], everhart, x0s[l], s);
    ASSERT_EQ(alone.last.exponents.size(), 1u);
    EXPECT_EQ((*lanes)[l].result.last.exponents, alone.last.exponents) << models[l]->info().id << " " << l;
    EXPECT_EQ((*lanes)[l].result.last.time, alone.last.time) << l;
  }
  // three orbits, the fourth lane repeating the last
  const std::vector<const Model*> three{models[1].get(), models[4].get(), models[6].get()};
  const std::vector<Eigen::VectorXd> threeStarts{x0s[1], x0s[4], x0s[6]};
  const auto some = lyapunovOnLanes(three, everhart, threeStarts, s);
  ASSERT_TRUE(some.has_value());
  for (std::size_t l = 0; l < 3; ++l)
    EXPECT_EQ((*some)[l].result.last.exponents,
              lyapunovExponents(*three[l], everhart, threeStarts[l], s).last.exponents)
        << l;
}

TEST(LyapunovLanes, RattlebackExponentsWithEverhartAreTheScalarRunsBitForBit) {
  expectExponentsAreTheScalarRuns(rattlebacks(), [] { return std::make_unique<Everhart>(0.01, 15, 12); });
}

TEST(LyapunovLanes, ParaboloidExponentsWithEverhartAreTheScalarRunsBitForBit) {
  expectExponentsAreTheScalarRuns(paraboloids(), [] { return std::make_unique<Everhart>(0.01, 15, 12); });
}

// Chaplygin balls of eight inertias, gyrostats and masses: the ball's Coefficients (J^-1, K, D, R) run on
// lanes, each lane its own ball's field, its derivatives and its exponents bit for bit
std::vector<std::unique_ptr<Model>> chaplyginBalls() {
  std::vector<std::unique_ptr<Model>> models;
  for (int l = 0; l < 8; ++l)
    models.push_back(test::makeModel("chaplygin_ball", {{"I1", 1.0 + 0.05 * l},
                                                        {"I2", 1.4 - 0.03 * l},
                                                        {"I3", 1.9 + 0.02 * l},
                                                        {"K1", 0.1 * l},
                                                        {"K3", 0.3 - 0.05 * l},
                                                        {"m", 1 + 0.1 * l}}));
  return models;
}

TEST(LyapunovLanes, ChaplyginBallKernelsWithAModelPerLaneEqualEachModelAloneBitForBit) {
  expectKernelsAreEachModelAlone(chaplyginBalls(), "Chaplygin balls");
}

TEST(LyapunovLanes, ChaplyginBallExponentsWithEverhartAreTheScalarRunsBitForBit) {
  expectExponentsAreTheScalarRuns(chaplyginBalls(), [] { return std::make_unique<Everhart>(0.01, 15, 12); });
}

// Balls on an ellipsoid of eight shapes, masses and fields, and in eight bowls (perturbed and not): the
// balls' Coefficients run on lanes, each lane its own ball's field, derivatives and exponents bit for bit
std::vector<std::unique_ptr<Model>> ballsOnSurfaces(const char* id) {
  std::vector<std::unique_ptr<Model>> models;
  for (int l = 0; l < 8; ++l)
    models.push_back(std::string(id) == "ball_on_ellipsoid"
                         ? test::makeModel(id, {{"b1", 1.5 + 0.05 * l},
                                                {"b3", 0.8 + 0.01 * l},
                                                {"R", 0.2},
                                                {"mu", 0.4 + 0.01 * l},
                                                {"k", 0.1 * l},
                                                {"c2", l % 2 == 0 ? 0.0 : 0.01 * l}})
                         : test::makeModel(id, {{"p", 1.0 + 0.1 * l},
                                                {"D", 1.0 - 0.05 * l},
                                                {"Lambda1", 0.02 * l},
                                                {"Lambda3", l % 3 == 0 ? 0.0 : -0.03}}));
  return models;
}

TEST(LyapunovLanes, BallsOnSurfacesKernelsWithAModelPerLaneEqualEachModelAloneBitForBit) {
  expectKernelsAreEachModelAlone(ballsOnSurfaces("ball_on_ellipsoid"), "balls on ellipsoids");
  expectKernelsAreEachModelAlone(ballsOnSurfaces("ball_on_paraboloid"), "balls in bowls");
}

TEST(LyapunovLanes, BallsOnSurfacesExponentsWithEverhartAreTheScalarRunsBitForBit) {
  const IntegratorFactory everhart = [] { return std::make_unique<Everhart>(0.02, 15, 12); };
  const auto onEllipsoids = ballsOnSurfaces("ball_on_ellipsoid"),
             inBowls = ballsOnSurfaces("ball_on_paraboloid");
  std::vector<Eigen::VectorXd> onEllipsoid, inBowl;
  for (int l = 0; l < 8; ++l) {
    onEllipsoid.push_back(onEllipsoids[static_cast<std::size_t>(l)]->stateFromNamed({{"M1", 0.3 + 0.01 * l},
                                                                                     {"M2", 0.8},
                                                                                     {"M3", 0.2},
                                                                                     {"gamma1", 0.3},
                                                                                     {"gamma2", -0.2},
                                                                                     {"gamma3", 0.9}},
                                                                                    "t"));
    inBowl.push_back(inBowls[static_cast<std::size_t>(l)]->stateFromNamed(
        {{"omega1", 0.3}, {"omega2", 0.1 + 0.02 * l}, {"omega3", 0.2}, {"x1", 0.2}, {"x2", -0.1}}, "t"));
  }
  expectExponentsAreTheScalarRuns(onEllipsoids, everhart, onEllipsoid);
  expectExponentsAreTheScalarRuns(inBowls, everhart, inBowl);
}

// Adams starts each interval's run orbit by orbit, on each lane's own tangent system (LaneStack::laneSystem)
TEST(LyapunovLanes, RattlebackExponentsWithAdamsAreTheScalarRunsBitForBit) {
  expectExponentsAreTheScalarRuns(rattlebacks(), [] { return std::make_unique<Adams>(0.005, 12); });
}

// Merson's steps are each lane's own (its error control reads the lane's orbit alone)
TEST(LyapunovLanes, RattlebackExponentsWithMersonAreTheScalarRunsBitForBit) {
  expectExponentsAreTheScalarRuns(rattlebacks(),
                                  [] { return std::make_unique<Merson>(0.01, 1e-10, 1e-10, 0.1); });
}

} // namespace
} // namespace rv
