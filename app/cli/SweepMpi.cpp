#include "app/cli/SweepMpi.h"

#include "dynamics/core/Errors.h"

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <list>
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
// A worker asks for its next chunk while it computes the current one (double buffering: rank 0's answer is
// never waited for), so it always holds at most two chunks. Every request carries the records of the chunk
// finished before it and is answered at once: a chunk, "later" (begin -1: a refined sweep's level waits for
// its last records -- which may be the ones this worker holds, so it sends them and asks again), or an empty
// chunk when there is no more work (a chunk is its points' indices: a refined level's lie apart); after the
// empty one the worker sends the records of its last chunk and ends.
constexpr int kRequestTag = 1; // worker -> rank 0: records, and a request for a chunk
constexpr int kChunkTag = 2;   // rank 0 -> worker: the indices, {-1}: later, none: no more work
constexpr int kLastTag = 3;    // worker -> rank 0: the records of its last chunk; it ends
// a chunk's point indices (long) go as they are
static_assert(sizeof(long) == sizeof(std::int64_t), "point indices are sent as MPI_INT64_T");
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

SweepTraffic serveSweep(const MpiSession& mpi, SweepStore& store, const std::function<ChunkOffer()>& next,
                        const std::function<bool()>& poll) {
#ifdef ROLLVIZ_HAVE_MPI
  const auto world = mpi.world();
  SweepTraffic traffic;
  if (!world || world->size == 1) return traffic;
  int working = world->size - 1;
  bool stopping = false;
  std::vector<char> buffer;
  // answers on their way: sent without waiting (a blocking send spun this rank's core until the worker took
  // it -- after the chunk it was computing -- and starved this rank's own computing thread: 2 ranks ran at
  // 71-79 % efficiency on two cores), each kept until sent
  std::list<std::pair<MPI_Request, std::vector<long>>> answers;
  const auto sent = [&answers] {
    std::erase_if(answers, [](auto& answer) {
      int done = 0;
      MPI_Test(&answer.first, &done, MPI_STATUS_IGNORE);
      return done != 0;
    });
  };
  auto idle = std::chrono::microseconds(100);
  while (working > 0) {
    sent();
    int waiting = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
    if (!waiting) {
      // no busy wait: this rank's own threads compute meanwhile, and workers ask ahead of need, so a longer
      // sleep (up to 2 ms when nothing comes) costs them nothing
      std::this_thread::sleep_for(idle);
      idle = std::min(2 * idle, std::chrono::microseconds(2000));
      if (!stopping && poll()) stopping = true;
      continue;
    }
    idle = std::chrono::microseconds(100);
    int count = 0;
    MPI_Get_count(&status, MPI_CHAR, &count);
    buffer.resize(static_cast<std::size_t>(count));
    MPI_Recv(buffer.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    for (auto& [index, record] : unpackRecords(buffer, store.columns())) {
      store.write(index, record);
      ++traffic.records;
    }
    traffic.bytes += count;
    if (status.MPI_TAG == kLastTag) {
      --working;
      continue;
    }
    if (!stopping && poll()) stopping = true;
    const ChunkOffer offer = stopping ? ChunkOffer{} : next();
    std::vector<long> chunk; // no more work: none
    if (offer.kind == ChunkOffer::Kind::Chunk) chunk = offer.indices;
    if (offer.kind == ChunkOffer::Kind::Later) chunk = {-1};
    auto& answer = answers.emplace_back(MPI_REQUEST_NULL, std::move(chunk));
    MPI_Isend(answer.second.data(), static_cast<int>(answer.second.size()), MPI_INT64_T, status.MPI_SOURCE,
              kChunkTag, MPI_COMM_WORLD, &answer.first);
  }
  for (auto& answer : answers) // every worker has taken its last answer (it sent kLastTag after it)
    MPI_Wait(&answer.first, MPI_STATUS_IGNORE);
  return traffic;
#else
  (void)mpi, (void)store, (void)next, (void)poll;
  return {};
#endif
}

void workSweep(const MpiSession& mpi,
               const std::function<std::vector<SweepRecord>(const std::vector<long>&)>& evaluate) {
#ifdef ROLLVIZ_HAVE_MPI
  (void)mpi;                 // the session only has to be alive; records carry their own column count
  std::vector<char> results; // the last chunk's records
  std::vector<long> chunk;
  const auto receive = [&chunk] {
    MPI_Status status;
    MPI_Probe(0, kChunkTag, MPI_COMM_WORLD, &status);
    int count = 0;
    MPI_Get_count(&status, MPI_INT64_T, &count);
    chunk.resize(static_cast<std::size_t>(count));
    MPI_Recv(chunk.data(), count, MPI_INT64_T, 0, kChunkTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  };
  MPI_Send(results.data(), 0, MPI_CHAR, 0, kRequestTag, MPI_COMM_WORLD);
  receive();
  while (!chunk.empty()) {
    // ask for the next chunk now (with the last one's records), compute this one, then take the answer. The
    // records go before the computing, sent in full: rank 0 takes them within its poll (a few ms), while a
    // send left in flight (a large message waits for both sides) would keep rank 0's receive waiting until
    // this rank calls MPI again, after its chunk
    MPI_Send(results.data(), static_cast<int>(results.size()), MPI_CHAR, 0, kRequestTag, MPI_COMM_WORLD);
    results.clear();
    if (chunk.front() < 0) // later: the level's last points are being computed elsewhere
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    else {
      const auto records = evaluate(chunk);
      for (std::size_t k = 0; k < chunk.size(); ++k)
        packRecord(results, chunk[k], records.at(k));
    }
    receive();
  }
  MPI_Send(results.data(), static_cast<int>(results.size()), MPI_CHAR, 0, kLastTag, MPI_COMM_WORLD);
#else
  (void)mpi, (void)evaluate;
#endif
}

} // namespace rv
