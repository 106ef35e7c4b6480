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

// the whole sweep on one thread, in whole batches as runSweepLevels chunks it
void sweepOnOneThread(const SweepSpec& spec) {
  std::filesystem::remove(storePath());
  SweepStore store(storePath(), "bench", spec.points(), static_cast<int>(spec.columns.size()), "bench");
  ChunkScheduler scheduler(store, 1, 0, {}, sweepBatch(spec));
  runSweepThreads(store, scheduler,
                  [&](const std::vector<long>& chunk, const ToolControl& c, const RecordSink& sink) {
                    evaluateSweepPoints(spec, chunk, c, sink);
                  },
                  1, {});
  store.remove();
}

// MEGNO over initial points, one thread: several points at once on SIMD lanes (0: the CPU's width; 4; 8)
// against one at a time (1). With rk4 (h = 0.01) each lane is the scalar run bit for bit; with the scene's
// Everhart 15 (h = 0.05) and adams (order 12, h = 0.05) a sweep runs one point at a time either way
// (scenes/builtin/MegnoTool.cpp says why): their rows show that it costs nothing
void SweepLanes(benchmark::State& state) {
  const char* method = state.range(1) == 0 ? "everhart" : state.range(1) == 1 ? "rk4" : "adams";
  nlohmann::json doc{{"scene", defaultScenePath("henon_heiles")},
                     {"axes",
                      {{{"id", "map.0"}, {"min", -0.3}, {"max", 0.3}, {"count", 8}},
                       {{"id", "map.1"}, {"min", -0.3}, {"max", 0.3}, {"count", 8}}}},
                     {"quantity", "megno"},
                     {"set", {{"megno.time", 200}}},
                     {"options", {{"lanes", state.range(0)}}}};
  if (state.range(1) == 1) doc["set"].update({{"integrator.method", "rk4"}, {"integrator.step", 0.01}});
  if (state.range(1) == 2)
    doc["set"].update({{"integrator.method", "adams"}, {"integrator.step", 0.05}, {"integrator.order", 12}});
  const SweepSpec spec = sweepFromJson(doc, "bench.json");
  for (auto _ : state)
    sweepOnOneThread(spec);
  state.SetLabel(method);
  state.counters["points/s"] =
      benchmark::Counter(static_cast<double>(spec.points()) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

// The largest Lyapunov exponent of Lorenz over rho (scenes/sweeps/lorenz_lyapunov_rho.json: rk4, h = 0.001,
// 16 values of rho, lyapunov.time 50), one thread: a parameter per lane, four (AVX2) or eight (AVX-512)
// points at once against one at a time (1), each lane the scalar run bit for bit
void SweepLanesLyapunov(benchmark::State& state) {
  nlohmann::json doc{{"scene", defaultScenePath("lorenz")},
                     {"axes", {{{"id", "rho"}, {"min", 0.5}, {"max", 250}, {"count", 16}}}},
                     {"quantity", "lyapunov.max"},
                     {"set", {{"lyapunov.time", 50}}},
                     {"options", {{"lanes", state.range(0)}}}};
  const SweepSpec spec = sweepFromJson(doc, "bench.json");
  for (auto _ : state)
    sweepOnOneThread(spec);
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
BENCHMARK(SweepLanes)
    ->Args({1, 0})
    ->Args({0, 0})
    ->Args({1, 1})
    ->Args({4, 1})
    ->Args({8, 1})
    ->Args({1, 2})
    ->Args({0, 2})
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(SweepLanesLyapunov)
    ->Arg(1)
    ->Arg(4)
    ->Arg(8)
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(SweepStoreWriteRead);
BENCHMARK(SweepRecordBytes);
