// The sweep's store and scheduler: records survive a reopen (resume), another run's file is refused, every
// point is handed out exactly once (resumed points never), any number of threads gives the same records, a
// stop leaves no half-written point, and records cross between ranks intact. Run under ThreadSanitizer too.
#include "dynamics/jobs/SweepStore.h"
#include "dynamics/core/Errors.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <gtest/gtest.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace rv {
namespace {

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / (name + "." + std::to_string(::getpid()))).string();
}

// a point's record depends only on its index: a sum whose cost varies along the grid, as chaos does
SweepRecord slowRecord(long i, const ToolControl&) {
  double s = 0;
  for (long k = 0; k < 20000 + (i % 7) * 30000; ++k)
    s += std::sin(static_cast<double>(i) + 1e-3 * static_cast<double>(k));
  SweepRecord r;
  r.values = {s, static_cast<double>(i) * 0.5};
  r.ok = i % 11 != 3;
  if (!r.ok) r.reason = "point " + std::to_string(i) + " failed";
  return r;
}

TEST(SweepStore, RecordsSurviveAReopenAndOtherRunsAreRefused) {
  const std::string path = tempPath("store");
  std::filesystem::remove(path);
  {
    SweepStore store(path, "run A", 10, 2, "--checkpoint");
    EXPECT_EQ(store.doneCount(), 0);
    store.write(7, {{1.5, -2.0}, 0.25, true, ""});
    store.write(2, {{std::nan(""), std::nan("")}, 0.5, false, std::string(500, 'x')});
  }
  SweepStore again(path, "run A", 10, 2, "--checkpoint");
  EXPECT_EQ(again.doneCount(), 2);
  EXPECT_EQ(again.failedCount(), 1);
  EXPECT_TRUE(again.done(7) && again.done(2) && !again.done(0));
  const SweepRecord a = again.read(7), b = again.read(2);
  EXPECT_EQ(a.values, (std::vector<double>{1.5, -2.0}));
  EXPECT_EQ(a.seconds, 0.25);
  EXPECT_TRUE(a.ok);
  EXPECT_FALSE(b.ok);
  EXPECT_EQ(b.reason.size(), static_cast<std::size_t>(SweepStore::kReasonBytes)); // cut, not overflowing
  for (const auto& [id, points, columns] :
       {std::tuple{"run B", 10L, 2}, {"run A", 11L, 2}, {"run A", 10L, 3}}) {
    try {
      SweepStore other(path, id, points, columns, "--checkpoint");
      ADD_FAILURE() << "another run's store was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--checkpoint " + path), std::string::npos) << e.what();
    }
  }
  again.remove();
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(SweepStore, EveryPointIsHandedOutOnceAndResumedPointsNever) {
  const std::string path = tempPath("sched");
  std::filesystem::remove(path);
  SweepStore store(path, "sched", 1000, 1, "-o");
  for (long i : {0L, 1L, 500L, 501L, 999L})
    store.write(i, {{1.0}, 0, true, ""});
  ChunkScheduler scheduler(store, 4);
  std::vector<int> handed(1000, 0);
  std::size_t chunks = 0, first = 0;
  while (const auto c = scheduler.next()) {
    ASSERT_FALSE(c->empty());
    EXPECT_TRUE(std::ranges::is_sorted(*c));
    if (chunks++ == 0) first = c->size();
    for (long i : *c)
      ++handed[static_cast<std::size_t>(i)];
  }
  for (long i = 0; i < 1000; ++i)
    EXPECT_EQ(handed[static_cast<std::size_t>(i)], store.done(i) ? 0 : 1) << i;
  // guided: a large first chunk, a few dozen requests, not one per point
  EXPECT_GT(first, 30U);
  EXPECT_LT(chunks, 200U);
  store.remove();
}

// with a granularity (the points computed at once on SIMD lanes) every chunk is whole batches -- the last
// ones too, where a plain schedule ends with single points -- and still every point is handed out once
TEST(SweepStore, ChunksAreWholeBatchesToTheEnd) {
  const std::string path = tempPath("batches");
  std::filesystem::remove(path);
  SweepStore store(path, "batches", 1000, 1, "-o");
  for (const int workers : {1, 3}) {
    ChunkScheduler scheduler(store, workers, 30, {}, 4);
    std::vector<int> handed(1000, 0);
    while (const auto c = scheduler.next()) {
      EXPECT_EQ(c->size() % 4, 0U) << c->front() << ".." << c->back();
      EXPECT_LE(c->size(), 28U); // within maxChunk 30, in whole batches
      for (long i : *c)
        ++handed[static_cast<std::size_t>(i)];
    }
    for (int h : handed)
      EXPECT_EQ(h, 1);
  }
  store.remove();
}

// a level of a refined sweep computes points that lie apart (every other one on a line of the finest grid,
// and lines apart): its chunks gather them into whole batches all the same, where a chunk of consecutive
// indices would hold one point each and leave the SIMD lanes idle
TEST(SweepStore, ALevelsPointsLyingApartMakeWholeBatches) {
  const std::string path = tempPath("apart");
  std::filesystem::remove(path);
  SweepStore store(path, "apart", 81 * 81, 1, "-o");
  std::vector<char> wanted(81 * 81, 0);
  long count = 0;
  for (long row = 1; row < 81; row += 2)
    for (long column = 0; column < 81; column += 2) {
      wanted[static_cast<std::size_t>(row * 81 + column)] = 1;
      ++count;
    }
  store.write(81 + 2, {{1.0}, 0, true, ""}); // resumed: not handed out
  ChunkScheduler scheduler(store, 2, 64, wanted, 8);
  std::vector<int> handed(81 * 81, 0);
  std::size_t chunks = 0;
  long total = 0;
  while (const auto c = scheduler.next()) {
    ++chunks;
    total += static_cast<long>(c->size());
    for (long i : *c)
      ++handed[static_cast<std::size_t>(i)];
    if (total < count - 8) { // whole batches (the level's last may be short)
      EXPECT_EQ(c->size() % 8, 0U);
    }
  }
  EXPECT_EQ(total, count - 1);
  for (std::size_t i = 0; i < handed.size(); ++i)
    EXPECT_EQ(handed[i], wanted[i] && i != 81 + 2 ? 1 : 0) << i;
  EXPECT_LT(chunks, 60U); // not one per point
  store.remove();
}

// a level of a refined sweep is finished once each of its points has a record, whoever wrote it (another
// rank's records arrive through the store): handing out its last chunk is not finishing it
TEST(SweepStore, ALevelIsFinishedWhenEachOfItsPointsHasARecord) {
  const std::string path = tempPath("level");
  std::filesystem::remove(path);
  SweepStore store(path, "level", 10, 1, "-o");
  std::vector<char> wanted(10, 0);
  wanted[2] = wanted[3] = wanted[7] = 1;
  store.write(3, {{1.0}, 0, true, ""}); // resumed
  ChunkScheduler scheduler(store, 2, 0, wanted);
  EXPECT_FALSE(scheduler.finished());
  std::vector<long> handed;
  while (const auto c = scheduler.next())
    handed.insert(handed.end(), c->begin(), c->end());
  EXPECT_EQ(handed, (std::vector<long>{2, 7}));
  EXPECT_FALSE(scheduler.finished()); // handed out, not recorded
  store.write(2, {{1.0}, 0, true, ""});
  EXPECT_FALSE(scheduler.finished());
  store.write(7, {{std::nan("")}, 0, false, "failed"}); // a failed point has its record too
  EXPECT_TRUE(scheduler.finished());
  store.remove();
}

std::vector<SweepRecord> runWith(int threads, const std::string& name) {
  const std::string path = tempPath(name);
  std::filesystem::remove(path);
  SweepStore store(path, "threads", 300, 2, "-o");
  ChunkScheduler scheduler(store, threads);
  std::vector<std::atomic<int>> calls(300);
  const bool complete = runSweepThreads(store, scheduler,
                                        [&](long i, const ToolControl& c) {
                                          ++calls[static_cast<std::size_t>(i)];
                                          return slowRecord(i, c);
                                        },
                                        threads, {});
  EXPECT_TRUE(complete);
  for (const auto& c : calls)
    EXPECT_EQ(c.load(), 1);
  std::vector<SweepRecord> out;
  for (long i = 0; i < 300; ++i)
    out.push_back(store.read(i));
  store.remove();
  return out;
}

TEST(SweepStore, AnyNumberOfThreadsGivesTheSameRecords) {
  const auto one = runWith(1, "t1"), three = runWith(3, "t3");
  ASSERT_EQ(one.size(), three.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].values, three[i].values) << i;
    EXPECT_EQ(one[i].ok, three[i].ok) << i;
    EXPECT_EQ(one[i].reason, three[i].reason) << i;
  }
}

TEST(SweepStore, AStoppedRunResumesWithoutRecomputing) {
  const std::string path = tempPath("stop");
  std::filesystem::remove(path);
  std::vector<std::atomic<int>> calls(400);
  const auto evaluate = [&](long i, const ToolControl& c) {
    ++calls[static_cast<std::size_t>(i)];
    return slowRecord(i, c);
  };
  long doneFirst = 0;
  {
    SweepStore store(path, "stop", 400, 2, "--checkpoint");
    ChunkScheduler scheduler(store, 2);
    std::atomic<int> polls{0};
    ToolControl stopSoon;
    stopSoon.stopRequested = [&] { return store.doneCount() > 50 || ++polls > 1000; };
    EXPECT_FALSE(runSweepThreads(store, scheduler, evaluate, 2, stopSoon));
    doneFirst = store.doneCount();
    EXPECT_GT(doneFirst, 0);
    EXPECT_LT(doneFirst, 400);
  }
  SweepStore store(path, "stop", 400, 2, "--checkpoint");
  EXPECT_EQ(store.doneCount(), doneFirst);
  std::vector<char> before(400);
  for (long i = 0; i < 400; ++i)
    before[static_cast<std::size_t>(i)] = store.done(i);
  for (auto& c : calls)
    c = 0;
  ChunkScheduler scheduler(store, 2);
  EXPECT_TRUE(runSweepThreads(store, scheduler, evaluate, 2, {}));
  for (long i = 0; i < 400; ++i) {
    EXPECT_EQ(calls[static_cast<std::size_t>(i)].load(), before[static_cast<std::size_t>(i)] ? 0 : 1) << i;
    const SweepRecord r = store.read(i), expected = slowRecord(i, {});
    EXPECT_EQ(r.values, expected.values) << i; // a point cut short by the stop was never written
  }
  store.remove();
}

// more threads than work (a resumed sweep with nothing or one point left): every thread ends, none hangs
TEST(SweepStore, ThreadsWithNothingToDoEnd) {
  const std::string path = tempPath("idle");
  std::filesystem::remove(path);
  SweepStore store(path, "idle", 3, 1, "-o");
  store.write(0, {{1.0}, 0, true, ""});
  store.write(2, {{1.0}, 0, true, ""});
  std::atomic<int> calls{0};
  const auto evaluate = [&](long, const ToolControl&) {
    ++calls;
    return SweepRecord{{2.0}, 0, true, ""};
  };
  for (int round = 0; round < 2; ++round) { // one point left, then none
    ChunkScheduler scheduler(store, 8);
    EXPECT_TRUE(runSweepThreads(store, scheduler, evaluate, 8, {}));
  }
  EXPECT_EQ(calls.load(), 1);
  EXPECT_EQ(store.read(1).values, (std::vector<double>{2.0}));
  store.remove();
}

// the GUI reads a sweep while its job writes: a point that reads as done has its whole record
TEST(SweepStore, ARunningSweepCanBeReadWhileItIsWritten) {
  const std::string path = tempPath("live");
  std::filesystem::remove(path);
  SweepStore store(path, "live", 200, 2, "-o");
  ChunkScheduler scheduler(store, 2);
  std::atomic<bool> finished{false};
  long checked = 0;
  std::thread reader([&] {
    std::vector<char> seen(200, 0);
    while (!finished.load())
      for (long i = 0; i < 200; ++i)
        if (!seen[static_cast<std::size_t>(i)] && store.done(i)) {
          seen[static_cast<std::size_t>(i)] = 1;
          const SweepRecord r = store.read(i), expected = slowRecord(i, {});
          EXPECT_EQ(r.values, expected.values) << i;
          EXPECT_EQ(r.ok, expected.ok) << i;
          ++checked;
        }
  });
  EXPECT_TRUE(runSweepThreads(store, scheduler, slowRecord, 2, {}));
  finished = true;
  reader.join();
  EXPECT_GT(checked, 0);
  store.remove();
}

TEST(SweepStore, RecordsCrossBetweenRanksIntact) {
  std::vector<char> bytes;
  packRecord(bytes, 12, {{1.0, std::nan(""), -0.0}, 2.5, false, "no state here"});
  packRecord(bytes, 40, {{3.0, 4.0, 5.0}, 0.125, true, ""});
  const auto records = unpackRecords(bytes, 3);
  ASSERT_EQ(records.size(), 2U);
  EXPECT_EQ(records[0].first, 12);
  EXPECT_FALSE(records[0].second.ok);
  EXPECT_EQ(records[0].second.reason, "no state here");
  EXPECT_TRUE(std::isnan(records[0].second.values[1]));
  EXPECT_TRUE(std::signbit(records[0].second.values[2]));
  EXPECT_EQ(records[1].second.values, (std::vector<double>{3.0, 4.0, 5.0}));
  EXPECT_EQ(records[1].second.seconds, 0.125);
  bytes.pop_back();
  EXPECT_THROW(unpackRecords(bytes, 3), ComputationError);
  EXPECT_THROW(unpackRecords(std::vector<char>(bytes.begin(), bytes.begin() + 30), 2), ComputationError);
}

} // namespace
} // namespace rv
