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

#include "dynamics/core/Errors.h"
#include "scenes/BuiltinTools.h"
#include "scenes/SceneLoader.h"
#include "scenes/ToolTask.h"

namespace rv {
namespace {

// A registered tool as a job: the first of its alternative scenes that does not fail gives the result (the
// sweep window's bifurcation curve: toward one end of the axis, else toward the other).
TEST(ToolTask, RunsTheFirstAlternativeThatDoesNotFail) {
  registerBuiltinTools();
  const auto henon = [](double to) {
    nlohmann::json d = nlohmann::json::parse(R"json({
      "problem": "henon_map", "parameters": {"a": 0.6, "b": 0.25}, "initial": {"map": [0.63, 0.19]},
      "continuation": {"parameter": "a", "step": 0.02},
      "bifurcation_curve": {"second_parameter": "b", "kind": "period_doubling", "second_min": -0.5,
                            "second_max": 0.5, "first_min": 0, "first_max": 1.5}})json");
    d["continuation"]["to"] = to;
    d["continuation"]["step"] = to > 0.6 ? 0.02 : -0.02;
    return d;
  };
  ToolTask task("bifurcation_curve", {henon(1.5), henon(0)}, "test");
  EXPECT_EQ(task.used(), -1);
  EXPECT_FALSE(task.result());
  ASSERT_TRUE(task.run({}));
  EXPECT_EQ(task.used(), 1); // up in a from 0.6 there is no doubling; down there is, at a = 3 (1 - b)^2 / 4
  const auto r = task.result();
  ASSERT_TRUE(r);
  ASSERT_GE(r->table.names.size(), 2u);
  EXPECT_NEAR(r->fields["start"]["a"].get<double>(), 0.75 * 0.75 * 0.75, 1e-9);
  for (long i = 0; i < r->table.rows(); ++i) {
    const double a = r->table.values[0][static_cast<std::size_t>(i)],
                 b = r->table.values[1][static_cast<std::size_t>(i)];
    EXPECT_NEAR(a, 0.75 * (1 - b) * (1 - b), 1e-8);
  }
  task.reset();
  EXPECT_FALSE(task.result());
  ToolTask none("bifurcation_curve", {henon(1.5)}, "test");
  try {
    none.run({});
    ADD_FAILURE() << "a period doubling above a = 0.6";
  } catch (const ComputationError& e) {
    EXPECT_NE(std::string(e.what()).find("finds no period doubling point"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ToolTask("sweep", {henon(0)}, "test"), InputError); // no runner: it runs over many scenes
  EXPECT_THROW(ToolTask("bifurcation_curve", {}, "test"), InputError);
}

nlohmann::json standardMapFamily() {
  return nlohmann::json::parse(R"json({
    "problem": "standard_map", "parameters": {"K": 1.5}, "initial": {"map": [3.0, 0.1]},
    "fixedpoint": {"guess": [3.1, 0.05]}, "continuation": {"parameter": "K", "to": 4.5, "step": 0.1}})json");
}

// the rows and notes of a run stream out as they are computed (the map window draws them so): every row of
// the result's table, in order, bit for bit, with its type; every note
TEST(ToolTask, StreamsEachRowAndNoteAsItIsComputed) {
  registerBuiltinTools();
  for (const char* tool : {"continuation", "bifurcation_tree"}) {
    ToolTask task(tool, {standardMapFamily()}, "test", false);
    EXPECT_FALSE(task.ownsItsScene());
    ASSERT_TRUE(task.run({})) << tool;
    const auto r = task.result();
    ASSERT_TRUE(r);
    std::vector<ToolTask::RunRow> rows;
    task.rows().take(rows);
    ASSERT_EQ(static_cast<long>(rows.size()), r->table.rows()) << tool;
    ASSERT_GT(rows.size(), 5u);
    for (std::size_t i = 0; i < rows.size(); ++i) {
      EXPECT_EQ(rows[i].run, 1);
      EXPECT_EQ(rows[i].row.names, r->table.names);
      EXPECT_EQ(rows[i].row.values, r->table.row(static_cast<long>(i))) << tool << " row " << i;
      ASSERT_EQ(rows[i].row.textNames, std::vector<std::string>{"type"});
      EXPECT_EQ(rows[i].row.text[0], r->text[0].values[i]);
    }
    std::vector<std::string> notes;
    task.notes().take(notes);
    EXPECT_EQ(notes, r->notes) << tool;
    // (pi, 0) doubles at K = 4: the family says so, and so does the tree, whose rows carry multipliers now
    const auto said = [&notes](const std::string& what) {
      return std::any_of(notes.begin(), notes.end(),
                         [&](const std::string& n) { return n.find(what) != std::string::npos; });
    };
    EXPECT_TRUE(said("= 4") || said("= 3.99999") || said("= 4.0000")) << tool;
    EXPECT_NE(std::find(r->table.names.begin(), r->table.names.end(), "re2"), r->table.names.end()) << tool;
  }
  // a separatrix streams each level's points as it grows them: the map coordinates of the table's rows
  ToolTask branch("separatrix", {standardMapFamily()}, "test", false,
                  {{"separatrix.branches", "[1]"}, {"fixedpoint.guess", "[0.01, 0.01]"}});
  ASSERT_TRUE(branch.run({}));
  std::vector<ToolTask::RunRow> rows;
  branch.rows().take(rows);
  const auto r = branch.result();
  ASSERT_TRUE(r);
  ASSERT_GT(rows.size(), 20u);
  EXPECT_EQ(rows.front().row.names, (std::vector<std::string>{"branch", "theta", "p"}));
  EXPECT_LE(static_cast<long>(rows.size()), r->table.rows());
}

// stopped and continued, a run starts again from the start (its rows carry the next run's number, so that a
// window drops what the first drew) and gives the family an uninterrupted run gives
TEST(ToolTask, StoppedAndContinuedItGivesTheUninterruptedFamily) {
  registerBuiltinTools();
  ToolTask whole("continuation", {standardMapFamily()}, "test", false);
  ASSERT_TRUE(whole.run({}));
  const auto reference = whole.result();
  ASSERT_TRUE(reference);
  ToolTask parts("continuation", {standardMapFamily()}, "test", false);
  long seen = 0;
  ToolControl stopAfterThree;
  stopAfterThree.stopRequested = [&] { return parts.rows().total() >= 3; };
  EXPECT_FALSE(parts.run(stopAfterThree));
  seen = parts.rows().total();
  EXPECT_GE(seen, 3);
  EXPECT_LT(seen, reference->table.rows());
  ASSERT_TRUE(parts.run({}));
  std::vector<ToolTask::RunRow> rows;
  parts.rows().take(rows);
  ASSERT_EQ(static_cast<long>(rows.size()), seen + reference->table.rows());
  for (std::size_t i = 0; i < rows.size(); ++i)
    EXPECT_EQ(rows[i].run, static_cast<long>(i) < seen ? 1 : 2) << i;
  const auto r = parts.result();
  ASSERT_TRUE(r);
  EXPECT_EQ(r->table.values, reference->table.values);
}

// a map tool's failure is the job's: the separatrices of an elliptic point
TEST(ToolTask, ASeparatrixOfAnEllipticPointFailsSayingWhy) {
  registerBuiltinTools();
  ToolTask branch("separatrix", {standardMapFamily()}, "test", false);
  try {
    branch.run({});
    ADD_FAILURE() << "(pi, 0) is elliptic at K = 1.5";
  } catch (const ComputationError& e) {
    EXPECT_NE(std::string(e.what()).find("not hyperbolic"), std::string::npos) << e.what();
  }
}

} // namespace
} // namespace rv
