#include "dynamics/jobs/SweepStore.h"

#include "dynamics/core/Errors.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <limits>
#include <stdexcept>
#include <thread>
#include <unistd.h>

namespace rv {

namespace {

constexpr char kMagic[] = "rollviz sweep store 1\n";
enum State : unsigned char { kNone = 0, kOk = 1, kFailed = 2 };

void writeAll(int fd, const char* data, std::size_t size, std::int64_t offset, const std::string& path) {
  while (size > 0) {
    const ssize_t n = ::pwrite(fd, data, size, offset);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw ComputationError(path + ": cannot write: " + std::strerror(errno));
    data += n, size -= static_cast<std::size_t>(n), offset += n;
  }
}

bool readAll(int fd, char* data, std::size_t size, std::int64_t offset) {
  while (size > 0) {
    const ssize_t n = ::pread(fd, data, size, offset);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n, size -= static_cast<std::size_t>(n), offset += n;
  }
  return true;
}

template <class T> void put(std::string& out, T v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

std::string header(const std::string& identity, long points, int columns) {
  std::string h(kMagic);
  put<std::int64_t>(h, static_cast<std::int64_t>(identity.size()));
  h += identity;
  put<std::int64_t>(h, points);
  put<std::int32_t>(h, columns);
  h.resize((h.size() + 63) / 64 * 64, '\0'); // records start aligned
  return h;
}

} // namespace

std::size_t SweepStore::recordBytes() const {
  return 8 + 8 + 8 * static_cast<std::size_t>(columns_) + kReasonBytes;
}

SweepStore::SweepStore(std::string path, const std::string& identity, long points, int columns,
                       const std::string& what)
    : path_(std::move(path)), points_(points), columns_(columns), done_(static_cast<std::size_t>(points)) {
  const std::string h = header(identity, points, columns);
  dataOffset_ = static_cast<std::int64_t>(h.size());
  const auto total = dataOffset_ + static_cast<std::int64_t>(recordBytes()) * points;
  fd_ = ::open(path_.c_str(), O_RDWR | O_CLOEXEC);
  if (fd_ < 0 && errno != ENOENT)
    throw InputError(what + " " + path_ + ": cannot open: " + std::strerror(errno));
  if (fd_ < 0) {
    // written whole under a temporary name, then renamed: a run killed here leaves no half header
    const std::string temp = path_ + ".part";
    const int fd = ::open(temp.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw InputError(what + " " + path_ + ": cannot create: " + std::strerror(errno));
    try {
      writeAll(fd, h.data(), h.size(), 0, path_);
      if (::ftruncate(fd, total) != 0)
        throw ComputationError(path_ + ": cannot size the file: " + std::strerror(errno));
    } catch (...) {
      ::close(fd);
      std::remove(temp.c_str());
      throw;
    }
    if (std::rename(temp.c_str(), path_.c_str()) != 0) {
      ::close(fd);
      std::remove(temp.c_str());
      throw InputError(what + " " + path_ + ": cannot create: " + std::strerror(errno));
    }
    fd_ = fd;
    return;
  }
  std::string found(h.size(), '\0');
  if (!readAll(fd_, found.data(), found.size(), 0) || found != h) {
    ::close(fd_);
    fd_ = -1;
    throw InputError(what + " " + path_ +
                     ": belongs to another sweep (or is not a sweep checkpoint); remove it "
                     "or give another file");
  }
  // the status bytes of every record, read in blocks
  const std::size_t rb = recordBytes();
  const long perBlock = std::max<long>(1, static_cast<long>((4u << 20) / rb));
  std::vector<char> block;
  for (long first = 0; first < points; first += perBlock) {
    const long n = std::min(perBlock, points - first);
    block.resize(static_cast<std::size_t>(n) * rb);
    if (!readAll(fd_, block.data(), block.size(), dataOffset_ + static_cast<std::int64_t>(first * rb))) {
      ::close(fd_);
      fd_ = -1;
      throw InputError(what + " " + path_ + ": truncated sweep checkpoint");
    }
    for (long i = 0; i < n; ++i)
      if (const char state = block[static_cast<std::size_t>(i) * rb]; state != kNone) {
        done_[static_cast<std::size_t>(first + i)].store(1, std::memory_order_relaxed);
        ++doneCount_;
        if (state == kFailed) ++failedCount_;
      }
  }
}

SweepStore::~SweepStore() {
  if (fd_ >= 0) ::close(fd_);
}

void SweepStore::write(long index, const SweepRecord& r) {
  std::vector<char> buf(recordBytes(), '\0');
  buf[0] = static_cast<char>(r.ok ? kOk : kFailed);
  std::memcpy(buf.data() + 8, &r.seconds, 8);
  for (int c = 0; c < columns_; ++c) {
    const double v = c < static_cast<int>(r.values.size()) ? r.values[static_cast<std::size_t>(c)]
                                                           : std::numeric_limits<double>::quiet_NaN();
    std::memcpy(buf.data() + 16 + 8 * c, &v, 8);
  }
  std::memcpy(buf.data() + 16 + 8 * columns_, r.reason.data(),
              std::min<std::size_t>(r.reason.size(), kReasonBytes));
  writeAll(fd_, buf.data(), buf.size(), dataOffset_ + static_cast<std::int64_t>(index * recordBytes()),
           path_);
  // after the record is written: a reader that sees the flag reads the whole record
  if (done_[static_cast<std::size_t>(index)].exchange(1, std::memory_order_acq_rel) == 0) {
    ++doneCount_;
    if (!r.ok) ++failedCount_; // a point is written once (a rewrite keeps its first count)
  }
}

SweepRecord SweepStore::read(long index) const {
  std::vector<char> buf(recordBytes());
  if (!readAll(fd_, buf.data(), buf.size(), dataOffset_ + static_cast<std::int64_t>(index * recordBytes())))
    throw ComputationError(path_ + ": cannot read the record of point " + std::to_string(index));
  SweepRecord r;
  r.ok = buf[0] == kOk;
  std::memcpy(&r.seconds, buf.data() + 8, 8);
  r.values.resize(static_cast<std::size_t>(columns_));
  for (int c = 0; c < columns_; ++c)
    std::memcpy(&r.values[static_cast<std::size_t>(c)], buf.data() + 16 + 8 * c, 8);
  const char* reason = buf.data() + 16 + 8 * columns_;
  r.reason.assign(reason, strnlen(reason, kReasonBytes));
  return r;
}

void SweepStore::remove() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::remove(path_.c_str());
}

ChunkScheduler::ChunkScheduler(const SweepStore& store, int workers, long maxChunk, std::vector<char> wanted,
                               int granularity)
    : store_(store), wanted_(std::move(wanted)), left_(0), workers_(std::max(1, workers)),
      maxChunk_(maxChunk > 0 ? maxChunk : 256), granularity_(std::max(1, granularity)) {
  if (!wanted_.empty() && wanted_.size() != static_cast<std::size_t>(store.points()))
    throw std::logic_error("ChunkScheduler: one wanted flag per point");
  for (long i = 0; i < store.points(); ++i)
    left_ += handsOut(i) ? 1 : 0;
}

std::optional<std::vector<long>> ChunkScheduler::next() {
  const std::lock_guard lock(mutex_);
  if (stopped_) return std::nullopt;
  while (cursor_ < store_.points() && !handsOut(cursor_))
    ++cursor_;
  if (cursor_ >= store_.points()) return std::nullopt;
  // a quarter of each worker's share of what is left: big chunks first, single points at the end
  long want = std::clamp(left_ / (4L * workers_), 1L, maxChunk_);
  // whole batches: rounded up to the granularity, down again where that passes maxChunk
  want = (want + granularity_ - 1) / granularity_ * granularity_;
  if (want > maxChunk_ && maxChunk_ >= granularity_) want = maxChunk_ / granularity_ * granularity_;
  std::vector<long> chunk;
  chunk.reserve(static_cast<std::size_t>(want));
  for (; cursor_ < store_.points() && static_cast<long>(chunk.size()) < want; ++cursor_)
    if (handsOut(cursor_)) chunk.push_back(cursor_);
  left_ -= static_cast<long>(chunk.size());
  return chunk;
}

void ChunkScheduler::stop() {
  const std::lock_guard lock(mutex_);
  stopped_ = true;
}

bool ChunkScheduler::finished() const {
  const std::lock_guard lock(mutex_);
  for (long i = 0; i < store_.points(); ++i)
    if (handsOut(i)) return false;
  return true;
}

bool runSweepThreads(SweepStore& store, ChunkScheduler& scheduler,
                     const std::function<SweepRecord(long, const ToolControl&)>& evaluate, int threads,
                     const ToolControl& control) {
  return runSweepThreads(
      store, scheduler,
      [&](const std::vector<long>& chunk, const ToolControl& c, const RecordSink& sink) {
        for (const long index : chunk) {
          if (c.stopRequested()) return;
          sink(index, evaluate(index, c));
        }
      },
      threads, control);
}

bool runSweepThreads(SweepStore& store, ChunkScheduler& scheduler, const ChunkEvaluator& evaluate,
                     int threads, const ToolControl& control) {
  std::atomic<bool> stop{false};
  std::exception_ptr failure; // a disk failure ends the run
  std::mutex failureMutex;
  const ToolControl pointControl{[&] { return stop.load(std::memory_order_relaxed); }, [](double) {}};
  const int count = std::max(1, threads);
  std::atomic<int> active{count}; // counted down by each worker as it ends
  const auto worker = [&] {
    try {
      while (!stop.load()) {
        const auto chunk = scheduler.next();
        if (!chunk) break;
        evaluate(*chunk, pointControl, [&](long index, const SweepRecord& record) {
          if (!stop.load()) store.write(index, record); // points cut short are dropped, not recorded
        });
      }
    } catch (...) {
      const std::lock_guard lock(failureMutex);
      if (!failure) failure = std::current_exception();
      stop = true;
    }
    --active;
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(count));
  for (int t = 0; t < count; ++t) // not `active`: a worker with nothing to do ends (and counts down) at once
    pool.emplace_back(worker);
  const double total = static_cast<double>(std::max(1L, store.points()));
  while (active.load() > 0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    control.progress(static_cast<double>(store.doneCount()) / total);
    if (!stop.load() && control.stopRequested()) {
      stop = true;
      scheduler.stop();
    }
  }
  for (auto& t : pool)
    t.join();
  if (failure) std::rethrow_exception(failure);
  return !stop.load(); // everything handed out was computed (a level of a refined sweep: not every point)
}

void packRecord(std::vector<char>& out, long index, const SweepRecord& r) {
  const auto add = [&out](const void* p, std::size_t n) {
    const auto* c = static_cast<const char*>(p);
    out.insert(out.end(), c, c + n);
  };
  const std::int64_t i = index;
  const std::uint8_t ok = r.ok ? 1 : 0;
  const auto n = static_cast<std::uint32_t>(r.values.size());
  const auto len =
      static_cast<std::uint16_t>(std::min<std::size_t>(r.reason.size(), SweepStore::kReasonBytes));
  add(&i, 8);
  add(&ok, 1);
  add(&r.seconds, 8);
  add(&n, 4);
  add(r.values.data(), 8 * r.values.size());
  add(&len, 2);
  add(r.reason.data(), len);
}

std::vector<std::pair<long, SweepRecord>> unpackRecords(const std::vector<char>& bytes, int columns) {
  std::vector<std::pair<long, SweepRecord>> out;
  std::size_t at = 0;
  const auto take = [&](void* p, std::size_t n) {
    if (at + n > bytes.size()) throw ComputationError("sweep: a truncated message between ranks");
    std::memcpy(p, bytes.data() + at, n);
    at += n;
  };
  while (at < bytes.size()) {
    std::int64_t i = 0;
    std::uint8_t ok = 0;
    std::uint32_t n = 0;
    std::uint16_t len = 0;
    SweepRecord r;
    take(&i, 8);
    take(&ok, 1);
    take(&r.seconds, 8);
    take(&n, 4);
    if (static_cast<int>(n) != columns) throw ComputationError("sweep: a message with the wrong columns");
    r.values.resize(n);
    take(r.values.data(), 8 * static_cast<std::size_t>(n));
    take(&len, 2);
    r.reason.resize(len);
    take(r.reason.data(), len);
    r.ok = ok != 0;
    out.emplace_back(static_cast<long>(i), std::move(r));
  }
  return out;
}

} // namespace rv
