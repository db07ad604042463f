#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "io/tile_data.hpp"

namespace punchsweep::io {

/// Flat byte form of one tile's results, shared by the MPI result messages and the resume
/// journal. Layout (native endianness: every rank of one job runs on one architecture):
/// a 32-byte header {u32 magic "PSTD", u32 version, u64 tile index, u64 point count,
/// u64 series count}, then the raw bytes of regime, valid (int8 x points), t_star, h_0,
/// h_inf, a1_inf, a2_inf, area_fraction_inf (float64 x points), a1, a2, P1, P2,
/// area_fraction (float64 x series). The series count is 0 for regime-only maps.
/// Values are copied bit for bit, NaN payloads included.
std::vector<std::byte> pack_tile(std::uint64_t tile_index, const TileData& data);

/// Decodes a pack_tile buffer into `out` (resizing its arrays) and returns the tile index.
/// Throws std::runtime_error naming the defect when the buffer is short, too long, has the
/// wrong magic or version, or inconsistent array lengths.
std::uint64_t unpack_tile(const std::byte* bytes, std::size_t size, TileData* out);

/// Size in bytes of a pack_tile buffer with `points` points and `series` series values.
std::size_t packed_tile_size(std::size_t points, std::size_t series);

}  // namespace punchsweep::io
