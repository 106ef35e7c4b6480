// Plain orbits on lanes (dynamics/tools/TrajectoryLanes.h): every step of every orbit, as integrating that
// orbit alone gives it (the loop of a sweep's trajectory quantity, scenes/builtin/SweepTool.cpp's
// integrateTo), bit for bit -- rattlebacks of eight shapes with rk4, everhart at a fixed step and adams; what
// cannot go on lanes says so; a batch with an orbit that blows up fails, for its orbits to be integrated
// alone. Their Poincare points, each orbit's map alone's.
#include "dynamics/tools/TrajectoryLanes.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/LaneField.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Adams.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/Merson.h"
#include "dynamics/integrators/Rk4.h"
#include "dynamics/integrators/Verner9.h"
#include "dynamics/models/BodyState.h"
#include "tests/dynamics/LaneTestSupport.h"
#include "tests/dynamics/TestSupport.h"

#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <tuple>

namespace rv {
namespace {

// a step as the loop hands it
using Step = std::tuple<double, Eigen::VectorXd, double, Eigen::VectorXd>;

// the orbit alone, as a sweep integrates it one point at a time: each step from its start to its end, the
// last cut at `time` by the dense output
std::vector<Step> stepsAlone(const Model& model, const IntegratorFactory& make, const Eigen::VectorXd& x0,
                             double time) {
  std::vector<Step> steps;
  auto integ = make();
  integ->start(model, 0.0, x0);
  Eigen::VectorXd previous = integ->state(), end;
  double tPrevious = integ->time();
  while (tPrevious < time) {
    integ->step();
    if (integ->time() >= time) {
      integ->interpolate(time, end);
      steps.emplace_back(tPrevious, previous, time, end);
      break;
    }
    steps.emplace_back(tPrevious, previous, integ->time(), integ->state());
    previous = integ->state();
    tPrevious = integ->time();
  }
  return steps;
}

using test::pointers;
using test::rattlebacks;

void expectEachOrbitIsAlone(const IntegratorFactory& make, const std::string& method) {
  const auto models = rattlebacks();
  std::vector<Eigen::VectorXd> x0s;
  for (int l = 0; l < 8; ++l)
    x0s.push_back(body_state::fromMomentumAndVertical(Eigen::Vector3d(0.01 * l, 0, -0.3 + 0.05 * l),
                                                      Eigen::Vector3d(0, 0.02 + 0.01 * l, 1).normalized()));
  const double time = 7.3; // not a whole number of steps: the last step is cut
  for (std::size_t count : {3, 8}) {
    const auto lanes = pointers(models, count);
    ASSERT_TRUE(trajectoriesRunOnLanes(lanes, make)) << method;
    const std::vector<Eigen::VectorXd> starts(x0s.begin(), x0s.begin() + static_cast<long>(count));
    std::vector<std::vector<Step>> seen(count);
    ASSERT_TRUE(integrateOnLanes(
        lanes, make, starts, time, {},
        [&](int lane, double t0, const Eigen::VectorXd& a, double t1, const Eigen::VectorXd& b) {
          seen[static_cast<std::size_t>(lane)].emplace_back(t0, a, t1, b);
        }));
    for (std::size_t l = 0; l < count; ++l) {
      const auto alone = stepsAlone(*models[l], make, x0s[l], time);
      ASSERT_EQ(seen[l].size(), alone.size()) << method << ", orbit " << l;
      EXPECT_EQ(std::get<2>(seen[l].back()), time);
      for (std::size_t k = 0; k < alone.size(); ++k)
        ASSERT_TRUE(seen[l][k] == alone[k])
            << method << ", " << count << " orbits, orbit " << l << ", step " << k;
    }
  }
}

TEST(TrajectoryLanes, EveryStepOfEachOrbitIsItsStepAloneBitForBit) {
  expectEachOrbitIsAlone([] { return std::make_unique<Rk4>(0.01); }, "rk4");
  expectEachOrbitIsAlone([] { return std::make_unique<Everhart>(0.02, 15, 12); }, "everhart");
  expectEachOrbitIsAlone([] { return std::make_unique<Adams>(0.01, 12); }, "adams");
}

// the orbits' stack evaluates each lane's field as the kernel's f alone (no tangent direction): for every
// registered model with a lane kernel, that f is the model's own right-hand side (Model::rhs) bit for bit,
// and the f of the kernel with a tangent direction too
TEST(TrajectoryLanes, TheKernelsFieldIsEachModelsRightHandSide) {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int kernels = 0;
  for (const auto& entry : ModelRegistry::global().entries()) {
    const auto model = entry.create(ParameterValues(entry.info->parameters));
    const auto kernel = laneKernelFor({model.get()});
    if (!kernel) continue;
    ++kernels;
    const int width = kernel->width(), n = model->dimension(), m = model->info().coreDimension;
    std::vector<double> in(static_cast<std::size_t>((n + m) * width), 0.0), out(in.size()),
        alone(static_cast<std::size_t>(n * width));
    for (int trial = 0; trial < 20; ++trial) {
      for (int i = 0; i < n * width; ++i)
        in[static_cast<std::size_t>(i)] = u(random);
      ASSERT_TRUE(kernel->tangentRhs(in.data(), 0, alone.data()));
      ASSERT_TRUE(kernel->tangentRhs(in.data(), 1, out.data()));
      for (int l = 0; l < width; ++l) {
        Eigen::VectorXd x(n), f(n);
        for (int c = 0; c < n; ++c)
          x[c] = in[static_cast<std::size_t>(c * width + l)];
        model->rhs(x.data(), f.data());
        for (int c = 0; c < n; ++c) {
          const auto i = static_cast<std::size_t>(c * width + l);
          ASSERT_EQ(alone[i], f[c]) << entry.info->id << " f" << c;
          ASSERT_EQ(out[i], f[c]) << entry.info->id << " f" << c << " beside a tangent direction";
        }
      }
    }
  }
  // henon_heiles, lorenz, ellipsoid_on_plane, paraboloid_on_plane, chaplygin_ball, ball_on_ellipsoid,
  // ball_on_paraboloid
  EXPECT_GE(kernels, 7);
}

// each orbit's map points, as a PoincareMap of that orbit alone finds them, bit for bit (the crossing located
// on the stack's dense output read at the orbit's lane)
void expectMapPointsAreEachMapsAlone(const std::vector<const Model*>& models,
                                     const std::vector<Eigen::VectorXd>& x0s, const IntegratorFactory& make,
                                     const SectionSettings& settings, const std::string& what) {
  const auto lanes = mapPointsOnLanes(models, make, x0s, settings);
  ASSERT_TRUE(lanes.has_value()) << what;
  ASSERT_EQ(lanes->size(), x0s.size()) << what;
  for (std::size_t l = 0; l < x0s.size(); ++l) {
    auto integ = make();
    integ->start(*models[l], 0, x0s[l], settings.backward ? -1 : +1);
    PoincareMap map(*models[l], std::move(integ), settings);
    std::vector<MapPoint> alone;
    while (auto p = map.next())
      alone.push_back(*p);
    ASSERT_GT(alone.size(), 3u) << what << ", orbit " << l;
    ASSERT_EQ((*lanes)[l].size(), alone.size()) << what << ", orbit " << l;
    for (std::size_t k = 0; k < alone.size(); ++k) {
      ASSERT_EQ((*lanes)[l][k].coordinates, alone[k].coordinates)
          << what << ", orbit " << l << ", point " << k;
      ASSERT_EQ((*lanes)[l][k].time, alone[k].time) << what << ", orbit " << l << ", point " << k;
      ASSERT_EQ((*lanes)[l][k].sheet, alone[k].sheet) << what << ", orbit " << l << ", point " << k;
    }
  }
}

TEST(TrajectoryLanes, EachOrbitsMapPointsAreItsMapsAloneBitForBit) {
  // Henon-Heiles at E = 1/8 on x = 0 (tori and chaos), everhart at a fixed step; forward and backward
  const auto hh = test::makeModel("henon_heiles", {{"energy", 0.125}});
  std::vector<Eigen::VectorXd> starts;
  for (int l = 0; l < 8; ++l) {
    const double y = -0.3 + 0.08 * l, py = 0.05 * (l % 3) - 0.05;
    Eigen::VectorXd x(4);
    x << 0, y, std::sqrt(0.25 - py * py - y * y + 2 * y * y * y / 3), py;
    starts.push_back(x);
  }
  SectionSettings s;
  s.maxPoints = 40, s.maxTime = 5000; // an orbit that never crossed would end there (and fail below)
  const IntegratorFactory everhart = [] { return std::make_unique<Everhart>(0.05, 15, 12); };
  for (std::size_t count : {3, 8}) {
    const std::vector<const Model*> models(count, hh.get());
    const std::vector<Eigen::VectorXd> some(starts.begin(), starts.begin() + static_cast<long>(count));
    expectMapPointsAreEachMapsAlone(models, some, everhart, s, "henon_heiles, " + std::to_string(count));
  }
  SectionSettings back = s;
  back.backward = true;
  expectMapPointsAreEachMapsAlone(std::vector<const Model*>(8, hh.get()), starts, everhart, back, "backward");
  // the maps end at max_time with fewer points than asked, each as alone; rk4, both directions of crossing
  SectionSettings timed = s;
  timed.maxPoints = 1000, timed.maxTime = 30, timed.checkDirection = false;
  expectMapPointsAreEachMapsAlone(
      std::vector<const Model*>(8, hh.get()), starts, [] { return std::make_unique<Rk4>(0.01); }, timed,
      "max_time");
  // Lorenz at eight values of rho (a parameter per lane) on z = 27, adams
  std::vector<std::unique_ptr<Model>> lorenz;
  std::vector<Eigen::VectorXd> x0s;
  for (int l = 0; l < 8; ++l) {
    lorenz.push_back(test::makeModel("lorenz", {{"rho", 26.0 + 2 * l}}));
    x0s.push_back(Eigen::Vector3d(1 + 0.1 * l, 1, 1));
  }
  SectionSettings z;
  z.observable = "z", z.value = 27, z.maxPoints = 30, z.maxTime = 5000;
  expectMapPointsAreEachMapsAlone(
      pointers(lorenz, 8), x0s, [] { return std::make_unique<Adams>(0.005, 12); }, z, "lorenz");
}

TEST(TrajectoryLanes, WhatCannotGoOnLanesSaysSo) {
  const auto models = rattlebacks();
  const auto four = pointers(models, 4);
  EXPECT_FALSE(trajectoriesRunOnLanes(four, [] { return std::make_unique<Merson>(0.01, 1e-10, 1e-10, 0.1); }))
      << "each lane at a time of its own";
  EXPECT_FALSE(trajectoriesRunOnLanes(four, [] { return std::make_unique<Everhart>(0.01, 15, 12, 1e-9); }))
      << "an adaptive step for all";
  EXPECT_FALSE(trajectoriesRunOnLanes(four, [] { return std::make_unique<Verner9>(1e-12, 0.01); }));
  const auto map = test::makeModel("standard_map", {});
  EXPECT_FALSE(trajectoriesRunOnLanes({map.get()}, [] { return std::make_unique<Rk4>(0.01); })) << "a map";
  const auto hh = test::makeModel("henon_heiles", {});
  EXPECT_FALSE(trajectoriesRunOnLanes({models[0].get(), hh.get()}, [] {
    return std::make_unique<Rk4>(0.01);
  })) << "two classes";
}

// above the escape energy an orbit of Henon-Heiles runs off to infinity in finite time: the batch fails (the
// sweep then integrates each orbit alone, where it fails or not as alone)
TEST(TrajectoryLanes, ABatchWithAnOrbitThatBlowsUpFails) {
  const auto hh = test::makeModel("henon_heiles", {});
  const auto rk4 = [] { return std::make_unique<Rk4>(0.01); };
  Eigen::VectorXd bound(4), escaping(4);
  bound << 0, 0.1, 0.3, 0.1;
  escaping << 0, 0.6, 0.6, 0.3;
  EXPECT_THROW(stepsAlone(*hh, rk4, escaping, 60), ComputationError);
  EXPECT_THROW(integrateOnLanes({hh.get(), hh.get()}, rk4, {bound, escaping}, 60, {},
                                [](int, double, const Eigen::VectorXd&, double, const Eigen::VectorXd&) {}),
               ComputationError);
}

} // namespace
} // namespace rv
