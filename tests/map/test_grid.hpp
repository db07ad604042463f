#pragma once
/// @file
/// Helpers the tests of several layers share: a standard linear solid's grid of named axes
/// and access to a tile's arrays by quantity name.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "map/grid.hpp"
#include "map/tile_data.hpp"

namespace punchsweep::map::testing {

/// The axes of a standard linear solid's map, in their order (model::sweep_axes).
enum : std::size_t { kL, kDh, kT, kPbar, kS, kAxes };
inline constexpr const char* kAxisNames[kAxes] = {"l", "dh", "T", "pbar", "s"};

/// A grid with those five named axes and no values yet.
inline Grid sls_grid() {
  Grid grid;
  for (const char* name : kAxisNames) grid.axes.push_back(Axis{name, {}, "", false, {}});
  return grid;
}

/// Quantity `name`'s array (kQuantities): a flag's codes or a real's values.
inline std::vector<std::int8_t>& flag(TileData& d, const char* name) { return d.flag(quantity(name)); }
inline const std::vector<std::int8_t>& flag(const TileData& d, const char* name) {
  return d.flag(quantity(name));
}
inline std::vector<double>& real(TileData& d, const char* name) { return d.real(quantity(name)); }
inline const std::vector<double>& real(const TileData& d, const char* name) {
  return d.real(quantity(name));
}

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

/// Whether every array of the two tiles holds the same bits (NaN payloads included).
inline bool same_bits(const TileData& a, const TileData& b) {
  for (std::size_t q = 0; q < kQuantityCount; ++q) {
    if (!same_bits(a.codes[q], b.codes[q]) || !same_bits(a.reals[q], b.reals[q])) return false;
  }
  return true;
}

}  // namespace punchsweep::map::testing
