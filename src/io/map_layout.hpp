#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "map/grid.hpp"
#include "map/quantities.hpp"

namespace punchsweep::io {

/// The periodic BEM reference a map holds: its bem_* variables are stored, and these
/// numbers become the global attributes bem_grid, bem_tolerance, bem_sample, bem_seed and
/// bem_method.
struct BemSetup {
  int grid = 0;              ///< BEM nodes per side of the l x l cell
  double tolerance = 0.0;    ///< the contact solver's conjugate-gradient tolerance
  std::int64_t sample = 0;   ///< number of grid points evaluated
  std::int64_t seed = 0;     ///< seed of the random sample
  std::string method;        ///< one line naming the method
  std::string sample_rule = "all";  ///< how the points were picked: all, random, invalid or boundary
};

/// What a regime map holds: its grid, snapshot times, quantities, chunk shape and reference.
struct MapLayout {
  map::Grid grid;
  std::vector<double> times;  ///< T_eps; the `time` coordinate (of the full quantities and bem_* series)
  map::Quantities quantities = map::Quantities::regime;
  map::Index chunk;                ///< chunk shape over the grid's axes, each in [1, axis length]
  std::optional<BemSetup> bem;                    ///< set: the bem_* variables are stored
  /// The box of tolerances about each point (output.tolerance, as given), where the map has
  /// one: t_star_low, t_star_high, regime_low and regime_high are stored, and it becomes the
  /// global attribute `tolerance`.
  std::string tolerance;

  /// Whether the model's time series are stored too.
  bool full() const { return quantities == map::Quantities::full; }
  /// Whether the map stores quantity `spec`.
  bool stores(const map::QuantitySpec& spec) const {
    return map::is_stored(spec, quantities, bem.has_value(), !tolerance.empty());
  }
  /// Whether any variable runs over the time axis.
  bool has_series() const { return full() || bem.has_value(); }
};

/// Throws std::invalid_argument for an empty axis, a chunk length outside [1, axis length],
/// or time series (full quantities or a BEM reference) without times.
void require_valid(const MapLayout& layout);

/// Throws std::invalid_argument, naming the axis, unless `box` is non-empty and inside the grid.
void require_inside_grid(const MapLayout& layout, const map::TileBox& box);

/// Whether `box` is one whole chunk, or the part of one that lies inside the grid (the
/// boxes that can be stored as one encoded chunk). `box` must lie inside the grid.
bool is_one_chunk(const MapLayout& layout, const map::TileBox& box);

/// Throws std::invalid_argument unless `box` lies inside the grid and is_one_chunk.
void require_one_chunk(const MapLayout& layout, const map::TileBox& box);

}  // namespace punchsweep::io
