// SweepCommand.cpp -- `rollviz sweep SWEEP.json -o chart.csv [--png chart.png] [--threads N] [--checkpoint
// FILE]`: a chart of regimes on threads, or under `mpirun -n N` on ranks (SweepMpi.h). Records go to a store
// on disk as they finish (dynamics/jobs/SweepStore.h); the CSV is written from it in grid order when every
// point is done, under a temporary name and renamed. With --checkpoint the store is kept when the run is
// killed or stopped, and the next run with the same file computes only the points it lacks.
#include "app/cli/Commands.h"
#include "app/cli/Progress.h"
#include "app/cli/SweepMpi.h"
#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "dynamics/io/FileNames.h"
#include "dynamics/tools/ToolRegistry.h"
#include "render/Snapshot.h"
#include "render/charts/SweepChart.h"
#include "render/context/HeadlessContext.h"
#include "render/export/Figure.h"
#include "render/export/VtkXmlFiles.h"
#include "scenes/Sweep.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fmt/core.h>
#include <fstream>
#include <functional>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <unistd.h>
#include <vtkRenderWindow.h>

namespace rv {

namespace {

struct SweepOptions {
  std::string sweep, output, png, size = "900x700", checkpoint, window;
  int lanes = -1; ///< --lanes: options.lanes for this run (-1: the file's)
  int threads = 0;
  bool timing = false;
};

std::string duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "?";
  const long s = std::lround(seconds);
  if (s < 60) return fmt::format("{}s", s);
  if (s < 3600) return fmt::format("{}m{:02}s", s / 60, s % 60);
  return fmt::format("{}h{:02}m", s / 3600, (s % 3600) / 60);
}

} // namespace

void writeChartFigure(const SweepChartData& data, const std::string& path, std::pair<int, int> pixels,
                      const std::string& what, const ChartStyle& style) {
  const auto chart = makeSweepChart(data);
  auto ctx = createHeadlessContext(pixels.first, pixels.second);
  chart->attach(ctx->window());
  styleCharts(ctx->window(), style);
  writeFigure(ctx->window(), path, what);
}

namespace {

// the grid as image data: a node per point, its columns and cost as arrays (NaN where it failed; a refined
// sweep's points not computed painted from the nearest computed one, their cost NaN)
void writeVti(const SweepSpec& spec, const SweepStore& store, const std::vector<double>& values,
              const std::string& path) {
  ImageGrid image;
  for (std::size_t a = 0; a < spec.axes.size(); ++a) {
    const SweepAxis& axis = spec.axes[a];
    image.size[a] = axis.count;
    image.origin[a] = axis.min;
    image.spacing[a] = axis.count > 1 ? (axis.max - axis.min) / (axis.count - 1) : 1;
    image.axisNames.push_back(spec.axisLabel(a));
  }
  image.arrays.names = spec.columns;
  image.arrays.names.emplace_back("seconds");
  const std::size_t n = spec.columns.size();
  for (long i = 0; i < spec.points(); ++i) {
    const auto at = values.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(i) * n);
    std::vector<double> row(at, at + static_cast<std::ptrdiff_t>(n));
    row.push_back(store.done(i) ? store.read(i).seconds : NAN);
    image.arrays.addRow(row);
  }
  writeImageVti(path, image);
}

// the CSV from the store in grid order: every point, or a refined sweep's computed points
void writeCsv(const SweepSpec& spec, const SweepStore& store, const std::string& path, bool timing) {
  AtomicFile csv(path, "-o");
  std::FILE* f = std::fopen(csv.tempPath().c_str(), "w");
  if (!f) throw InputError("-o " + path + ": cannot write");
  std::string line;
  for (const auto& h : sweepCsvHeader(spec, timing))
    line += (line.empty() ? "" : ",") + h;
  std::fprintf(f, "%s\n", line.c_str());
  for (long i = 0; i < spec.points(); ++i)
    if (store.done(i)) std::fprintf(f, "%s\n", sweepCsvRow(spec, i, store.read(i), timing).c_str());
  const bool ok = std::fflush(f) == 0 && ::fsync(fileno(f)) == 0;
  std::fclose(f);
  if (!ok) throw ComputationError(path + ": cannot write");
  csv.commit();
}

void writeResults(const SweepSpec& spec, const SweepStore& store, const SweepOptions& o) {
  const bool vti = hasExtension(o.output, ".vti");
  SweepChartData data = sweepChartData(spec);
  if (vti || !o.png.empty()) data.values = sweepGridValues(spec, store);
  if (vti)
    writeVti(spec, store, data.values, o.output);
  else
    writeCsv(spec, store, o.output, o.timing);
  if (!o.png.empty()) writeChartFigure(data, o.png, parseSize(o.size), "--png");
}

// the sweep file, over --window's ranges where given (a zoom into its chart)
SweepSpec loadSweepWindow(const std::string& path, const std::string& window) {
  SweepSpec spec = loadSweep(path);
  if (window.empty()) return spec;
  std::vector<double> bounds;
  std::stringstream list(window);
  for (std::string v; std::getline(list, v, ',');) {
    try {
      std::size_t used = 0;
      bounds.push_back(std::stod(v, &used));
      if (used != v.size()) throw std::invalid_argument(v);
    } catch (const std::exception&) {
      throw InputError("--window: '" + v + "' is not a number (x0,x1 or x0,x1,y0,y1)");
    }
  }
  return zoomSweep(spec, bounds, "--window");
}

int runSweep(const SweepOptions& o) {
  const MpiSession mpi;
  const auto world = mpi.world();
  const bool writer = !world || world->rank == 0;
  if (o.threads < 0) throw InputError("--threads: must be at least 1");

  // rank 0 reads and checks everything and opens the store, then hands the resolved sweep to the others
  std::optional<SweepSpec> spec;
  std::unique_ptr<SweepStore> opened;
  std::string resolved;
  const int remote = world ? world->size - 1 : 0;
  const int threads = o.threads > 0 ? o.threads
                      : world       ? 1
                                    : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  const bool keep = !o.checkpoint.empty();
  if (writer) {
    try {
      spec = loadSweepWindow(o.sweep, o.window);
      if (o.lanes >= 0) spec = sweepWithOptions(*spec, {{"lanes", o.lanes}}, "--lanes");
      checkWritable(o.output, "-o");
      if (!o.png.empty()) {
        checkWritable(o.png, "--png");
        (void)parseSize(o.size);
      }
      resolved = spec->resolved.dump();
      const std::string storePath =
          keep ? o.checkpoint : fmt::format("{}.{}.sweep-part", o.output, ::getpid());
      opened =
          std::make_unique<SweepStore>(storePath, resolved, spec->points(),
                                       static_cast<int>(spec->columns.size()), keep ? "--checkpoint" : "-o");
    } catch (...) {
      (void)mpi.broadcast({}); // the other ranks end too
      throw;
    }
  }
  resolved = mpi.broadcast(resolved);
  if (resolved.empty()) return 2;
  if (!writer) {
    const SweepSpec s = sweepFromJson(nlohmann::json::parse(resolved), o.sweep);
    workSweep(mpi, [&s](const std::vector<long>& chunk) { return evaluateSweepPoints(s, chunk, {}); });
    return 0;
  }

  SweepStore& store = *opened;
  struct Cleanup { // a run without --checkpoint leaves no store behind, whatever happens
    SweepStore& store;
    bool keep;
    ~Cleanup() {
      if (!keep) store.remove();
    }
  } cleanup{store, keep};

  const long resumed = store.doneCount();
  std::atomic<long> computed{0};
  // several points at once on SIMD lanes where the quantity can (options.lanes, --lanes)
  const ChunkEvaluator evaluateChunk = [&](const std::vector<long>& chunk, const ToolControl& c,
                                           const RecordSink& sink) {
    evaluateSweepPoints(*spec, chunk, c, [&](long index, const SweepRecord& record) {
      ++computed;
      sink(index, record);
    });
  };
  Progress progress("sweep");
  const auto start = std::chrono::steady_clock::now();
  // on a terminal a live line; elsewhere (mpirun forwards stderr through a pipe, batch logs) a line every 30
  // s
  const bool terminal = ::isatty(STDERR_FILENO) == 1;
  auto logged = start;
  const auto report = [&] {
    const long done = store.doneCount(), total = spec->points();
    const auto clock = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(clock - start).count();
    const long now = done - resumed;
    const double eta = now > 0 ? elapsed / now * (total - done) : NAN;
    // a refined sweep computes a part of its finest grid, how much is known level by level: no ETA
    const std::string detail = spec->refine > 0
                                   ? fmt::format("{} points of the finest grid's {}", done, total)
                                   : fmt::format("{}/{} points, ETA {}", done, total, duration(eta));
    progress.update(static_cast<double>(done) / total, detail);
    if (!terminal && clock - logged >= std::chrono::seconds(30)) {
      logged = clock;
      fmt::print(stderr, "sweep: {:.0f}%  {}\n", 100.0 * done / total, detail);
    }
  };
  ToolControl control;
  control.stopRequested = [] { return interrupted(); };
  control.progress = [&](double) { report(); };
  double bytesPerPoint = 0;
  bool complete = false;
  if (remote > 0) {
    // this rank computes on its threads while its main thread serves the others, level after level of a
    // refined sweep: a level's scheduler hands out to both, and the next level begins once every record of
    // this one is in (the other ranks are told "later" meanwhile)
    ToolControl local;
    local.stopRequested = [] { return interrupted(); };
    std::mutex levelMutex;
    ChunkScheduler* level = nullptr; // the level being handed out
    bool levelsDone = false;
    std::exception_ptr failure;
    std::thread computing([&] {
      try {
        complete = runSweepLevels(*spec, store, threads + remote, [&](ChunkScheduler& scheduler) {
          {
            const std::lock_guard lock(levelMutex);
            level = &scheduler;
          }
          bool finished = runSweepThreads(store, scheduler, evaluateChunk, threads, local);
          while (finished && !scheduler.finished()) { // the other ranks' last chunks of the level
            if (interrupted()) finished = false;
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
          }
          const std::lock_guard lock(levelMutex);
          level = nullptr;
          return finished;
        });
      } catch (...) {
        failure = std::current_exception();
      }
      const std::lock_guard lock(levelMutex);
      levelsDone = true;
    });
    const auto next = [&]() -> ChunkOffer {
      const std::lock_guard lock(levelMutex);
      if (level) {
        if (auto chunk = level->next()) return {ChunkOffer::Kind::Chunk, std::move(*chunk)};
        return {ChunkOffer::Kind::Later};
      }
      return levelsDone ? ChunkOffer{ChunkOffer::Kind::End} : ChunkOffer{ChunkOffer::Kind::Later};
    };
    const SweepTraffic traffic = serveSweep(mpi, store, next, [&] {
      report();
      return interrupted();
    });
    computed += traffic.records;
    bytesPerPoint =
        traffic.records > 0 ? static_cast<double>(traffic.bytes) / static_cast<double>(traffic.records) : 0;
    computing.join();
    if (failure) std::rethrow_exception(failure);
  } else {
    complete = runSweepLevels(*spec, store, threads, [&](ChunkScheduler& scheduler) {
      return runSweepThreads(store, scheduler, evaluateChunk, threads, control);
    });
  }
  progress.clear(); // the summary below takes its line
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (complete) writeResults(*spec, store, o);
  const long failed = store.failedCount();
  fmt::print(
      stderr,
      "sweep: {} points{}: {} computed now, {} from the checkpoint, {} failed; {:.3g} s on {} thread{}{}{}\n",
      spec->points(),
      spec->refine > 0 ? fmt::format(" on the finest grid ({} levels of refinement)", spec->refine) : "",
      computed.load(), resumed, failed, seconds, threads, threads == 1 ? "" : "s",
      remote > 0 ? fmt::format(" and {} more rank{}", remote, remote == 1 ? "" : "s") : "",
      bytesPerPoint > 0 ? fmt::format(", {:.0f} bytes sent per point", bytesPerPoint) : "");
  if (!complete) {
    if (keep) fmt::print(stderr, "sweep: stopped; run again with --checkpoint {} to go on\n", o.checkpoint);
    return 130;
  }
  if (keep) store.remove();
  return 0;
}

} // namespace

Command addSweepCommand(CLI::App& app) {
  // a sweep runs a tool over many scenes: its own command, with the registry entry's name and help
  const ToolEntry& entry = ToolRegistry::global().get("sweep");
  auto* cmd = app.add_subcommand(entry.command, entry.commandHelp);
  auto o = std::make_shared<SweepOptions>();
  cmd->add_option("sweep", o->sweep, "sweep file (JSON: scene, axes, quantity, set, options)")->required();
  cmd->add_option(
         "-o,--output", o->output,
         "CSV file: the axes, the quantity's columns, status (the same file on any threads and ranks); a "
         ".vti file is image data for ParaView (the axes as x, y; the columns and seconds as point data)")
      ->check(writesOneOf({".csv", ".vti"}))
      ->required();
  cmd->add_flag(
      "--timing", o->timing,
      "add the CSV column seconds: what each point cost (the one column that differs between runs)");
  cmd->add_option("--png", o->png, "also draw the chart into this figure: PNG, or SVG or PDF (vectors)")
      ->check(writesOneOf(figureExtensions()));
  cmd->add_option("--size", o->size, "chart size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--threads", o->threads,
                  "computing threads (default: every core; under mpirun, 1 per rank)");
  cmd->add_option("--window", o->window,
                  "x0,x1[,y0,y1]: the axes' ranges instead of the sweep file's (a zoom into its chart; the "
                  "same counts)");
  cmd->add_option(
      "--lanes", o->lanes,
      "1: one point at a time (the scalar path, for comparison); 0: several points on SIMD lanes where "
      "the quantity can, as many as the CPU's registers take (the default; rollviz info names the width); "
      "4 or 8: that many");
  cmd->add_option("--checkpoint", o->checkpoint,
                  "keep finished points in FILE: a sweep killed and started again goes on from there");
  return {cmd, [o] { return runSweep(*o); }};
}

} // namespace rv
