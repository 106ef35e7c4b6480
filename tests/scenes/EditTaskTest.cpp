// Edit properties (manual §2.1) of the fixed-point family: a stopped tool takes an edited scene's values;
// a search goes on from where it stopped, a continuation starts again with them. Known answers on the
// standard map: the point (pi, 0) has the trace 2 - K.
#include "dynamics/core/Errors.h"
#include "dynamics/jobs/JobTree.h"
#include "dynamics/jobs/MegnoTask.h"
#include "scenes/SceneLoader.h"
#include "scenes/SceneTools.h"

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

TEST(EditTask, AFixedPointSearchGoesOnWithTheNewProblem) {
  const SceneMap sm(standardMap(0.9));
  JobTree tree;
  auto task = std::make_unique<FixedPointTask>(sm.taskSpec());
  FixedPointTask* search = task.get();
  Job& job = tree.add(std::move(task));
  runToEnd(job);
  ASSERT_TRUE(search->result());
  EXPECT_NEAR(search->result()->point[0], std::numbers::pi, 1e-9);
  const Scene after = standardMap(2.0);
  bool goesOn = false;
  job.edit([&](Task& t) { goesOn = editTask(t, after); });
  EXPECT_TRUE(goesOn);
  EXPECT_FALSE(search->result()) << "the old point is not the answer for the new values";
  EXPECT_EQ(search->spec().guess, sm.taskSpec().guess) << "the guess is the tool's own";
  runToEnd(job);
  const auto found = search->result(); // (a copy: the result is read under the task's lock)
  ASSERT_TRUE(found);
  const auto& m = found->multipliers;
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR((m[0] + m[1]).real(), 2 - 2.0, 1e-9) << "trace 2 - K at the new K";
  EXPECT_EQ(found->type, FixedPointType::Elliptic);
}

TEST(EditTask, AContinuationStartsAgainWithTheNewSettings) {
  const SceneMap sm(standardMap(1.5, 2.5, 0.1));
  JobTree tree;
  auto task = std::make_unique<ContinuationTask>(sm.taskSpec(), sm.continuation());
  ContinuationTask* family = task.get();
  Job& job = tree.add(std::move(task));
  runToEnd(job);
  std::vector<ContinuationPoint> points;
  family->points().take(points);
  ASSERT_EQ(points.size(), 11u); // K = 1.5 .. 2.5
  bool goesOn = true;
  job.edit([&](Task& t) { goesOn = editTask(t, standardMap(1.5, 3.0, 0.25)); });
  EXPECT_FALSE(goesOn);
  runToEnd(job);
  family->points().take(points);
  ASSERT_EQ(points.size(), 7u); // K = 1.5, 1.75, ..., 3.0
  EXPECT_NEAR(points.back().parameter, 3.0, 1e-12);
  for (const auto& p : points)
    EXPECT_NEAR((p.fixedPoint.multipliers[0] + p.fixedPoint.multipliers[1]).real(), 2 - p.parameter, 1e-8);
}

TEST(EditTask, ASeparatrixKeepsItsBranchAndToolsWithoutSettingsSaySo) {
  const SceneMap sm(standardMap(0.9));
  SeparatrixSettings s;
  s.branch = 3;
  SeparatrixTask branch(sm.taskSpec(), s);
  EXPECT_FALSE(editTask(branch, standardMap(1.2)));
  EXPECT_EQ(branch.settings().branch, 3);
  const Scene scene = standardMap(0.9);
  MegnoTask megno(scene.runSpec(), MegnoSettings{});
  EXPECT_THROW(editTask(megno, scene), InputError);
}

} // namespace
} // namespace rv
