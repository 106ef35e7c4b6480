// Jobs: start, stop promptly, continue, edit and continue, restart, delete, the tree; and a random stress of
// many jobs for ThreadSanitizer (run under the tsan preset: ctest --preset tsan).
#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/jobs/JobTree.h"
#include "dynamics/jobs/MegnoTask.h"
#include "dynamics/jobs/PoincareTask.h"

#include "tests/jobs/WaitFor.h"
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>
#include <map>
#include <random>
#include <thread>

namespace rv {
namespace {

RunSpec henonHeiles(double energy = 0.125) {
  RunSpec s(ModelRegistry::global().get("henon_heiles"), IntegratorRegistry::global().get("everhart"));
  s.modelParameters.set("energy", energy);
  s.integratorParameters.set("step", 0.05);
  s.initialState = s.makeModel()->stateFromMap({0.1, 0.1}, {}, "t");
  return s;
}

using test::waitFor;

TEST(Job, RunsStopsPromptlyAndContinuesWhereItStopped) {
  JobTree tree;
  auto task = std::make_unique<PoincareTask>(henonHeiles(), SectionSettings{.maxPoints = 0});
  auto* poincare = task.get();
  Job& job = tree.add(std::move(task));
  job.start();
  ASSERT_TRUE(waitFor([&] { return poincare->points().total() >= 20; }));
  job.stop(); // returns at all: an endless map (maxPoints 0) stopped (how fast is a figure, not a test)
  EXPECT_EQ(job.status(), Job::Status::Stopped);
  std::vector<MapPoint> first;
  poincare->points().take(first);
  const long n = static_cast<long>(first.size());
  job.start(); // continues: the points go on in time
  ASSERT_TRUE(waitFor([&] { return poincare->points().total() >= n + 10; }));
  job.stop();
  std::vector<MapPoint> more;
  poincare->points().take(more);
  ASSERT_FALSE(more.empty());
  EXPECT_GT(more.front().time, first.back().time);
}

// a task of 100 equal steps that counts them, for pauses at a known place
class CountingTask : public Task {
public:
  std::string name() const override { return "count"; }
  std::string describe() const override { return "100 steps"; }
  bool run(const ToolControl& control) override {
    for (; done < 100; ++done) {
      if (control.stopRequested()) return false;
      control.progress(done / 100.0);
    }
    return true;
  }
  void reset() override { done = 0; }
  int done = 0;
};

TEST(Job, PausesWhereAskedAndThenRunsToTheEnd) {
  JobTree tree;
  auto task = std::make_unique<CountingTask>();
  auto* count = task.get();
  tree.pauseNextAt(0.3);
  Job& job = tree.add(std::move(task));
  job.start();
  ASSERT_TRUE(waitFor([&] { return !job.running(); }));
  EXPECT_EQ(job.status(), Job::Status::Stopped);
  EXPECT_EQ(count->done, 31) << "step 30 reported 0.3; the stop is seen before step 31";
  EXPECT_DOUBLE_EQ(job.progress(), 0.3);
  job.start(); // the pause is used up
  ASSERT_TRUE(waitFor([&] { return !job.running(); }));
  EXPECT_EQ(job.status(), Job::Status::Finished);
  EXPECT_EQ(count->done, 100);
  Job& next = tree.add(std::make_unique<CountingTask>()); // the tree's pause was for one job
  next.start();
  ASSERT_TRUE(waitFor([&] { return !next.running(); }));
  EXPECT_EQ(next.status(), Job::Status::Finished);
}

TEST(Job, EditTheEnergyAndContinueGivesPointsAtTheNewEnergy) {
  JobTree tree;
  auto task = std::make_unique<PoincareTask>(henonHeiles(0.125), SectionSettings{.maxPoints = 0});
  auto* poincare = task.get();
  Job& job = tree.add(std::move(task));
  job.start();
  ASSERT_TRUE(waitFor([&] { return poincare->points().total() >= 5; }));
  job.edit([](Task& t) {
    auto& p = static_cast<PoincareTask&>(t);
    RunSpec s = p.spec();
    s.modelParameters.set("energy", 0.15); // a larger region: the last point has a state there
    p.edit(s, p.settings());
  });
  const long before = poincare->points().total();
  std::vector<MapPoint> drop;
  poincare->points().take(drop);
  job.start();
  ASSERT_TRUE(waitFor([&] { return poincare->points().total() >= before + 5; }));
  job.stop();
  const auto model = poincare->spec().makeModel();
  const Eigen::VectorXd x = poincare->lastState();
  EXPECT_NEAR(model->integrals(x.data())[0], 0.15, 1e-10) << "the trajectory goes on at the new energy";
  EXPECT_NEAR(model->integrals(poincare->levelState().data())[0], 0.15, 1e-12) << "its level's state";
  // an energy at which the last point has no state (E = 0: only the origin): the edit is refused, nothing
  // changes
  EXPECT_THROW(job.edit([](Task& t) {
    auto& p = static_cast<PoincareTask&>(t);
    RunSpec s = p.spec();
    s.modelParameters.set("energy", 0.0);
    p.edit(s, p.settings());
  }),
               InputError);
  EXPECT_EQ(poincare->spec().modelParameters["energy"], 0.15);
}

// edited before its first map point (stopped at once): it starts again from its first point, on the new level
TEST(Job, AnEditBeforeTheFirstPointStartsAgainAtTheNewEnergy) {
  JobTree tree;
  auto task = std::make_unique<PoincareTask>(henonHeiles(0.125), SectionSettings{.maxPoints = 0});
  auto* poincare = task.get();
  Job& job = tree.add(std::move(task));
  job.edit([](Task& t) {
    auto& p = static_cast<PoincareTask&>(t);
    RunSpec s = p.spec();
    s.modelParameters.set("energy", 0.15);
    p.edit(s, p.settings());
  });
  const auto model = poincare->spec().makeModel();
  EXPECT_NEAR(model->integrals(poincare->spec().initialState.data())[0], 0.15, 1e-12);
  job.start();
  ASSERT_TRUE(waitFor([&] { return poincare->points().total() >= 3; }));
  job.stop();
  EXPECT_NEAR(model->integrals(poincare->lastState().data())[0], 0.15, 1e-10);
}

// a plot filter opened on a running map (manual §2.4): the job samples its own steps for it
TEST(PlotTaps, AMapTrajectoryFeedsAnOpenPlotWithTheFiltersPoints) {
  const RunSpec spec = henonHeiles(0.125);
  const PlotSettings settings{
      .axes = {"t", "E", "x"}, .condition = "t", .period = 0.25, .maxPoints = 40, .timeLimit = 1e9};
  // the same plot computed on its own: an independent integrator from the same state
  const auto model = spec.makeModel();
  auto integ = spec.makeIntegrator(*model);
  integ->start(*model, 0, spec.initialState);
  const auto expected = samplePlot(*model, *integ, settings, {});
  ASSERT_EQ(expected.size(), 40u);

  JobTree tree;
  auto task = std::make_unique<PoincareTask>(spec, SectionSettings{.maxPoints = 0});
  auto* poincare = task.get();
  auto tap = std::make_shared<PlotTap>(settings);
  auto closed = std::make_shared<PlotTap>(settings);
  closed->closed = true;
  poincare->taps().add(tap);
  poincare->taps().add(closed);
  Job& job = tree.add(std::move(task));
  job.start();
  ASSERT_TRUE(waitFor([&] { return tap->points.total() >= 40 && poincare->points().total() >= 20; }));
  job.stop();
  std::vector<std::vector<double>> got;
  tap->points.take(got);
  ASSERT_EQ(got.size(), 40u) << "max points per trajectory";
  for (std::size_t k = 0; k < got.size(); ++k)
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(got[k][i], expected[k][i], 1e-12) << "point " << k << " axis " << i;
  EXPECT_EQ(closed->points.total(), 0) << "a closed window gets nothing";

  // a tap opened on the running job after an edit of the energy: its points are on the new level (the
  // sampler reads the new model)
  job.edit([](Task& t) {
    auto& p = static_cast<PoincareTask&>(t);
    RunSpec s = p.spec();
    s.modelParameters.set("energy", 0.15);
    p.edit(s, p.settings());
  });
  job.start();
  auto later = std::make_shared<PlotTap>(PlotSettings{.axes = {"t", "E"}, .condition = "x", .period = 0.01});
  poincare->taps().add(later);
  ASSERT_TRUE(waitFor([&] { return later->points.total() >= 30; }));
  job.stop();
  later->points.take(got);
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_NEAR(got[k][1], 0.15, 1e-9);
    if (k > 0) {
      EXPECT_GT(got[k][0], got[k - 1][0]);
    }
  }
}

TEST(Job, RestartBeginsAgainAndFinishedJobsReportIt) {
  JobTree tree;
  SectionSettings s;
  s.maxPoints = 30;
  auto task = std::make_unique<PoincareTask>(henonHeiles(), s);
  auto* poincare = task.get();
  Job& job = tree.add(std::move(task));
  job.start();
  ASSERT_TRUE(waitFor([&] { return job.status() == Job::Status::Finished; }));
  EXPECT_EQ(poincare->points().total(), 30);
  EXPECT_EQ(job.progress(), 1.0);
  job.restart();
  ASSERT_TRUE(waitFor([&] { return job.status() == Job::Status::Finished; }));
  EXPECT_EQ(poincare->points().total(), 30) << "restart clears and recomputes";
}

TEST(Job, FailuresAreReportedWithTheReason) {
  JobTree tree;
  RunSpec spec = henonHeiles();
  spec.integratorParameters.set("step", 5.0); // blows up
  spec.initialState << 0, 0.5, 0.6, 0.1;
  Job& job = tree.add(std::make_unique<PoincareTask>(spec, SectionSettings{.maxPoints = 0}));
  job.start();
  ASSERT_TRUE(waitFor([&] { return job.status() == Job::Status::Failed; }));
  EXPECT_NE(job.error().find("finite"), std::string::npos) << job.error();
}

TEST(JobTree, ToolsHangUnderTheirTrajectoryAndGoWithIt) {
  JobTree tree;
  Job& map = tree.add(std::make_unique<PoincareTask>(henonHeiles(), SectionSettings{.maxPoints = 0}));
  MegnoSettings ms;
  ms.maxTime = 50;
  Job& megno = tree.add(std::make_unique<MegnoTask>(henonHeiles(), ms), &map);
  ms.maxTime = 20;
  Job& shorter = tree.add(std::make_unique<MegnoTask>(henonHeiles(), ms), &map);
  EXPECT_EQ(megno.parent(), &map);
  EXPECT_EQ(tree.children(map).size(), 2u);
  megno.start();
  shorter.start();
  ASSERT_TRUE(waitFor(
      [&] { return megno.status() == Job::Status::Finished && shorter.status() == Job::Status::Finished; }));
  EXPECT_NEAR(static_cast<MegnoTask&>(megno.task()).result().last.time, 50, 1e-9);
  EXPECT_NEAR(static_cast<MegnoTask&>(shorter.task()).result().last.time, 20, 1e-9);
  tree.remove(map);
  EXPECT_TRUE(tree.jobs().empty());
}

// issue 61 (3): a job put back (Undo, a session) keeps its number; a number a window's job had is never given
// again (the window finds its job by it); the tree lists the jobs by number, each after its parent
TEST(JobTree, AJobPutBackKeepsItsNumber) {
  class WindowTask : public CountingTask {
  public:
    bool ownsItsScene() const override { return true; }
  };
  JobTree tree;
  Job& a = tree.add(std::make_unique<CountingTask>());
  Job& b = tree.add(std::make_unique<CountingTask>());
  Job& chart = tree.add(std::make_unique<WindowTask>());
  Job& c = tree.add(std::make_unique<CountingTask>(), &a);
  EXPECT_EQ(std::vector<int>({a.id(), b.id(), chart.id(), c.id()}), std::vector<int>({1, 2, 3, 4}));
  tree.remove(b);
  tree.remove(chart);
  EXPECT_EQ(tree.add(std::make_unique<CountingTask>(), nullptr, 2).id(), 2); // put back: its number
  const auto ids = [&tree] {
    std::vector<int> out;
    for (const Job* j : tree.jobs())
      out.push_back(j->id());
    return out;
  };
  EXPECT_EQ(ids(), std::vector<int>({1, 2, 4}));
  EXPECT_EQ(tree.add(std::make_unique<CountingTask>(), nullptr, 2).id(), 5); // taken: the next number
  EXPECT_EQ(tree.add(std::make_unique<CountingTask>(), nullptr, 3).id(), 6); // a window's: never again
  EXPECT_EQ(tree.add(std::make_unique<CountingTask>(), nullptr, 9).id(), 9); // a saved one from a session
  EXPECT_EQ(tree.add(std::make_unique<CountingTask>()).id(), 10);            // new ones go on from there
  EXPECT_EQ(ids(), std::vector<int>({1, 2, 4, 5, 6, 9, 10}));
  EXPECT_EQ(tree.add(std::make_unique<CountingTask>(), tree.find(10), 7).id(), 7);
  EXPECT_EQ(ids(), std::vector<int>({1, 2, 4, 5, 6, 9, 10, 7})) << "a child after its parent";
}

TEST(JobTree, StressManyJobsInRandomOrder) {
  JobTree tree;
  std::mt19937 rng(42);
  std::vector<MapPoint> sink;
  for (int i = 0; i < 100; ++i)
    tree.add(std::make_unique<PoincareTask>(henonHeiles(), SectionSettings{.maxPoints = 0}));
  for (int op = 0; op < 400; ++op) {
    auto jobs = tree.jobs();
    if (jobs.empty()) break;
    Job& j = *jobs[rng() % jobs.size()];
    switch (rng() % 7) {
    case 0:
    case 1:
      j.start();
      break;
    case 2:
      j.stop();
      break;
    case 3:
      j.restart();
      break;
    case 4:
      j.edit([&](Task& t) {
        auto& p = static_cast<PoincareTask&>(t);
        RunSpec s = p.spec();
        s.modelParameters.set("energy", 0.1 + 0.02 * (rng() % 3));
        try {
          p.edit(s, p.settings());
        } catch (const InputError&) {
          // the last point lies outside the new region: refused, as it should be
        }
      });
      break;
    case 5:
      static_cast<PoincareTask&>(j.task()).points().take(sink);
      break;
    case 6:
      if (rng() % 4 == 0) tree.remove(j);
      break;
    }
  }
  tree.stopAll();
  for (Job* j : tree.jobs())
    EXPECT_NE(j->status(), Job::Status::Running);
  tree.removeAll();
  EXPECT_TRUE(tree.jobs().empty());
}

// how long the time-bounded stress runs: ROLLVIZ_STRESS_SECONDS (./test gives 60 under ThreadSanitizer)
double stressSeconds(double fallback) {
  const char* s = std::getenv("ROLLVIZ_STRESS_SECONDS");
  return s ? std::atof(s) : fallback;
}

TEST(JobTree, StressFiftyJobsStartedEditedStoppedContinuedDeletedLoseNoResult) {
  JobTree tree;
  std::mt19937 rng(7);
  std::map<Job*, long> taken; // points taken from each job since it last began again
  std::vector<MapPoint> sink;
  const auto add = [&] {
    Job& j = tree.add(std::make_unique<PoincareTask>(henonHeiles(0.1 + 0.01 * (rng() % 3)),
                                                     SectionSettings{.maxPoints = 0}));
    taken[&j] = 0;
  };
  for (int i = 0; i < 50; ++i)
    add();
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(stressSeconds(3));
  long ops = 0;
  while (std::chrono::steady_clock::now() < end) {
    ++ops;
    auto jobs = tree.jobs();
    Job& j = *jobs[rng() % jobs.size()];
    auto& task = static_cast<PoincareTask&>(j.task());
    switch (rng() % 8) {
    case 0:
    case 1:
      j.start();
      break;
    case 2:
      j.stop();
      break;
    case 3:
      j.restart(); // begins again: its channel starts empty
      taken[&j] = 0;
      break;
    case 4:
      j.edit([&](Task& t) {
        auto& p = static_cast<PoincareTask&>(t);
        RunSpec spec = p.spec();
        spec.modelParameters.set("energy", 0.1 + 0.01 * (rng() % 3));
        try {
          p.edit(spec, p.settings());
        } catch (const InputError&) {
          // the last point lies outside the new region: refused, nothing changes
        }
      });
      break;
    case 5:
    case 6:
      taken[&j] += static_cast<long>(task.points().take(sink));
      break;
    case 7:
      if (rng() % 8 == 0) {
        taken.erase(&j);
        tree.remove(j);
        add(); // fifty at all times
      }
      break;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(rng() % 500));
  }
  tree.stopAll();
  ASSERT_EQ(tree.jobs().size(), 50u);
  long points = 0;
  for (Job* j : tree.jobs()) {
    EXPECT_NE(j->status(), Job::Status::Running);
    auto& task = static_cast<PoincareTask&>(j->task());
    taken[j] += static_cast<long>(task.points().take(sink));
    EXPECT_EQ(taken[j], task.points().total()) << "job " << j->id() << ": every point produced was delivered";
    points += taken[j];
  }
  std::printf("  %ld operations, %ld points delivered\n", ops, points);
  EXPECT_GT(points, 0);
  tree.removeAll();
  EXPECT_TRUE(tree.jobs().empty());
}

TEST(Channel, ABoundedChannelMakesTheProducerWaitAndLosesNothing) {
  Channel<long> channel(100);
  const long n = 200000;
  std::thread producer([&] {
    for (long i = 0; i < n; ++i)
      channel.push(i);
  });
  std::vector<long> batch;
  long next = 0;
  while (next < n) {
    channel.take(batch);
    for (long v : batch)
      ASSERT_EQ(v, next++) << "in order, none lost";
    std::this_thread::sleep_for(std::chrono::microseconds(50));
  }
  producer.join();
  EXPECT_EQ(channel.total(), n);
  EXPECT_LE(channel.highWater(), 100u);
  // a full channel nobody takes from: the producer waits, and a stop ends the wait
  Channel<int> full(2);
  full.push(1), full.push(2);
  std::atomic<bool> stop{false}, returned{false};
  std::atomic<int> polls{0};
  std::thread waiting([&] {
    full.push(3, [&] {
      ++polls;
      return stop.load();
    });
    returned = true;
  });
  // polled twice: it found the channel full and waited for room at least once (without a sleep to hope so)
  EXPECT_TRUE(waitFor([&] { return polls >= 2; })); // (no ASSERT before the join)
  EXPECT_EQ(full.total(), 2);
  EXPECT_FALSE(returned);
  stop = true;
  const bool ended = waitFor([&] { return returned.load(); }, std::chrono::milliseconds(60000));
  std::vector<int> room;
  if (!ended) full.take(room); // the stop was not seen: make room so that the thread can be joined
  waiting.join();
  EXPECT_TRUE(ended) << "a stop ends the wait, nobody taking";
  EXPECT_EQ(full.total(), 3) << "the item pushed on the stop is kept";
}

long residentKiB() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::atol(line.c_str() + 6);
  return 0;
}

TEST(PoincareTask, MemoryStaysBoundedWhileAMapStreamsTenMillionPoints) {
#if defined(__SANITIZE_THREAD__) || defined(__SANITIZE_ADDRESS__)
  const long n = 1000000; // the sanitizers are ten times slower: the bound is the same
#else
  const long n = 10000000;
#endif
  RunSpec spec(ModelRegistry::global().get("standard_map"), IntegratorRegistry::global().get("rk4"));
  spec.modelParameters.set("K", 0.9);
  spec.initialState = Eigen::Vector2d(3.0, 0.7);
  SectionSettings settings;
  settings.maxPoints = n;
  JobTree tree;
  auto owned = std::make_unique<PoincareTask>(spec, settings);
  auto* task = owned.get();
  Job& job = tree.add(std::move(owned));
  const long before = residentKiB();
  job.start();
  // a slow consumer that keeps nothing: without the bound the channel would hold millions of points
  std::vector<MapPoint> batch;
  long received = 0;
  double lastTime = -1;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (received < n) {
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << received << " points";
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    task->points().take(batch);
    for (const auto& p : batch) {
      ASSERT_GT(p.time, lastTime) << "in order";
      lastTime = p.time;
    }
    received += static_cast<long>(batch.size());
    ASSERT_NE(job.status(), Job::Status::Failed) << job.error();
  }
  ASSERT_TRUE(waitFor([&] { return job.status() == Job::Status::Finished; }));
  const long grown = residentKiB() - before;
  std::printf("  %ld points, at most %zu waiting at once, resident memory grew by %ld KiB\n", received,
              task->points().highWater(), grown);
  EXPECT_EQ(received, n);
  EXPECT_LE(task->points().highWater(), PoincareTask::kChannelCapacity + 1);
#if !defined(__SANITIZE_THREAD__) && !defined(__SANITIZE_ADDRESS__)
  EXPECT_LT(grown, 200 * 1024) << "10^7 points held at once would take about 700 MB";
#endif
}

TEST(PoincareTask, SavedAndRestoredItGoesOnWithTheSamePointsBitForBit) {
  SectionSettings settings;
  settings.maxPoints = 600;
  PoincareTask first(henonHeiles(0.125), settings);
  long polls = 0, limit = 3000; // a stop, once asked, stays asked until the limit moves
  ToolControl stop;
  stop.stopRequested = [&] { return ++polls > limit; };
  ASSERT_FALSE(first.run(stop));
  std::vector<MapPoint> before;
  first.points().take(before);
  ASSERT_GT(before.size(), 3u);
  // an edit rebuilds the map from the last point: the point limit then counts from there
  first.edit(first.spec(), first.settings());
  limit = polls + 3000;
  ASSERT_FALSE(first.run(stop));
  Snapshot saved;
  first.save(saved);
  std::vector<MapPoint> middle;
  first.points().take(middle);
  // the reference goes on; a fresh task restores the snapshot and goes on too
  ASSERT_TRUE(first.run({}));
  std::vector<MapPoint> expected;
  first.points().take(expected);
  PoincareTask second(henonHeiles(0.125), settings);
  second.restore(saved);
  ASSERT_TRUE(second.run({}));
  std::vector<MapPoint> got;
  second.points().take(got);
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(before.size() + middle.size() + got.size(), 600u) << "the limit counts the points made before";
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].time, expected[i].time) << i;
    EXPECT_EQ(got[i].coordinates, expected[i].coordinates) << i;
  }
  EXPECT_TRUE(second.lastState() == first.lastState());
}

TEST(PoincareTask, AFinishedTrajectoryExtendedGoesOnAsOneLongerRunBitForBit) {
  // the GUI's Start on a finished trajectory: 200 points, then 150 more == one run of 350
  SectionSettings shortRun;
  shortRun.maxPoints = 200;
  JobTree tree;
  auto owned = std::make_unique<PoincareTask>(henonHeiles(0.125), shortRun);
  PoincareTask* task = owned.get();
  Job& job = tree.add(std::move(owned));
  job.start();
  ASSERT_TRUE(waitFor([&] { return job.status() == Job::Status::Finished; }));
  std::vector<MapPoint> got;
  task->points().take(got);
  ASSERT_EQ(got.size(), 200u);
  job.start(); // finished: nothing happens
  job.edit([](Task& t) { static_cast<PoincareTask&>(t).extend(150); });
  EXPECT_EQ(job.status(), Job::Status::Stopped) << "an extended trajectory can be started again";
  EXPECT_EQ(task->limit(), 350);
  job.start();
  ASSERT_TRUE(waitFor([&] { return job.status() == Job::Status::Finished; }));
  std::vector<MapPoint> more;
  task->points().take(more);
  got.insert(got.end(), more.begin(), more.end());
  SectionSettings longRun;
  longRun.maxPoints = 350;
  PoincareTask reference(henonHeiles(0.125), longRun);
  ASSERT_TRUE(reference.run({}));
  std::vector<MapPoint> expected;
  reference.points().take(expected);
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].time, expected[i].time) << i;
    EXPECT_EQ(got[i].coordinates, expected[i].coordinates) << i;
  }
}

} // namespace
} // namespace rv
