#pragma once
/// @file
/// The layouts of the map files, in each file's `layout_version` attribute, so that a reader
/// knows what it holds and refuses a layout newer than it knows (Python's open_map: its
/// LAYOUT_VERSIONS say the same numbers, and a test holds them to these).

namespace punchsweep::map {

/// A regime map (`punchsweep sweep` of the two-level square lattice: HDF5, regime and t*
/// over the grid's axes): 1. Maps written before the attribute carry none and are read as 1.
inline constexpr int kRegimeLayoutVersion = 1;

/// A texture's map (`sweep` with [texture], `surface-map`: netCDF-4, a `level` dimension,
/// map::kTextureQuantities): 2 since it is written through the sweep's journal, with an
/// `identity` and no curve_seconds variable; 1 (or none) before.
inline constexpr int kTextureLayoutVersion = 2;

}  // namespace punchsweep::map
