// The fixed-point search as a job: its path streamed, and failures reported in the job's status (the rest of
// the family runs as registered tools: tests/scenes/ChartTaskTest.cpp ToolTask).
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

} // namespace
} // namespace rv
