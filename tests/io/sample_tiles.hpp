#pragma once

#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/encoded_tile.hpp"
#include "map/test_grid.hpp"
#include "map/tile_data.hpp"

namespace punchsweep::io::testing {

using namespace map::testing;

/// The message of the std::runtime_error `f` throws ("" if it throws none).
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

/// A NaN with a chosen payload, so a round trip that canonicalises NaNs is caught.
inline double nan_with_payload(std::uint64_t payload) {
  std::uint64_t bits = 0x7FF8000000000000ULL | (payload & 0x0007FFFFFFFFFFFFULL);
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

/// Deterministic tile contents that differ from seed to seed and from array to array,
/// with NaNs (several payloads), -0.0, infinities and every regime/valid code mixed in;
/// the bem_* arrays too when `bem`.
inline map::TileData sample_tile(std::uint64_t seed, std::size_t points, std::size_t times, bool full,
                                 bool bem = false) {
  map::TileData data;
  data.resize(points, times, full ? map::Quantities::full : map::Quantities::regime, bem);
  const std::vector<double> specials{nan_with_payload(seed + 1),
                                     -0.0,
                                     std::numeric_limits<double>::infinity(),
                                     nan_with_payload(0x5A5A5),
                                     -std::numeric_limits<double>::infinity(),
                                     std::numeric_limits<double>::denorm_min()};
  auto value = [&](std::size_t array, std::size_t i) {
    const std::uint64_t k = seed * 1000003 + array * 7919 + i;
    if (k % 11 == 3) return specials[k % specials.size()];
    return static_cast<double>(k) * 1.000000119 + 1.0 / static_cast<double>(k + 3);
  };
  // Flag codes: every code of the flag set and not_computed (-1): regime 0..2, validity 0..3.
  for (std::size_t q = 0; q < map::kQuantityCount; ++q) {
    const map::QuantitySpec& spec = map::kQuantities[q];
    if (spec.kind == map::Kind::flag) {
      const int codes = spec.flags == map::Flags::regime ? 4 : 6;  // every code and -1
      const std::uint64_t step = spec.source == map::Source::bem ? 5 : spec.flags == map::Flags::regime ? 1 : 3;
      std::vector<std::int8_t>& v = data.flag(q);
      for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<std::int8_t>(static_cast<int>((seed + step * i) % codes) - 1);
    } else {
      std::vector<double>& v = data.real(q);
      for (std::size_t i = 0; i < v.size(); ++i) v[i] = value(q, i);
    }
  }
  return data;
}

/// An EncodedTile as the codec and the journal see it: tile index `seed`, `chunks` runs of
/// deterministic bytes whose lengths vary around `bytes` (and from seed to seed), and
/// summary counts that fit its points.
inline EncodedTile sample_encoded_tile(std::uint64_t seed, std::size_t chunks, std::size_t bytes) {
  EncodedTile tile;
  tile.tile = seed;
  tile.summary.points = 4096 + seed % 13;
  tile.summary.regimes = {seed % 100, 2000, 7};
  tile.summary.validity = {3000, 0, seed % 50, 1, seed % 3};
  tile.summary.bem_regimes = {seed % 7, 3, 11};
  tile.summary.bem_agreeing = seed % 5;
  std::uint32_t x = static_cast<std::uint32_t>(seed) * 2654435761U + 1;
  for (std::size_t c = 0; c < chunks; ++c) {
    std::vector<std::byte> chunk(bytes + (seed * 31 + c * 17) % (bytes / 2 + 1));
    for (std::byte& b : chunk) {
      x = x * 1664525U + 1013904223U;
      b = static_cast<std::byte>(x >> 24);
    }
    tile.chunks.push_back(std::move(chunk));
  }
  return tile;
}

}  // namespace punchsweep::io::testing
