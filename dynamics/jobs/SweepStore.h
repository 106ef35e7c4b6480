// SweepStore.h -- the results of a sweep (one record per grid point) kept on disk as they arrive, and the
// hand-out of the points still to compute in chunks, on threads or to remote ranks.
//
// The store is a file of fixed-size records, one per point at the point's own offset: results are written in
// whatever order they finish, memory stays bounded for 10^7 points, the final CSV is read through it in grid
// order, and a run killed at any moment (SIGKILL included) and started again on the same file computes only
// the points it has no record of. Its header names the run (the resolved sweep): another run's file is
// refused, never mixed in.
//
// Chunks follow guided self-scheduling (Polychronopoulos & Kuck, IEEE Trans. Comput. 36 (1987) 1425-1439):
// each request gets a share of what is left, so expensive (chaotic) points late in the grid do not leave
// workers idle, and the number of requests stays small. The result of a point never depends on who computed
// it, so the chart is the same bit for bit for any number of threads or ranks.
#pragma once
#include "dynamics/tools/ToolControl.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rv {

/// The outcome of one grid point.
struct SweepRecord {
  std::vector<double> values; ///< the quantity's columns (NaN where it failed)
  double seconds = 0;         ///< what it cost
  bool ok = true;
  std::string reason; ///< why it failed (cut to kReasonBytes)
};

class SweepStore {
public:
  static constexpr int kReasonBytes = 120;
  /// Opens `path`, creating it when missing. InputError naming `what` (e.g. "--checkpoint") when the file
  /// belongs to another run (`identity`, `points`, `columns` differ) or cannot be read or written.
  SweepStore(std::string path, const std::string& identity, long points, int columns,
             const std::string& what);
  ~SweepStore();
  SweepStore(const SweepStore&) = delete;
  SweepStore& operator=(const SweepStore&) = delete;
  long points() const { return points_; }
  int columns() const { return columns_; }
  /// Whether point `index` has a record (read at open; kept up to date by write). Safe to ask from any thread
  /// while others write: a point reads as done only once its record is whole.
  bool done(long index) const {
    return done_[static_cast<std::size_t>(index)].load(std::memory_order_acquire) != 0;
  }
  /// Points with a record.
  long doneCount() const { return doneCount_.load(); }
  /// Points whose record says they failed.
  long failedCount() const { return failedCount_.load(); }
  /// Writes the record of `index` (thread-safe for distinct indices). ComputationError when the disk fails.
  void write(long index, const SweepRecord& record);
  /// The record of a done point.
  SweepRecord read(long index) const;
  /// Removes the file (the run completed and its output is written).
  void remove();
  const std::string& path() const { return path_; }

private:
  std::size_t recordBytes() const;
  std::string path_;
  int fd_ = -1;
  long points_;
  int columns_;
  std::int64_t dataOffset_ = 0;
  std::vector<std::atomic<unsigned char>> done_;
  std::atomic<long> doneCount_{0}, failedCount_{0};
};

/// Hands out the points without a record in chunks: the next ones in index order (consecutive in a plain
/// sweep; a refined sweep's level passes over the points it does not compute, so that its chunks are whole
/// batches too, however far apart its points lie).
class ChunkScheduler {
public:
  /// `workers`: how many ask at once; `maxChunk` bounds a chunk (0: automatic). `wanted` (one flag per point;
  /// empty: all) limits it to some points: a level of a refined sweep. `granularity`: chunks are whole
  /// multiples of it where the points allow (the batch of points computed at once on SIMD lanes: the last
  /// chunks are whole batches, not single points left to the slower one-at-a-time path).
  ChunkScheduler(const SweepStore& store, int workers, long maxChunk = 0, std::vector<char> wanted = {},
                 int granularity = 1);
  /// The indices of the next chunk to compute (ascending), or nothing when every point is handed out (or
  /// after stop()).
  std::optional<std::vector<long>> next();
  /// Hands out nothing more.
  void stop();
  /// Whether every point it hands out (the level's) has a record -- those computed elsewhere (other ranks)
  /// included.
  bool finished() const;

private:
  bool handsOut(long index) const {
    return !store_.done(index) && (wanted_.empty() || wanted_[static_cast<std::size_t>(index)]);
  }
  const SweepStore& store_;
  std::vector<char> wanted_;
  mutable std::mutex mutex_;
  long cursor_ = 0, left_;
  int workers_;
  long maxChunk_;
  long granularity_;
  bool stopped_ = false;
};

/// Computes every point the scheduler hands out on `threads` threads: `evaluate(index, control)` never
/// throws (a failure is a record with ok = false), its record is written to the store. `control` stops it
/// (points in progress are finished or dropped, never half-written); its progress is the fraction of all
/// points done. Returns whether every point the scheduler hands out has a record (false: stopped).
bool runSweepThreads(SweepStore& store, ChunkScheduler& scheduler,
                     const std::function<SweepRecord(long, const ToolControl&)>& evaluate, int threads,
                     const ToolControl& control);
/// Receives the record of a point as soon as it is computed.
using RecordSink = std::function<void(long index, const SweepRecord& record)>;
/// Computes the points of a chunk, each record handed to the sink as computed: several points at once on
/// SIMD lanes where it can, in batches it forms itself (a point that cannot go on a lane -- no state at its
/// values -- leaves no lane idle: the next point takes it). Stops between batches when the control asks.
using ChunkEvaluator = std::function<void(const std::vector<long>&, const ToolControl&, const RecordSink&)>;
/// The same, a chunk at a time; a record computed after a stop (cut short) is dropped, not written.
bool runSweepThreads(SweepStore& store, ChunkScheduler& scheduler, const ChunkEvaluator& evaluate,
                     int threads, const ToolControl& control);

/// Packs records for sending between ranks: per record the index, status, cost, values and reason.
void packRecord(std::vector<char>& out, long index, const SweepRecord& record);
/// Unpacks what packRecord wrote; ComputationError when the bytes are truncated.
std::vector<std::pair<long, SweepRecord>> unpackRecords(const std::vector<char>& bytes, int columns);

} // namespace rv
