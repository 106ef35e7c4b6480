// A chart's job stopped part-way goes on from its stop point when it runs again (no work done twice) and
// ends with the chart of an uninterrupted run, for every view that keeps its computation (SceneCharts.h
// ChartProgress); an edit of the scene starts it afresh.
#include "scenes/ChartTask.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <sstream>

namespace rv {
namespace {

using nlohmann::json;

struct Case {
  const char* view;
  json document;
  bool rows = true; ///< the chart's CSV has its points (a heat map has none: MapGrid's own tests compare it)
};

json lorenz() {
  return {{"problem", "lorenz"},
          {"integrator", {{"method", "rk4"}, {"step", 0.01}}},
          {"initial", {{"state", {{"x", 1}, {"y", 1}, {"z", 1}}}}},
          {"poincare", {{"section", "z"}, {"value", 27}, {"points", 60}}},
          {"lyapunov", {{"time", 40}, {"output_period", 0.5}}},
          {"megno", {{"time", 40}, {"output_period", 0.5}, {"interval", 0.5}}}};
}

json standardMap() {
  return {{"problem", "standard_map"},
          {"parameters", {{"K", 0.9}}},
          {"initial", {{"map", {3.0, 0.1}}}},
          {"poincare", {{"points", 400}}},
          {"grid",
           {{"x_min", 0},
            {"x_max", 6.2},
            {"y_min", -1},
            {"y_max", 1},
            {"step_x", 0.25},
            {"step_y", 0.1},
            {"threads", 1}}}};
}

std::string csvOf(const Chart& chart) {
  std::ostringstream out;
  chart.writeCsv(out);
  return out.str();
}

class ChartTaskResumes : public testing::TestWithParam<Case> {};

TEST_P(ChartTaskResumes, AStoppedChartGoesOnFromWhereItStopped) {
  const Case& c = GetParam();
  ChartTask whole(c.document, "case.json", c.view);
  ASSERT_TRUE(whole.run({}));
  const std::string expected = csvOf(*whole.chart());
  if (c.rows) {
    ASSERT_GT(std::count(expected.begin(), expected.end(), '\n'), 10) << expected;
  }

  ChartTask task(c.document, "case.json", c.view);
  double reached = 0;
  ToolControl stopHalfway;
  stopHalfway.progress = [&](double f) { reached = std::max(reached, f); };
  stopHalfway.stopRequested = [&] { return reached >= 0.4; };
  ASSERT_FALSE(task.run(stopHalfway));
  ASSERT_GE(reached, 0.4);
  ASSERT_LT(reached, 1.0);
  ASSERT_TRUE(task.chart()) << "a partial chart is kept";
  if (c.rows) {
    EXPECT_NE(csvOf(*task.chart()), expected);
  }

  double first = -1;
  ToolControl goOn;
  goOn.progress = [&](double f) {
    if (first < 0) first = f;
  };
  ASSERT_TRUE(task.run(goOn));
  EXPECT_GE(first, 0.4) << "the second run started again from the beginning";
  EXPECT_EQ(csvOf(*task.chart()), expected);
  EXPECT_EQ(task.completed(), 1);

  // an edit (here to the same scene) drops what was computed: the next run starts from the beginning
  reached = 0;
  ASSERT_FALSE(task.run(stopHalfway));
  task.edit(c.document);
  first = -1;
  ASSERT_TRUE(task.run(goOn));
  EXPECT_LT(first, 0.4);
  EXPECT_EQ(csvOf(*task.chart()), expected);
  EXPECT_EQ(task.completed(), 2);
}

INSTANTIATE_TEST_SUITE_P(Views, ChartTaskResumes,
                         testing::Values(Case{"lyapunov", lorenz()}, Case{"megno", lorenz()},
                                         Case{"poincare", lorenz()}, Case{"poincare", standardMap()},
                                         Case{"map3d", lorenz()}, Case{"surface", standardMap(), false}),
                         [](const testing::TestParamInfo<Case>& info) {
                           return std::string(info.param.view) + "_" +
                                  info.param.document["problem"].get<std::string>();
                         });

} // namespace
} // namespace rv
