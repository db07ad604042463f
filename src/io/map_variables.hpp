#pragma once

#include <algorithm>
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
  const char* units;  ///< nullptr for the flag variables, which have none
  const char* long_name;
  const char* comment;                        ///< nullptr when there is none
  std::vector<std::int8_t> TileData::*codes;  ///< int8 source, or nullptr
  std::vector<double> TileData::*values;      ///< float64 source, or nullptr
};

/// The data variables in the order the writer creates them, which is also the order of an
/// EncodedTile's chunks. The series variables are stored only with Quantities::full.
inline constexpr std::array<VariableSpec, 13> kVariables{{
    {"regime", false, nullptr, "contact regime of the level-2 punches", nullptr, &TileData::regime, nullptr},
    {"valid", false, nullptr, "validity of the localization method", nullptr, &TileData::valid, nullptr},
    {"t_star", false, "T_eps", "time at which the level-2 punches touch",
     "0 for the immediate regime, NaN for never", nullptr, &TileData::t_star},
    {"h_0", false, "R", "displacement difference between punch tip and square centre at t = 0", nullptr,
     nullptr, &TileData::h_0},
    {"h_inf", false, "R", "displacement difference between punch tip and square centre as t -> infinity",
     nullptr, nullptr, &TileData::h_inf},
    {"a1_inf", false, "R", "long-term contact radius of a level-1 punch", nullptr, nullptr,
     &TileData::a1_inf},
    {"a2_inf", false, "R", "long-term contact radius of a level-2 punch", nullptr, nullptr,
     &TileData::a2_inf},
    {"area_fraction_inf", false, "1", "long-term contact area fraction", nullptr, nullptr,
     &TileData::area_fraction_inf},
    {"a1", true, "R", "contact radius of a level-1 punch", nullptr, nullptr, &TileData::a1},
    {"a2", true, "R", "contact radius of a level-2 punch", nullptr, nullptr, &TileData::a2},
    {"P1", true, "R^2 E0/(1-nu^2)", "load on one level-1 punch", nullptr, nullptr, &TileData::P1},
    {"P2", true, "R^2 E0/(1-nu^2)", "load on one level-2 punch", nullptr, nullptr, &TileData::P2},
    {"area_fraction", true, "1", "contact area fraction", nullptr, nullptr, &TileData::area_fraction},
}};

// The stored variables are therefore a prefix of the table, in every layout.
static_assert(std::is_partitioned(kVariables.begin(), kVariables.end(),
                                  [](const VariableSpec& spec) { return !spec.series; }),
              "the series variables must come last");

/// What never-written cells of the flag variables read as (the HDF5 fill value).
inline constexpr std::int8_t kNotComputed = -1;

/// Deflate level of every variable: level 1, because the sweep must write > 2e6 points/s.
inline constexpr unsigned kDeflateLevel = 1;

/// Whether a map of `layout` stores `spec`.
inline bool is_stored(const VariableSpec& spec, const MapLayout& layout) {
  return !spec.series || layout.full();
}

/// Throws std::invalid_argument naming the array unless every array of `data` has the
/// length a tile of `points` points needs in a map of `layout` (series arrays empty for
/// Quantities::regime).
void require_tile_arrays(const MapLayout& layout, std::size_t points, const TileData& data);

}  // namespace punchsweep::io
