// SweepMpi.h -- `mpirun -n N rollviz sweep ...`: rank 0 reads the sweep, writes the store and the chart, and
// computes on its own threads; ranks 1..N-1 compute the chunks rank 0 hands out on demand (dynamic load
// balancing: a rank that finishes early asks again) and send their records back with the next request. The
// transport is Open MPI (MPI-3, Gropp, Lusk & Skjellum, "Using MPI", 3rd ed., MIT Press 2014); built without
// MPI, or not started by mpirun, rollviz runs the sweep on threads alone.
#pragma once
#include "dynamics/jobs/SweepStore.h"

#include <functional>
#include <optional>
#include <string>

namespace rv {

/// This process's place among the ranks.
struct MpiWorld {
  int rank = 0, size = 1;
};

/// Starts MPI when this process was launched by mpirun (its environment says so) and rollviz was built
/// with MPI; nothing otherwise. The session ends (MPI_Finalize) when the returned guard is destroyed.
class MpiSession {
public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  /// The world, when running under mpirun.
  std::optional<MpiWorld> world() const { return world_; }
  /// Rank 0's `text` on every rank (rank 0 passes it, the others receive it).
  std::string broadcast(const std::string& text) const;

private:
  std::optional<MpiWorld> world_;
};

/// What the other ranks sent.
struct SweepTraffic {
  long records = 0; ///< points they computed
  long bytes = 0;   ///< bytes of records received
};

/// What rank 0 answers a rank that asks for work.
struct ChunkOffer {
  enum class Kind {
    Chunk, ///< the points `indices`
    Later, ///< none yet: a level of a refined sweep waits for its last points (the next level follows from
           ///< them)
    End    ///< no more work
  } kind = Kind::End;
  std::vector<long> indices = {};
};

/// Rank 0: answers the other ranks' requests for chunks with `next` and writes the records they send into
/// `store` until every rank has been told there is no more work. `poll` runs between messages (progress,
/// Ctrl-C: it returns true to stop handing out work).
SweepTraffic serveSweep(const MpiSession& mpi, SweepStore& store, const std::function<ChunkOffer()>& next,
                        const std::function<bool()>& poll);

/// Ranks 1..N-1: asks rank 0 for chunks, computes their points with `evaluate` (a record per index, in the
/// chunk's order; SIMD lanes as it forms its batches) and sends the records back, until rank 0 has no more
/// work.
void workSweep(const MpiSession& mpi,
               const std::function<std::vector<SweepRecord>(const std::vector<long>&)>& evaluate);

} // namespace rv
