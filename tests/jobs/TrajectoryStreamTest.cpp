// TrajectoryStream: the consumer gets exactly the requested time, every step in between, a prompt stop,
// and the same motion as a plain integration. Run under the tsan preset for data races.
#include "dynamics/jobs/TrajectoryStream.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Rk4.h"
#include "tests/jobs/WaitFor.h"

#include <chrono>
#include <gtest/gtest.h>
#include <random>
#include <thread>

namespace rv {
namespace {

std::unique_ptr<Model> lorenz() {
  const auto& e = ModelRegistry::global().get("lorenz");
  return e.create(ParameterValues(e.info->parameters));
}

std::unique_ptr<Integrator> started(const Model& m, double h) {
  auto rk4 = std::make_unique<Rk4>(h);
  Eigen::VectorXd x0(3);
  x0 << 1, 1, 1;
  rk4->start(m, 0, x0);
  return rk4;
}

TEST(TrajectoryStream, DeliversTheStateAtTheRequestedTimeAndEveryStep) {
  const auto m = lorenz();
  TrajectoryStream stream(started(*m, 1e-3));
  stream.requestUntil(0.5);
  TrajectoryStream::Batch b, all;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::seconds(60); // generous: a busy machine
  bool reached = false;
  while (!reached && std::chrono::steady_clock::now() < deadline) {
    if (stream.take(b)) {
      all.times.insert(all.times.end(), b.times.begin(), b.times.end());
      if (b.reached) reached = true, all.at = b.at, all.atTime = b.atTime;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_TRUE(reached);
  EXPECT_EQ(all.atTime, 0.5);
  EXPECT_EQ(all.times.size(), 500u);
  // same as integrating directly
  auto direct = started(*m, 1e-3);
  for (int i = 0; i < 500; ++i)
    direct->step();
  EXPECT_NEAR((direct->state() - all.at).norm(), 0, 1e-9 * direct->state().norm());
}

// 10^15 steps away from its target: the destructor returns at all only because it stops the work (how fast it
// does is a figure, not asserted)
TEST(TrajectoryStream, StopsPromptlyWhileWorkingOnAFarTarget) {
  const auto m = lorenz();
  auto stream = std::make_unique<TrajectoryStream>(started(*m, 1e-6));
  stream->requestUntil(1e9);
  // at work on it: steps have come (instead of sleeping and hoping the thread has started)
  TrajectoryStream::Batch b;
  ASSERT_TRUE(
      test::waitFor([&] { return stream->take(b) && !b.times.empty(); }, std::chrono::milliseconds(60000)));
  EXPECT_FALSE(b.reached);
  EXPECT_FALSE(stream->idle());
  stream.reset();
}

TEST(TrajectoryStream, IsIdleOnceTheRequestedStateIsTaken) {
  const auto m = lorenz();
  TrajectoryStream stream(started(*m, 1e-3));
  EXPECT_TRUE(stream.idle()); // nothing asked for yet
  stream.requestUntil(0.1);
  TrajectoryStream::Batch b;
  bool reached = false;
  ASSERT_TRUE(test::waitFor(
      [&] {
        if (stream.take(b) && b.reached) reached = true;
        return reached;
      },
      std::chrono::milliseconds(60000)));
  EXPECT_TRUE(stream.idle());
  EXPECT_FALSE(stream.take(b)) << "idle: nothing more came";
  stream.requestUntil(0.05); // back in time: the state there is delivered (where the stream stands)
  EXPECT_FALSE(stream.idle());
  ASSERT_TRUE(test::waitFor([&] { return stream.take(b) && b.reached; }, std::chrono::milliseconds(60000)));
  EXPECT_TRUE(stream.idle());
}

TEST(TrajectoryStream, ManyStreamsRequestedAndDestroyedInRandomOrder) {
  const auto m = lorenz();
  std::mt19937 rng(1);
  std::vector<std::unique_ptr<TrajectoryStream>> streams;
  TrajectoryStream::Batch b;
  for (int i = 0; i < 200; ++i) {
    const int op = static_cast<int>(rng() % 4);
    if (op == 0 || streams.empty())
      streams.push_back(std::make_unique<TrajectoryStream>(started(*m, 1e-3)));
    else if (op == 1)
      streams[rng() % streams.size()]->requestUntil(static_cast<double>(rng() % 100) / 50.0);
    else if (op == 2)
      streams[rng() % streams.size()]->take(b);
    else
      streams.erase(streams.begin() + static_cast<long>(rng() % streams.size()));
  }
  streams.clear();
  SUCCEED();
}

} // namespace
} // namespace rv
