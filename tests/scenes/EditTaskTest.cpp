// Edit properties (manual §2.1) of the fixed-point family, which the map window runs as the registry's
// runners (scenes/ToolTask.h): a stopped tool takes an edited scene's values and starts again with them,
// keeping its own settings (a search its guess, a separatrix its branch). Known answers on the
// standard map: the point (pi, 0) has the trace 2 - K.
#include "dynamics/core/Errors.h"
#include "dynamics/jobs/JobTree.h"
#include "dynamics/jobs/MegnoTask.h"
#include "scenes/BuiltinTools.h"
#include "scenes/SceneLoader.h"
#include "scenes/SceneTools.h"
#include "scenes/ToolTask.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace rv {
namespace {

using nlohmann::json;

Scene standardMap(double K, double to = 2.5, double step = 0.1) {
  const json doc = {{"problem", "standard_map"},
                    {"parameters", {{"K", K}}},
                    {"initial", {{"map", {3.0, 0.1}}}},
                    {"fixedpoint", {{"guess", {3.1, 0.05}}}},
                    {"continuation", {{"parameter", "K"}, {"to", to}, {"step", step}}}};
  return sceneFromJson(doc, "standard.json");
}

void runToEnd(Job& job) {
  job.start();
  while (job.running())
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

// the map's fixed-point search (the fixedpoint tool's runner from a click: the guess its own) searches again
// from its guess with the edited problem
TEST(EditTask, AFixedPointSearchSearchesAgainWithTheNewProblem) {
  registerBuiltinTools();
  JobTree tree;
  auto task =
      std::make_unique<ToolTask>("fixedpoint", std::vector<json>{standardMap(0.9).document}, "standard.json",
                                 false, std::vector<SceneOverride>{{"fixedpoint.guess", "[3.2, -0.05]"}});
  ToolTask* search = task.get();
  Job& job = tree.add(std::move(task));
  runToEnd(job);
  ASSERT_TRUE(search->result());
  EXPECT_NEAR(search->result()->fields["point"][0].get<double>(), std::numbers::pi, 1e-9);
  EXPECT_GE(search->rows().total(), 2) << "its path streamed, step by step";
  bool goesOn = true;
  job.edit([&](Task& t) { goesOn = editTask(t, standardMap(2.0)); });
  EXPECT_FALSE(goesOn);
  EXPECT_FALSE(search->result()) << "the old point is not the answer for the new values";
  runToEnd(job);
  const auto found = search->result(); // (a copy: the result is read under the task's lock)
  ASSERT_TRUE(found);
  const auto& m = found->fields["multipliers"];
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR(m[0][0].get<double>() + m[1][0].get<double>(), 2 - 2.0, 1e-9) << "trace 2 - K at the new K";
  EXPECT_EQ(found->fields["type"], "elliptic");
  // the guess stayed the click's, not the edited scene's (3.1, 0.05): the first step of the path starts there
  std::vector<ToolTask::RunRow> path;
  search->rows().take(path);
  const auto second = std::find_if(path.begin(), path.end(), [](const auto& r) { return r.run == 2; });
  ASSERT_NE(second, path.end());
  EXPECT_EQ(second->row.names, (std::vector<std::string>{"theta", "p", "residual"}));
  EXPECT_EQ(second->row.values[0], 3.2);
  EXPECT_EQ(second->row.values[1], -0.05);
}

// a search that does not converge fails the job, saying why
TEST(EditTask, ASearchThatDoesNotConvergeFailsTheJob) {
  registerBuiltinTools();
  JobTree tree;
  json doc = standardMap(0.9).document;
  doc["fixedpoint"]["max_iterations"] = 1;
  doc["fixedpoint"]["max_distance"] = 1e-3;
  Job& job =
      tree.add(std::make_unique<ToolTask>("fixedpoint", std::vector<json>{doc}, "standard.json", false,
                                          std::vector<SceneOverride>{{"fixedpoint.guess", "[2.0, 1.0]"}}));
  runToEnd(job);
  EXPECT_EQ(job.status(), Job::Status::Failed);
  EXPECT_NE(job.error().find("no convergence"), std::string::npos) << job.error();
}

// a family on the map runs as the continuation's registered runner (scenes/ToolTask.h): edited, it starts
// again with the new settings
TEST(EditTask, AContinuationStartsAgainWithTheNewSettings) {
  registerBuiltinTools();
  JobTree tree;
  auto task = std::make_unique<ToolTask>("continuation", std::vector<json>{standardMap(1.5).document},
                                         "standard.json", false);
  ToolTask* family = task.get();
  Job& job = tree.add(std::move(task));
  runToEnd(job);
  ASSERT_TRUE(family->result());
  EXPECT_EQ(family->result()->table.rows(), 11); // K = 1.5 .. 2.5
  bool goesOn = true;
  job.edit([&](Task& t) { goesOn = editTask(t, standardMap(1.5, 3.0, 0.25)); });
  EXPECT_FALSE(goesOn);
  EXPECT_FALSE(family->result()) << "the old family is not the answer for the new values";
  runToEnd(job);
  const auto r = family->result();
  ASSERT_TRUE(r);
  ASSERT_EQ(r->table.rows(), 7); // K = 1.5, 1.75, ..., 3.0
  const auto& K = r->table.values[0];
  EXPECT_NEAR(K.back(), 3.0, 1e-12);
  for (std::size_t i = 0; i < K.size(); ++i) // re1 + re2: the trace 2 - K
    EXPECT_NEAR(r->table.values[3][i] + r->table.values[5][i], 2 - K[i], 1e-8);
}

// an edit keeps a tool's own settings: the separatrices the map grows keep their branches, a doubled family
// its switch
TEST(EditTask, AToolKeepsItsOwnSettingsAndToolsWithoutSettingsSaySo) {
  registerBuiltinTools();
  ToolTask branches("separatrix", {standardMap(0.9).document}, "standard.json", false,
                    {{"separatrix.branches", "[3]"}, {"fixedpoint.guess", "[0.01, 0.01]"}});
  EXPECT_FALSE(editTask(branches, standardMap(1.2)));
  ASSERT_TRUE(branches.run({}));
  const auto r = branches.result();
  ASSERT_TRUE(r);
  ASSERT_GT(r->table.rows(), 0);
  for (double b : r->table.values[0])
    EXPECT_EQ(b, 3);
  EXPECT_NEAR(std::remainder(r->fields["fixedpoint"]["point"][0].get<double>(), 2 * std::numbers::pi), 0,
              1e-9)
      << "the saddle (0, 0)";
  // its incoming branch's multiplier at the new K: 1 + K/2 - sqrt(K + K^2/4) (0.4 at the old K = 0.9)
  const double K = 1.2;
  EXPECT_NEAR(r->fields["branches"][0]["multiplier"].get<double>(), 1 + K / 2 - std::sqrt(K + K * K / 4),
              1e-9);
  const Scene scene = standardMap(0.9);
  MegnoTask megno(scene.runSpec(), MegnoSettings{});
  EXPECT_THROW(editTask(megno, scene), InputError);
}

} // namespace
} // namespace rv
