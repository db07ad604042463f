#include "io/tile_encoder.hpp"

#include <array>
#include <bit>
#include <cstring>
#include <limits>
#include <span>

#include "io/map_variables.hpp"

namespace punchsweep::io {

// H5Dwrite_chunk stores the bytes it is given as they are, and the map's types are
// little-endian (H5T_STD_I8LE, H5T_IEEE_F64LE): on a big-endian host the encoder would
// have to swap every value first, which no supported platform needs.
static_assert(std::endian::native == std::endian::little,
              "TileEncoder writes raw chunk bytes, which must be little-endian like the map's types");

namespace {

/// Copies a tile at the grid's edge into a whole chunk (row-major over `chunk`, `inner`
/// values per point), with `fill` in the part that lies outside the grid.
void pad_to_chunk(const std::byte* tile, std::size_t element, const void* fill, std::size_t inner,
                  const map::Index& count, const map::Index& chunk, std::vector<std::byte>* out) {
  std::size_t values = inner;
  for (const std::size_t c : chunk) values *= c;
  out->resize(values * element);
  for (std::size_t i = 0; i < values; ++i) std::memcpy(out->data() + i * element, fill, element);
  // The fastest axis is contiguous in both: copy one run per position on the slower axes.
  const std::size_t rank = count.size();
  const std::size_t run = count[rank - 1] * inner * element;
  std::size_t runs = 1;
  for (std::size_t a = 0; a + 1 < rank; ++a) runs *= count[a];
  const std::byte* from = tile;
  for (std::size_t r = 0; r < runs; ++r, from += run) {
    std::size_t to = 0;  // the run's first point, row-major over `chunk`
    std::size_t rest = r;
    std::size_t stride = chunk[rank - 1];
    for (std::size_t a = rank - 1; a-- > 0; rest /= count[a]) {
      to += (rest % count[a]) * stride;
      stride *= chunk[a];
    }
    std::memcpy(out->data() + to * inner * element, from, run);
  }
}

/// Counts the points per code 0 .. N-1 (not_computed is counted nowhere).
template <std::size_t N>
void count_codes(const std::vector<std::int8_t>& codes, std::array<std::uint64_t, N>* counts) {
  for (const std::int8_t c : codes) {
    if (c >= 0 && static_cast<std::size_t>(c) < N) ++(*counts)[static_cast<std::size_t>(c)];
  }
}

}  // namespace

TileEncoder::TileEncoder(const MapLayout& layout)
    : layout_(layout), compressor_(static_cast<int>(kDeflateLevel)) {
  require_valid(layout_);
}

EncodedTile TileEncoder::encode(std::uint64_t tile, const map::TileBox& box, const map::TileData& data) {
  require_one_chunk(layout_, box);
  const std::size_t points = box.points();
  require_tile_arrays(layout_, points, data);

  EncodedTile encoded;
  encoded.tile = tile;
  encoded.summary.points = points;
  const std::vector<std::int8_t>& regime = data.flag(map::quantity("regime"));
  const std::vector<std::int8_t>& bem_regime = data.flag(map::quantity("bem_regime"));
  count_codes(regime, &encoded.summary.regimes);
  count_codes(data.flag(map::quantity("valid")), &encoded.summary.validity);
  count_codes(bem_regime, &encoded.summary.bem_regimes);
  for (std::size_t i = 0; i < bem_regime.size(); ++i) {
    const std::int8_t bem = bem_regime[i];  // counted as agreeing only where counted above
    const bool counted = bem >= 0 && static_cast<std::size_t>(bem) < encoded.summary.bem_regimes.size();
    if (counted && bem == regime[i]) ++encoded.summary.bem_agreeing;
  }

  const bool edge = box.count != layout_.chunk;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const std::size_t q : stored_variables(layout_)) {
    const map::QuantitySpec& spec = map::kQuantities[q];
    const bool codes = spec.kind == map::Kind::flag;
    const std::size_t element = codes ? sizeof(std::int8_t) : sizeof(double);
    const std::size_t inner = spec.extent == map::Extent::series ? layout_.times.size() : 1;
    const auto* values = codes ? reinterpret_cast<const std::byte*>(data.flag(q).data())
                               : reinterpret_cast<const std::byte*>(data.real(q).data());
    std::span<const std::byte> bytes;
    if (edge) {
      const void* fill = codes ? static_cast<const void*>(&kNotComputed) : static_cast<const void*>(&nan);
      pad_to_chunk(values, element, fill, inner, box.count, layout_.chunk, &padded_);
      bytes = compressor_.compress(padded_.data(), padded_.size(), element);
    } else {
      bytes = compressor_.compress(values, points * inner * element, element);
    }
    encoded.chunks.emplace_back(bytes.begin(), bytes.end());
  }
  return encoded;
}

bool TileEncoder::decodes(const EncodedTile& tile, const map::TileBox& box) const {
  if (tile.summary.points != box.points()) return false;
  const std::vector<std::size_t> variables = stored_variables(layout_);
  if (tile.chunks.size() != variables.size()) return false;
  std::size_t chunk_points = 1;
  for (const std::size_t c : layout_.chunk) chunk_points *= c;
  for (std::size_t k = 0; k < variables.size(); ++k) {
    const map::QuantitySpec& spec = map::kQuantities[variables[k]];
    const std::size_t element = spec.kind == map::Kind::flag ? sizeof(std::int8_t) : sizeof(double);
    const std::size_t inner = spec.extent == map::Extent::series ? layout_.times.size() : 1;
    if (!inflates_to(tile.chunks[k], chunk_points * inner * element)) return false;
  }
  return true;
}

}  // namespace punchsweep::io
