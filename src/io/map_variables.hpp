#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "io/map_layout.hpp"
#include "map/quantities.hpp"
#include "map/tile_data.hpp"

namespace punchsweep::io {

/// What never-written cells of the flag variables read as (the HDF5 fill value).
inline constexpr std::int8_t kNotComputed = map::kNotComputed;

/// Deflate level of every variable: level 1, because the sweep must write > 2e6 points/s.
inline constexpr unsigned kDeflateLevel = 1;

/// The quantities (indices into map::kQuantities) a map of `layout` stores as data
/// variables, in kQuantities order: the order the writer creates them and of an
/// EncodedTile's chunks.
std::vector<std::size_t> stored_variables(const MapLayout& layout);

/// Uncompressed bytes per grid point of a map of `layout` (all its stored variables).
std::size_t uncompressed_bytes_per_point(const MapLayout& layout);

/// Throws std::invalid_argument naming the array unless every array of `data` has the
/// length a tile of `points` points needs in a map of `layout` (the arrays of variables
/// the map does not store empty).
void require_tile_arrays(const MapLayout& layout, std::size_t points, const map::TileData& data);

}  // namespace punchsweep::io
