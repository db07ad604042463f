#pragma once

#include <chrono>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "io/map_layout.hpp"
#include "io/regime_map_writer.hpp"
#include "io/tile_journal.hpp"
#include "map/tiling.hpp"
#include "run/preflight.hpp"
#include "run/progress.hpp"
#include "sweep/tile_ranges.hpp"

namespace punchsweep::run {

/// Rank 0's side of a sweep: the map under construction (OutputPaths::partial), its
/// journal and the progress. The HDF5 file is always rebuilt: after kill -9 it may be
/// damaged, the journal not. On Start::resume the journal's tiles are replayed into it
/// first and only the rest are pending; every tile that arrives is journalled before it
/// is written, so a map can always be finished from its journal.
class MapRun {
 public:
  /// `start` must be fresh or resume (preflight's verdict). Throws on I/O errors.
  MapRun(const sweep::SweepConfig& config, const io::MapLayout& layout, const io::MapAttributes& attributes,
         Start start, const map::Tiling& tiling, std::ostream& log);

  /// The tiles still to compute.
  const sweep::TileRanges& pending() const { return pending_; }

  /// The scheduler's sink: journals and writes one tile packed by io::pack_encoded_tile.
  void accept(std::span<const std::byte> bytes);

  /// After a stop signal: hands what was written to the operating system; the journal
  /// keeps the finished tiles for --resume.
  void interrupt();

  /// Completes the map: run statistics, `completed` = 1, the .partial renamed to the final
  /// name, the journal removed, the summary printed.
  void finish(int ranks);

  const Progress& progress() const { return progress_; }
  const OutputPaths& paths() const { return paths_; }

 private:
  OutputPaths paths_;
  const map::Tiling& tiling_;
  io::RegimeMapWriter writer_;
  Progress progress_;
  std::optional<io::TileJournal> journal_;
  sweep::TileRanges pending_;
  std::chrono::steady_clock::time_point last_flush_;
};

/// The map's layout for a sweep: grid, times, quantities, the tiling's chunks and, with a
/// reference, its grid, solver tolerance and sample size.
io::MapLayout map_layout(const sweep::SweepConfig& config, const map::Tiling& tiling,
                         const std::optional<std::uint64_t>& reference_points, double reference_tolerance);

}  // namespace punchsweep::run
