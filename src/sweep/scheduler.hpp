#pragma once

#include <mpi.h>

#include <csignal>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "sweep/tile_ranges.hpp"

namespace punchsweep::sweep {

/// Computes one tile, by its index, into the bytes that travel to rank 0 (the sweep packs
/// its encoded chunks: io::pack_encoded_tile), or into none when it gave the tile up on a
/// stop signal (the tile then stays pending). Called on every rank.
using TileWork = std::function<std::vector<std::byte>(std::uint64_t tile)>;

/// Receives each finished tile's bytes on rank 0.
using TileSink = std::function<void(std::span<const std::byte> bytes)>;

/// How a sweep ended on rank 0.
struct ScheduleResult {
  std::size_t tiles_done = 0;  ///< tiles finished by this run (not counting resumed ones)
  bool interrupted = false;    ///< a stop was requested before every tile was handed out
  int stop_signal = 0;         ///< the stop signal, 0 if none
  int stop_rank = 0;           ///< the rank that received it (rank 0 or a worker)
};

/// Dynamic manager/worker scheduling of tiles over the ranks of `comm`.
///
/// Rank 0 is the manager: it hands out batches of tiles as index ranges (guided sizes: a
/// batch is about the remaining tiles / (4 * ranks), at least 1 and at most 256; two batches
/// in flight per worker so no worker waits for the next), receives each tile as one message of `work`'s bytes and
/// passes it to `sink`, and between those duties computes tiles itself, so N ranks use N
/// cores. Every rank turns the tiles it computes into bytes itself (the sweep compresses
/// there), so the manager's share of the file writing stays a copy of bytes however many
/// workers there are. With one rank it simply computes every tile. When `*stop` becomes
/// non-zero (SIGTERM, SIGUSR1, SIGINT) on rank 0, or on any worker (which tells rank 0 and
/// starts no further tile), the manager stops handing out work, tells the workers to
/// finish or give up the tile in hand (`work` decides: the sweep gives up within a point),
/// and collects what was computed; untouched and given-up tiles stay pending.
/// The scheduler knows nothing of grids, models or files.
///
/// Called collectively. `pending` (rank 0 only) holds the tiles still to compute; no memory
/// of the schedule grows with the number of tiles.
///
/// `pace` says what a tile costs: Pace::tiles (microseconds to milliseconds a point: two
/// guided batches queued at each worker, so none waits for the next) or Pace::units (a
/// tile is seconds to minutes of work, such as a texture's load curve: one tile at a time
/// to each worker, handed out as it finishes, so no worker holds a queue while another is
/// idle), or Pace::readings (units, the first of them long, most a fraction of a second,
/// such as a texture map's tiles read off curves built once: one tile at a time to each
/// worker at first, then two queued at each, so that none waits while rank 0 computes).
enum class Pace { tiles, units, readings };
ScheduleResult run_schedule(MPI_Comm comm, const TileRanges& pending, const TileWork& work,
                            const TileSink& sink, const volatile std::sig_atomic_t* stop, Pace pace = Pace::tiles);

}  // namespace punchsweep::sweep
