#pragma once
/// @file
/// The sweep's driver side of MPI: the session a command holds, and the few collective
/// steps it takes outside the scheduler (rank 0's verdicts shared with every rank, the
/// world's schedule, an abort). With the scheduler (scheduler.hpp) these are the engine's
/// only MPI calls; the command line (app/) sees none.

#include <cstdint>
#include <csignal>
#include <vector>

#include "sweep/scheduler.hpp"

namespace punchsweep::sweep {

/// MPI for the life of a command (MPI_Init_thread, FUNNELED, to MPI_Finalize). Under Open
/// MPI's launcher a rank does not outlive it (Linux: the parent's death kills it), so after
/// `kill -9 mpirun` no orphan goes on writing the map that --resume is about to rebuild.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0;
  int size_ = 1;
};

/// Rank 0's value, on every rank (collective).
int share_from_root(int value);
std::uint64_t share_from_root(std::uint64_t value);

/// The greatest of every rank's status, and the lowest rank that has it (collective): after
/// a step each rank may fail in alone, the one that says why.
struct RankStatus {
  int status = 0;
  int rank = 0;
};
RankStatus worst_status(int status);

/// Every rank's `mine`, one after the other in rank order, on rank 0 (empty on the others;
/// collective).
std::vector<double> gather_to_root(const std::vector<double>& mine);

/// run_schedule over all the ranks of the session.
ScheduleResult run_world_schedule(const TileRanges& pending, const TileWork& work, const TileSink& sink,
                                  const volatile std::sig_atomic_t* stop, Pace pace = Pace::tiles);

/// Ends every rank at once with `code` (a rank that failed leaves the others no way on).
[[noreturn]] void abort_all_ranks(int code);

}  // namespace punchsweep::sweep
