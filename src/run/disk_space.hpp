#pragma once

#include <cstdint>
#include <string>

#include "io/map_layout.hpp"
#include "map/tiling.hpp"
#include "run/preflight.hpp"
#include "sweep/tile_evaluator.hpp"

namespace punchsweep::run {

/// The disk space a map and its journal will take, measured: a few tiles (spread over the
/// grid, for at most about `seconds`) are evaluated by the model and encoded as the sweep
/// encodes them, and their compressed bytes per point are scaled to the grid. The BEM
/// reference's variables are counted uncompressed at the sampled points. The journal holds
/// the same chunks again, plus a record header per tile.
struct DiskEstimate {
  double map_bytes = 0.0;
  double journal_bytes = 0.0;
  std::uint64_t sampled_points = 0;
};

/// `evaluator` is the sweep's (its reference, if any, is skipped); `layout` the map's.
DiskEstimate estimate_disk(const map::Tiling& tiling, const sweep::TileEvaluator& evaluator,
                           const io::MapLayout& layout, double seconds);

/// Bytes free to an unprivileged user on the file system that holds `path`'s folder; a
/// negative number when it cannot be told.
double free_bytes(const std::string& path);

/// "" when the output's file system has room for what this run will still write (the
/// whole map, which a resumed run rebuilds in place of its .partial, and what the journal
/// still lacks), else the refusal with the numbers.
std::string disk_space_problem(const OutputPaths& paths, const DiskEstimate& need);

/// "1.23 GiB", "456 MiB", ...
std::string format_bytes(double bytes);

}  // namespace punchsweep::run
