#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "io/chunk_compressor.hpp"
#include "io/encoded_tile.hpp"
#include "io/map_layout.hpp"
#include "map/tile_data.hpp"
#include "map/grid.hpp"

namespace punchsweep::io {

/// Turns a computed tile into the chunks a regime map stores (an EncodedTile), so that the
/// shuffle + deflate work is done by the rank that computed the tile rather than by the
/// one rank that writes the file. The bytes are exactly what HDF5's shuffle + deflate
/// pipeline of the map's variables makes of the chunk, so any reader decodes them, and they
/// depend only on the tile's values: every rank makes the same bytes.
///
/// Only little-endian hosts are supported: chunks written with H5Dwrite_chunk must hold
/// the file's little-endian types, and the encoder copies values as they lie in memory.
/// (tile_encoder.cpp refuses to compile elsewhere.) Not thread-safe (one per rank).
class TileEncoder {
 public:
  /// Throws std::invalid_argument for an empty axis, a chunk length outside
  /// [1, axis length], or time series without times.
  explicit TileEncoder(const MapLayout& layout);

  /// Encodes `data` (row-major over `box`, time last for the series) into one chunk per
  /// stored variable and counts its summary. `box` must be one whole chunk or, at the
  /// grid's edge, the part of one inside the grid; the rest of such a chunk is filled with
  /// what unwritten cells read as (not_computed, NaN). Throws std::invalid_argument for
  /// another box or arrays of the wrong length, std::runtime_error if zlib fails.
  EncodedTile encode(std::uint64_t tile, const map::TileBox& box, const map::TileData& data);

  /// Whether `tile` is what encode() makes for `box`: its point count, one chunk per stored
  /// variable, each inflating to exactly a whole chunk's bytes. A record read back from a
  /// file is checked so before its chunks go into a map (they are written as they are).
  bool decodes(const EncodedTile& tile, const map::TileBox& box) const;

  const MapLayout& layout() const { return layout_; }

 private:
  MapLayout layout_;
  ChunkCompressor compressor_;
  std::vector<std::byte> padded_;  ///< an edge tile grown to a whole chunk
};

}  // namespace punchsweep::io
