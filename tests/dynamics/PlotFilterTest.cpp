// The 2D / 3D plot filters' sampling (manual §2.4.1-2): output when the condition has changed by the period.
#include "dynamics/tools/PlotFilter.h"
#include "dynamics/core/Errors.h"
#include "dynamics/integrators/Everhart.h"
#include "dynamics/integrators/TimeSampler.h"
#include "tests/dynamics/TestSupport.h"

#include <cmath>
#include <gtest/gtest.h>

namespace rv {
namespace {

struct HenonHeilesRun {
  std::unique_ptr<Model> model = test::makeModel("henon_heiles", {{"energy", 0.125}});
  Everhart integrator{0.05, 15, 12};
  HenonHeilesRun() { integrator.start(*model, 0, model->stateFromMap({0.1, 0.1}, {}, "t")); }
};

TEST(PlotFilter, InTimeThePointsLandOnMultiplesOfThePeriod) {
  HenonHeilesRun r;
  PlotSettings s{
      .axes = {"t", "E", "x"}, .condition = "t", .period = 0.25, .maxPoints = 1000, .timeLimit = 20};
  const auto pts = samplePlot(*r.model, r.integrator, s, {});
  ASSERT_EQ(pts.size(), 81u); // t = 0, 0.25, ..., 20
  for (std::size_t k = 0; k < pts.size(); ++k) {
    ASSERT_EQ(pts[k].size(), 3u);
    EXPECT_NEAR(pts[k][0], 0.25 * k, 1e-12);
    EXPECT_NEAR(pts[k][1], 0.125, 1e-10) << "the energy, an integral, is the same at every point";
  }
  s.maxPoints = 10;
  HenonHeilesRun again;
  EXPECT_EQ(samplePlot(*again.model, again.integrator, s, {}).size(), 10u);
}

// the apex filter's feed: whole states at exact multiples of the period, step by step as a running map
// offers them, the same as sampling the dense output directly
TEST(PlotFilter, WholeStatesStepByStepAreTheDenseOutputAtTheMultiples) {
  HenonHeilesRun r, again;
  PlotSampler sampler(*r.model,
                      PlotSettings{.condition = "t", .period = 0.3, .maxPoints = 50, .wholeState = true});
  std::vector<std::vector<double>> got;
  while (got.size() < 50) {
    r.integrator.step();
    sampler.offerStep(r.integrator, [&](const std::vector<double>& v) { got.push_back(v); });
  }
  std::vector<Eigen::VectorXd> expected;
  sampleUniform(again.integrator, 0.3, 50, [&](double, const Eigen::VectorXd& x) {
    expected.push_back(x);
    return true;
  });
  ASSERT_EQ(got.size(), 50u);
  for (std::size_t k = 0; k < got.size(); ++k) {
    ASSERT_EQ(got[k].size(), std::size_t(r.model->dimension() + 1));
    EXPECT_NEAR(got[k][0], 0.3 * k, 1e-12);
    for (int i = 0; i < r.model->dimension(); ++i)
      EXPECT_NEAR(got[k][i + 1], expected[k][i], 1e-13);
  }
}

TEST(PlotFilter, ByAnObservableEachPointMovesItByThePeriod) {
  HenonHeilesRun r;
  PlotSettings s{.axes = {"y", "py"}, .condition = "y", .period = 0.05, .maxPoints = 200, .timeLimit = 50};
  const auto pts = samplePlot(*r.model, r.integrator, s, {});
  ASSERT_GT(pts.size(), 20u);
  for (std::size_t k = 1; k < pts.size(); ++k)
    EXPECT_GE(std::abs(pts[k][0] - pts[k - 1][0]), 0.05) << k;
  // a condition that never changes (the energy) ends at the time limit with the first point only
  HenonHeilesRun still;
  s.condition = "E";
  s.timeLimit = 5;
  EXPECT_EQ(samplePlot(*still.model, still.integrator, s, {}).size(), 1u);
  EXPECT_GE(still.integrator.time(), 5.0);
}

TEST(PlotFilter, BadSettingsNameTheField) {
  HenonHeilesRun r;
  const auto error = [&](PlotSettings s) {
    try {
      samplePlot(*r.model, r.integrator, s, {});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error({.axes = {"t", "nope"}}), "plot.y: unknown observable 'nope' of henon_heiles");
  EXPECT_EQ(error({.axes = {"t"}}), "plot.axes: give 2 or 3 observables");
  EXPECT_EQ(error({.condition = "q"}), "plot.condition: unknown observable 'q' of henon_heiles");
  EXPECT_EQ(error({.period = 0}), "plot.period: must be positive");
}

} // namespace
} // namespace rv
