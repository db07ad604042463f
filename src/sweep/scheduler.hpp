#pragma once

#include <mpi.h>

#include <csignal>
#include <cstddef>
#include <functional>
#include <vector>

#include "io/encoded_tile.hpp"
#include "io/tile_encoder.hpp"
#include "sweep/tile_evaluator.hpp"
#include "sweep/tiling.hpp"

namespace punchsweep::sweep {

/// Receives each finished tile on rank 0, encoded (writes it to the journal and the map;
/// its box is the tiling's box of `tile.tile`).
using TileSink = std::function<void(const io::EncodedTile& tile)>;

/// How a sweep ended on rank 0.
struct ScheduleResult {
  std::size_t tiles_done = 0;  ///< tiles finished by this run (not counting resumed ones)
  bool interrupted = false;    ///< a stop was requested before every tile was handed out
};

/// Dynamic manager/worker scheduling of tiles over the ranks of `comm`.
///
/// Rank 0 is the manager: it hands out batches of tile indices (guided sizes: a batch is
/// about the remaining tiles / (4 * ranks), at least 1; two batches in flight per worker so
/// no worker waits for the next), receives each tile as one packed EncodedTile message and
/// passes it to `sink`, and between those duties computes tiles itself, so N ranks use N
/// cores. Every rank encodes (compresses) the tiles it computes with `encoder`, so the
/// manager's share of the file writing stays a copy of bytes however many workers there
/// are. With one rank it simply computes every tile. When `*stop` becomes non-zero
/// (SIGTERM, SIGUSR1, SIGINT) the manager stops handing out work, tells the workers to
/// finish the tile in hand, and collects what was computed; untouched tiles stay pending.
///
/// Called collectively. `encoder` has the map's layout, whose chunk shape is the tiling's.
/// `pending` (rank 0 only) lists the tiles still to compute.
ScheduleResult run_schedule(MPI_Comm comm, const Tiling& tiling, const TileEvaluator& evaluator,
                            io::TileEncoder& encoder, const std::vector<std::size_t>& pending,
                            const TileSink& sink, const volatile std::sig_atomic_t* stop);

}  // namespace punchsweep::sweep
