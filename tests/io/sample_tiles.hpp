#pragma once

#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "io/encoded_tile.hpp"
#include "io/tile_data.hpp"

namespace punchsweep::io::testing {

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
inline TileData sample_tile(std::uint64_t seed, std::size_t points, std::size_t times, bool full,
                            bool bem = false) {
  TileData data;
  data.resize(points, times, full, bem);
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
  for (std::size_t i = 0; i < points; ++i) {
    data.regime[i] = static_cast<std::int8_t>(static_cast<int>((seed + i) % 4) - 1);
    data.valid[i] = static_cast<std::int8_t>(static_cast<int>((seed + 3 * i) % 5) - 1);
  }
  for (std::size_t i = 0; i < data.bem_regime.size(); ++i) {
    data.bem_regime[i] = static_cast<std::int8_t>(static_cast<int>((seed + 5 * i) % 4) - 1);
  }
  std::size_t array = 0;
  for (auto* v : {&data.t_star, &data.h_0, &data.h_inf, &data.a1_inf, &data.a2_inf, &data.area_fraction_inf,
                  &data.a1, &data.a2, &data.P1, &data.P2, &data.area_fraction, &data.bem_t_star, &data.bem_a1,
                  &data.bem_a2, &data.bem_P1, &data.bem_P2, &data.bem_area_fraction}) {
    for (std::size_t i = 0; i < v->size(); ++i) (*v)[i] = value(array, i);
    ++array;
  }
  return data;
}

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

/// Whether every array of the two tiles holds the same bits (NaN payloads included).
inline bool same_bits(const TileData& a, const TileData& b) {
  return same_bits(a.regime, b.regime) && same_bits(a.valid, b.valid) && same_bits(a.t_star, b.t_star) &&
         same_bits(a.h_0, b.h_0) && same_bits(a.h_inf, b.h_inf) && same_bits(a.a1_inf, b.a1_inf) &&
         same_bits(a.a2_inf, b.a2_inf) && same_bits(a.area_fraction_inf, b.area_fraction_inf) &&
         same_bits(a.a1, b.a1) && same_bits(a.a2, b.a2) && same_bits(a.P1, b.P1) && same_bits(a.P2, b.P2) &&
         same_bits(a.area_fraction, b.area_fraction) && same_bits(a.bem_regime, b.bem_regime) &&
         same_bits(a.bem_t_star, b.bem_t_star) && same_bits(a.bem_a1, b.bem_a1) && same_bits(a.bem_a2, b.bem_a2) &&
         same_bits(a.bem_P1, b.bem_P1) && same_bits(a.bem_P2, b.bem_P2) &&
         same_bits(a.bem_area_fraction, b.bem_area_fraction);
}

/// An EncodedTile as the codec and the journal see it: tile index `seed`, `chunks` runs of
/// deterministic bytes whose lengths vary around `bytes` (and from seed to seed), and
/// summary counts that fit its points.
inline EncodedTile sample_encoded_tile(std::uint64_t seed, std::size_t chunks, std::size_t bytes) {
  EncodedTile tile;
  tile.tile = seed;
  tile.summary.points = 4096 + seed % 13;
  tile.summary.regimes = {seed % 100, 2000, 7};
  tile.summary.validity = {3000, 0, seed % 50, 1};
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
