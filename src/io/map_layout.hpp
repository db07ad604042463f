#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "sweep/grid.hpp"
#include "sweep/sweep_config.hpp"

namespace punchsweep::io {

/// What a regime map holds: its grid, snapshot times, quantities and chunk shape.
struct MapLayout {
  sweep::Grid grid;
  std::vector<double> times;  ///< T_eps; the `time` coordinate (used by the full quantities)
  sweep::Quantities quantities = sweep::Quantities::regime;
  std::array<std::size_t, sweep::kAxes> chunk{};  ///< 5-D chunk shape, each in [1, axis length]

  /// Whether the time series are stored too.
  bool full() const { return quantities == sweep::Quantities::full; }
};

/// Throws std::invalid_argument for an empty axis, a chunk length outside [1, axis length],
/// or full quantities without times.
void require_valid(const MapLayout& layout);

/// Throws std::invalid_argument, naming the axis, unless `box` is non-empty and inside the grid.
void require_inside_grid(const MapLayout& layout, const sweep::TileBox& box);

/// Whether `box` is one whole chunk, or the part of one that lies inside the grid (the
/// boxes that can be stored as one encoded chunk). `box` must lie inside the grid.
bool is_one_chunk(const MapLayout& layout, const sweep::TileBox& box);

/// Throws std::invalid_argument unless `box` lies inside the grid and is_one_chunk.
void require_one_chunk(const MapLayout& layout, const sweep::TileBox& box);

}  // namespace punchsweep::io
