#include "app/cli/SweepMpi.h"

#include "dynamics/core/Errors.h"

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <thread>
#include <vector>

#ifdef ROLLVIZ_HAVE_MPI
#include <mpi.h>
#endif

namespace rv {

namespace {

// launched by mpirun (Open MPI, or a PMI launcher such as MPICH's Hydra or Slurm's srun)
bool launchedByMpirun() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(var)) return true;
  return false;
}

#ifdef ROLLVIZ_HAVE_MPI
constexpr int kRequestTag = 1; // worker -> rank 0: the records of the last chunk (empty at first)
constexpr int kChunkTag = 2;   // rank 0 -> worker: [begin, end), empty when there is no more work
#endif

} // namespace

MpiSession::MpiSession() {
#ifdef ROLLVIZ_HAVE_MPI
  if (!launchedByMpirun()) return;
  int provided = 0;
  // only the main thread calls MPI; computing threads never do
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MpiWorld w;
  MPI_Comm_rank(MPI_COMM_WORLD, &w.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &w.size);
  world_ = w;
#else
  (void)launchedByMpirun;
#endif
}

MpiSession::~MpiSession() {
#ifdef ROLLVIZ_HAVE_MPI
  if (world_) MPI_Finalize();
#endif
}

std::string MpiSession::broadcast(const std::string& text) const {
#ifdef ROLLVIZ_HAVE_MPI
  if (!world_ || world_->size == 1) return text;
  auto size = static_cast<std::int64_t>(text.size());
  MPI_Bcast(&size, 1, MPI_INT64_T, 0, MPI_COMM_WORLD);
  std::string out = world_->rank == 0 ? text : std::string(static_cast<std::size_t>(size), '\0');
  MPI_Bcast(out.data(), static_cast<int>(size), MPI_CHAR, 0, MPI_COMM_WORLD);
  return out;
#else
  return text;
#endif
}

SweepTraffic serveSweep(const MpiSession& mpi, SweepStore& store, ChunkScheduler& scheduler,
                        const std::function<bool()>& poll) {
#ifdef ROLLVIZ_HAVE_MPI
  const auto world = mpi.world();
  SweepTraffic traffic;
  if (!world || world->size == 1) return traffic;
  int working = world->size - 1;
  bool stopping = false;
  std::vector<char> buffer;
  while (working > 0) {
    int waiting = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kRequestTag, MPI_COMM_WORLD, &waiting, &status);
    if (!waiting) {
      // no busy wait: this rank's own threads compute meanwhile; a request waits at most this long
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      if (!stopping && poll()) {
        stopping = true;
        scheduler.stop();
      }
      continue;
    }
    int count = 0;
    MPI_Get_count(&status, MPI_CHAR, &count);
    buffer.resize(static_cast<std::size_t>(count));
    MPI_Recv(buffer.data(), count, MPI_CHAR, status.MPI_SOURCE, kRequestTag, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    for (auto& [index, record] : unpackRecords(buffer, store.columns())) {
      store.write(index, record);
      ++traffic.records;
    }
    traffic.bytes += count;
    std::int64_t chunk[2] = {0, 0};
    if (const auto next = scheduler.next())
      chunk[0] = next->first, chunk[1] = next->second;
    else
      --working;
    MPI_Send(chunk, 2, MPI_INT64_T, status.MPI_SOURCE, kChunkTag, MPI_COMM_WORLD);
  }
  return traffic;
#else
  (void)mpi, (void)store, (void)scheduler, (void)poll;
  return {};
#endif
}

void workSweep(const MpiSession& mpi, int columns, const std::function<SweepRecord(long)>& evaluate) {
#ifdef ROLLVIZ_HAVE_MPI
  (void)mpi, (void)columns; // the session only has to be alive; records carry their own column count
  std::vector<char> results;
  for (;;) {
    MPI_Send(results.data(), static_cast<int>(results.size()), MPI_CHAR, 0, kRequestTag, MPI_COMM_WORLD);
    results.clear();
    std::int64_t chunk[2];
    MPI_Recv(chunk, 2, MPI_INT64_T, 0, kChunkTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (chunk[0] == chunk[1]) return;
    for (std::int64_t i = chunk[0]; i < chunk[1]; ++i)
      packRecord(results, static_cast<long>(i), evaluate(static_cast<long>(i)));
  }
#else
  (void)mpi, (void)columns, (void)evaluate;
#endif
}

} // namespace rv
