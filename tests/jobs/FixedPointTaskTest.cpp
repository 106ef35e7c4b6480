// The fixed-point family as jobs: results streamed, prompt stops, continuation that goes on from where it
// stopped to the same family as an uninterrupted run, and failures reported in the job's status.
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/jobs/FixedPointTasks.h"
#include "dynamics/jobs/JobTree.h"

#include "tests/jobs/WaitFor.h"
#include <chrono>
#include <cmath>
#include <gtest/gtest.h>
#include <thread>

namespace rv {
namespace {

using namespace std::chrono_literals;

using test::waitFor;

MapTaskSpec spec(const char* model, std::initializer_list<std::pair<const char*, double>> params,
                 Eigen::VectorXd guess) {
  MapTaskSpec s{RunSpec(ModelRegistry::global().get(model), IntegratorRegistry::global().get("everhart"))};
  for (const auto& [k, v] : params)
    s.run.modelParameters.set(k, v);
  s.run.integratorParameters.set("step", 0.05);
  s.guess = std::move(guess);
  return s;
}

TEST(FixedPointJobs, FixedPointStreamsItsPathAndFinishes) {
  JobTree tree;
  auto task = std::make_unique<FixedPointTask>(spec("henon_map", {}, Eigen::Vector2d(0.5, 0.1)));
  auto* fp = task.get();
  Job& job = tree.add(std::move(task));
  job.start();
  ASSERT_TRUE(waitFor([&] { return job.status() == Job::Status::Finished; }));
  const double x = (-0.7 + std::sqrt(0.49 + 5.6)) / 2.8;
  ASSERT_TRUE(fp->result());
  EXPECT_NEAR(fp->result()->point[0], x, 1e-12);
  EXPECT_GE(fp->path().total(), 2);
}

TEST(FixedPointJobs, FailureIsTheJobsStatus) {
  JobTree tree;
  MapTaskSpec s = spec("henon_map", {}, Eigen::Vector2d(0.2, 0.0));
  s.search.maxIterations = 1;
  s.search.maxDistance = 1e-3;
  Job& job = tree.add(std::make_unique<FixedPointTask>(s));
  job.start();
  ASSERT_TRUE(waitFor([&] { return job.status() == Job::Status::Failed; }));
  EXPECT_NE(job.error().find("no convergence"), std::string::npos) << job.error();
}

// Henon-Heiles' straight-line orbit continued in the energy: slow enough (a flow) to be stopped midway
TEST(FixedPointJobs, ContinuationStopsPromptlyAndGoesOnToTheSameFamily) {
  ContinuationSettings c;
  c.parameter = "energy";
  c.to = 0.16;
  c.step = 0.0005;
  const MapTaskSpec s = spec("henon_heiles", {{"energy", 0.125}}, Eigen::Vector2d(0.0, 0.25));

  JobTree tree;
  auto whole = std::make_unique<ContinuationTask>(s, c);
  auto* w = whole.get();
  Job& a = tree.add(std::move(whole));
  a.start();
  ASSERT_TRUE(waitFor([&] { return a.status() == Job::Status::Finished; }));
  std::vector<ContinuationPoint> reference;
  w->points().take(reference);
  ASSERT_EQ(reference.size(), 71u);

  auto parts = std::make_unique<ContinuationTask>(s, c);
  auto* p = parts.get();
  Job& b = tree.add(std::move(parts));
  b.start();
  ASSERT_TRUE(waitFor([&] { return p->points().total() >= 3; }));
  const auto t0 = std::chrono::steady_clock::now();
  b.stop();
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 1000ms);
  EXPECT_EQ(b.status(), Job::Status::Stopped);
  b.start();
  ASSERT_TRUE(waitFor([&] { return b.status() == Job::Status::Finished; }));
  std::vector<ContinuationPoint> got;
  p->points().take(got);
  ASSERT_EQ(got.size(), reference.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_DOUBLE_EQ(got[i].parameter, reference[i].parameter);
    EXPECT_LT((got[i].fixedPoint.point - reference[i].fixedPoint.point).norm(), 1e-9);
    // the straight-line orbit at every energy: y = 0, py = sqrt(2E) / 2
    EXPECT_NEAR(got[i].fixedPoint.point[0], 0, 1e-9);
    EXPECT_NEAR(got[i].fixedPoint.point[1], std::sqrt(2 * got[i].parameter) / 2, 1e-9);
  }
}

TEST(FixedPointJobs, SeparatrixRefusesAnEllipticPointInItsStatus) {
  JobTree tree;
  Job& job = tree.add(std::make_unique<SeparatrixTask>(
      spec("standard_map", {{"K", 1.5}}, Eigen::Vector2d(3.1, 0.0)), SeparatrixSettings{}));
  job.start();
  ASSERT_TRUE(waitFor([&] { return job.status() == Job::Status::Failed; }));
  EXPECT_NE(job.error().find("not hyperbolic"), std::string::npos) << job.error();
}

} // namespace
} // namespace rv
