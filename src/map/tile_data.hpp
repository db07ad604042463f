#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "map/quantities.hpp"

namespace punchsweep::map {

/// Results of one tile: one array per output quantity (kQuantities order), row-major over
/// the tile box and, for a series, over (box, time). A quantity the map does not store has
/// an empty array. Codes: what the model's enums say (regime, validity), -1 not computed;
/// reals: NaN where not defined (t_star for never) and for the BEM outside its sample.
struct TileData {
  std::array<std::vector<std::int8_t>, kQuantityCount> codes;  ///< flags; empty for reals
  std::array<std::vector<double>, kQuantityCount> reals;       ///< reals; empty for flags

  std::vector<std::int8_t>& flag(std::size_t q) { return codes[q]; }
  const std::vector<std::int8_t>& flag(std::size_t q) const { return codes[q]; }
  std::vector<double>& real(std::size_t q) { return reals[q]; }
  const std::vector<double>& real(std::size_t q) const { return reals[q]; }
  /// The length of quantity q's array (either kind).
  std::size_t size(std::size_t q) const {
    return kQuantities[q].kind == Kind::flag ? codes[q].size() : reals[q].size();
  }

  /// Sizes the array of every quantity a map of `quantities` (with or without a BEM
  /// reference and a box of tolerances) stores, for `points` points and `times` snapshot times: flags at -1 (not
  /// computed), the model's reals at 0 (every one is overwritten), the others' at NaN
  /// (only some points are written). The others are left empty.
  void resize(std::size_t points, std::size_t times, Quantities quantities, bool bem, bool tolerance = false) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t q = 0; q < kQuantityCount; ++q) {
      const QuantitySpec& spec = kQuantities[q];
      const std::size_t n = !is_stored(spec, quantities, bem, tolerance) ? 0
                            : spec.extent == Extent::series ? points * times
                                                            : points;
      if (spec.kind == Kind::flag) {
        codes[q].assign(n, kNotComputed);
        reals[q].clear();
      } else {
        reals[q].assign(n, spec.source == Source::model ? 0.0 : kNaN);
        codes[q].clear();
      }
    }
  }
};

}  // namespace punchsweep::map
