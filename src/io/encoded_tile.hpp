#pragma once

#include <array>
#include <iterator>

#include "model/point/validity.hpp"
#include <cstddef>
#include <cstdint>
#include <vector>

namespace punchsweep::io {

/// The counts of one tile that the progress lines and the end-of-run summary need, kept
/// beside the compressed chunks so that rank 0 never has to decode one.
struct TileSummary {
  std::uint64_t points = 0;                 ///< grid points in the tile
  std::array<std::uint64_t, 3> regimes{};   ///< points per regime code: 0 immediate, 1 delayed, 2 never
  std::array<std::uint64_t, std::size(model::kValidities)> validity{};  ///< points per validity code (docs/maps.md, "Validity")
  std::array<std::uint64_t, 3> bem_regimes{};  ///< BEM reference points per regime code
  std::uint64_t bem_agreeing = 0;              ///< BEM reference points whose regime is the model's

  bool operator==(const TileSummary&) const = default;
};

/// One tile in the form the map stores it: for each stored variable, in the writer's
/// variable order (io/map_variables.hpp), its whole HDF5 chunk shuffled and deflated, ready
/// for H5Dwrite_chunk. Made by TileEncoder where the tile is computed, so the rank that
/// writes the map only copies bytes.
struct EncodedTile {
  std::uint64_t tile = 0;                      ///< the tile's index in the sweep's tiling
  std::vector<std::vector<std::byte>> chunks;  ///< one encoded chunk per stored variable
  TileSummary summary;

  bool operator==(const EncodedTile&) const = default;
};

/// Flat byte form of an EncodedTile, shared by the MPI result messages and the resume
/// journal. Layout (native endianness: every rank of one job runs on one architecture, and
/// the chunks are little-endian anyway, see TileEncoder): a 128-byte header {u32 magic
/// "PSET", u32 version (4), u64 tile index, u64 points, u64 x 3 regime counts, u64 x 5
/// validity counts, u64 x 3 BEM regime counts, u64 BEM agreeing count, u64 chunk count},
/// then u64 byte length per chunk, then the chunks' bytes.
std::vector<std::byte> pack_encoded_tile(const EncodedTile& tile);

/// Decodes a pack_encoded_tile buffer. Throws std::runtime_error naming the defect when
/// the buffer is short, too long, has the wrong magic or version, chunk lengths that do not
/// add up to it, or summary counts larger than its point count (or, for the agreeing
/// count, than its BEM count).
EncodedTile unpack_encoded_tile(const std::byte* bytes, std::size_t size);

}  // namespace punchsweep::io
