#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "io/map_layout.hpp"
#include "io/tile_data.hpp"

namespace punchsweep::io {

/// One data variable of the regime map and the TileData array it comes from.
struct VariableSpec {
  const char* name;
  bool series;        ///< over (l, dh, T, pbar, s, time) rather than the 5 axes
  bool bem;           ///< of the periodic BEM reference (stored with MapLayout::bem)
  const char* units;  ///< nullptr for the flag variables, which have none
  const char* long_name;
  const char* comment;                        ///< nullptr when there is none
  std::vector<std::int8_t> TileData::*codes;  ///< int8 source, or nullptr
  std::vector<double> TileData::*values;      ///< float64 source, or nullptr
};

/// The data variables in the order the writer creates them, which is also the order of an
/// EncodedTile's chunks (stored_variables picks those of a layout). The model's series are
/// stored only with Quantities::full, the bem_* variables only with a BEM reference.
inline constexpr std::array<VariableSpec, 20> kVariables{{
    {"regime", false, false, nullptr, "contact regime of the level-2 punches", nullptr, &TileData::regime, nullptr},
    {"valid", false, false, nullptr, "validity of the localization method", nullptr, &TileData::valid, nullptr},
    {"t_star", false, false, "T_eps", "time at which the level-2 punches touch",
     "0 for the immediate regime, NaN for never", nullptr, &TileData::t_star},
    {"h_0", false, false, "R", "displacement difference between punch tip and square centre at t = 0", nullptr,
     nullptr, &TileData::h_0},
    {"h_inf", false, false, "R", "displacement difference between punch tip and square centre as t -> infinity",
     nullptr, nullptr, &TileData::h_inf},
    {"a1_inf", false, false, "R", "long-term contact radius of a level-1 punch", nullptr, nullptr,
     &TileData::a1_inf},
    {"a2_inf", false, false, "R", "long-term contact radius of a level-2 punch", nullptr, nullptr,
     &TileData::a2_inf},
    {"area_fraction_inf", false, false, "1", "long-term contact area fraction", nullptr, nullptr,
     &TileData::area_fraction_inf},
    {"a1", true, false, "R", "contact radius of a level-1 punch", nullptr, nullptr, &TileData::a1},
    {"a2", true, false, "R", "contact radius of a level-2 punch", nullptr, nullptr, &TileData::a2},
    {"P1", true, false, "R^2 E0/(1-nu^2)", "load on one level-1 punch", nullptr, nullptr, &TileData::P1},
    {"P2", true, false, "R^2 E0/(1-nu^2)", "load on one level-2 punch", nullptr, nullptr, &TileData::P2},
    {"area_fraction", true, false, "1", "contact area fraction", nullptr, nullptr, &TileData::area_fraction},
    {"bem_regime", false, true, nullptr, "periodic BEM reference: contact regime of the level-2 punches",
     "not_computed at grid points outside the reference sample", &TileData::bem_regime, nullptr},
    {"bem_t_star", false, true, "T_eps", "periodic BEM reference: time at which the level-2 punches touch",
     "0 for the immediate regime; NaN for never, for delayed beyond the last snapshot time, and outside the "
     "reference sample",
     nullptr, &TileData::bem_t_star},
    {"bem_a1", true, true, "R", "periodic BEM reference: contact radius of a level-1 punch",
     "equivalent radius sqrt(area / pi) of the grid nodes in contact; NaN outside the reference sample",
     nullptr, &TileData::bem_a1},
    {"bem_a2", true, true, "R", "periodic BEM reference: contact radius of a level-2 punch",
     "equivalent radius sqrt(area / pi) of the grid nodes in contact; NaN outside the reference sample",
     nullptr, &TileData::bem_a2},
    {"bem_P1", true, true, "R^2 E0/(1-nu^2)", "periodic BEM reference: load on one level-1 punch",
     "NaN outside the reference sample", nullptr, &TileData::bem_P1},
    {"bem_P2", true, true, "R^2 E0/(1-nu^2)", "periodic BEM reference: load on one level-2 punch",
     "NaN outside the reference sample", nullptr, &TileData::bem_P2},
    {"bem_area_fraction", true, true, "1", "periodic BEM reference: contact area fraction",
     "NaN outside the reference sample", nullptr, &TileData::bem_area_fraction},
}};

/// What never-written cells of the flag variables read as (the HDF5 fill value).
inline constexpr std::int8_t kNotComputed = -1;

/// Deflate level of every variable: level 1, because the sweep must write > 2e6 points/s.
inline constexpr unsigned kDeflateLevel = 1;

/// Whether a map of `layout` stores `spec`.
inline bool is_stored(const VariableSpec& spec, const MapLayout& layout) {
  if (spec.bem) return layout.bem.has_value();
  return !spec.series || layout.full();
}

/// The variables a map of `layout` stores, in kVariables order.
std::vector<const VariableSpec*> stored_variables(const MapLayout& layout);

/// Uncompressed bytes per grid point of a map of `layout` (all its stored variables).
std::size_t uncompressed_bytes_per_point(const MapLayout& layout);

/// Throws std::invalid_argument naming the array unless every array of `data` has the
/// length a tile of `points` points needs in a map of `layout` (the arrays of variables
/// the map does not store empty).
void require_tile_arrays(const MapLayout& layout, std::size_t points, const TileData& data);

}  // namespace punchsweep::io
