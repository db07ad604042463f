#include "io/map_variables.hpp"

#include <stdexcept>
#include <string>

namespace punchsweep::io {

std::vector<std::size_t> stored_variables(const MapLayout& layout) {
  std::vector<std::size_t> stored;
  for (std::size_t q = 0; q < map::kQuantityCount; ++q) {
    if (layout.stores(map::kQuantities[q])) stored.push_back(q);
  }
  return stored;
}

std::size_t uncompressed_bytes_per_point(const MapLayout& layout) {
  std::size_t bytes = 0;
  for (const std::size_t q : stored_variables(layout)) {
    const map::QuantitySpec& spec = map::kQuantities[q];
    const std::size_t element = spec.kind == map::Kind::flag ? sizeof(std::int8_t) : sizeof(double);
    bytes += element * (spec.extent == map::Extent::series ? layout.times.size() : 1);
  }
  return bytes;
}

void require_tile_arrays(const MapLayout& layout, std::size_t points, const map::TileData& data) {
  for (std::size_t q = 0; q < map::kQuantityCount; ++q) {
    const map::QuantitySpec& spec = map::kQuantities[q];
    const std::size_t expected = !layout.stores(spec)                  ? 0
                                 : spec.extent == map::Extent::series ? points * layout.times.size()
                                                                       : points;
    const std::size_t size = data.size(q);
    if (size != expected) {
      throw std::invalid_argument("regime map: tile array " + std::string(spec.name) + " has " +
                                  std::to_string(size) + " values, the tile needs " + std::to_string(expected));
    }
  }
}

}  // namespace punchsweep::io
