#pragma once

#include <mpi.h>

#include <csignal>
#include <cstddef>
#include <functional>
#include <vector>

#include "io/tile_data.hpp"
#include "sweep/tile_evaluator.hpp"
#include "sweep/tiling.hpp"

namespace punchsweep::sweep {

/// Receives each finished tile on rank 0 (writes it to the map and the journal).
using TileSink = std::function<void(std::size_t tile, const io::TileData& data)>;

/// How a sweep ended on rank 0.
struct ScheduleResult {
  std::size_t tiles_done = 0;  ///< tiles finished by this run (not counting resumed ones)
  bool interrupted = false;    ///< a stop was requested before every tile was handed out
};

/// Dynamic manager/worker scheduling of tiles over the ranks of `comm`.
///
/// Rank 0 is the manager: it hands out batches of tile indices (guided sizes: a batch is
/// about the remaining tiles / (4 * ranks), at least 1; two batches in flight per worker so
/// no worker waits for the next), receives each tile's results as one packed message and
/// passes them to `sink`, and between those duties computes tiles itself, so N ranks use N
/// cores. With one rank it simply computes every tile. When `*stop` becomes non-zero
/// (SIGTERM, SIGUSR1, SIGINT) the manager stops handing out work, tells the workers to
/// finish the tile in hand, and collects what was computed; untouched tiles stay pending.
///
/// Called collectively. `pending` (rank 0 only) lists the tiles still to compute.
ScheduleResult run_schedule(MPI_Comm comm, const Tiling& tiling, const TileEvaluator& evaluator,
                            const std::vector<std::size_t>& pending, const TileSink& sink,
                            const volatile std::sig_atomic_t* stop);

}  // namespace punchsweep::sweep
