#include "sweep/mpi_session.hpp"

#include <mpi.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include <cstdlib>

namespace punchsweep::sweep {

MpiSession::MpiSession() {
#ifdef __linux__
  // Only under the launcher: a singleton run may well be meant to outlive its shell.
  if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() == 1) std::_Exit(1);  // the launcher died before prctl took effect
  }
#endif
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() { MPI_Finalize(); }

int share_from_root(int value) {
  MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

RankStatus worst_status(int status) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  RankStatus out;
  MPI_Allreduce(&status, &out.status, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  const int mine = status == out.status ? rank : size;
  MPI_Allreduce(&mine, &out.rank, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return out;
}

std::vector<double> gather_to_root(const std::vector<double>& mine) {
  int size = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(size), 0), offsets(static_cast<std::size_t>(size), 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<double> all;
  if (rank == 0) {
    for (int r = 1; r < size; ++r) offsets[static_cast<std::size_t>(r)] = offsets[static_cast<std::size_t>(r - 1)] + counts[static_cast<std::size_t>(r - 1)];
    all.resize(static_cast<std::size_t>(offsets.back() + counts.back()));
  }
  MPI_Gatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  return all;
}

std::uint64_t share_from_root(std::uint64_t value) {
  MPI_Bcast(&value, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  return value;
}

ScheduleResult run_world_schedule(const TileRanges& pending, const TileWork& work, const TileSink& sink,
                                  const volatile std::sig_atomic_t* stop, Pace pace) {
  return run_schedule(MPI_COMM_WORLD, pending, work, sink, stop, pace);
}

void abort_all_ranks(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::abort();  // MPI_Abort does not return; the compiler does not know it
}

}  // namespace punchsweep::sweep
