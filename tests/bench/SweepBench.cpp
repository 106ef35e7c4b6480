// Sweep benchmarks: points per second of a MEGNO chart of the Henon-Heiles section on 1 and 2 threads (the
// parallel efficiency is their ratio over 2), the cost of the store (a point written and read back), and the
// bytes a record takes between MPI ranks. The ranks' own scaling is measured by sweep_scaling.sh (mpirun).
#include "dynamics/jobs/SweepStore.h"
#include "scenes/SceneLoader.h"
#include "scenes/Sweep.h"

#include <benchmark/benchmark.h>
#include <filesystem>
#include <unistd.h>

namespace {

using namespace rv;

SweepSpec henonHeilesChart(int count) {
  nlohmann::json doc{{"scene", defaultScenePath("henon_heiles")},
                     {"axes",
                      {{{"id", "map.0"}, {"min", -0.3}, {"max", 0.3}, {"count", count}},
                       {{"id", "map.1"}, {"min", -0.3}, {"max", 0.3}, {"count", count}}}},
                     {"quantity", "megno"},
                     {"set", {{"megno.time", 200}}}};
  return sweepFromJson(doc, "bench.json");
}

std::string storePath() {
  return (std::filesystem::temp_directory_path() / ("bench-sweep." + std::to_string(::getpid()))).string();
}

void SweepThreads(benchmark::State& state) {
  const SweepSpec spec = henonHeilesChart(12);
  const int threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    std::filesystem::remove(storePath());
    SweepStore store(storePath(), "bench", spec.points(), static_cast<int>(spec.columns.size()), "bench");
    ChunkScheduler scheduler(store, threads);
    runSweepThreads(store, scheduler,
                    [&](long i, const ToolControl& c) { return evaluateSweepPoint(spec, i, c); }, threads,
                    {});
    store.remove();
  }
  state.counters["points/s"] =
      benchmark::Counter(static_cast<double>(spec.points()) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

void SweepStoreWriteRead(benchmark::State& state) {
  std::filesystem::remove(storePath());
  SweepStore store(storePath(), "bench", 100000, 1, "bench");
  long i = 0;
  const SweepRecord r{{1.5}, 0.01, true, ""};
  for (auto _ : state) {
    store.write(i, r);
    benchmark::DoNotOptimize(store.read(i));
    i = (i + 7919) % 100000;
  }
  store.remove();
}

void SweepRecordBytes(benchmark::State& state) {
  std::vector<char> bytes;
  for (auto _ : state) {
    bytes.clear();
    packRecord(bytes, 123456, {{2.0}, 0.01, true, ""});
    benchmark::DoNotOptimize(bytes.data());
  }
  state.counters["bytes/point"] = static_cast<double>(bytes.size());
}

} // namespace

BENCHMARK(SweepThreads)->Arg(1)->Arg(2)->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(SweepStoreWriteRead);
BENCHMARK(SweepRecordBytes);
