#include "io/map_variables.hpp"

#include <stdexcept>
#include <string>

namespace punchsweep::io {

void require_tile_arrays(const MapLayout& layout, std::size_t points, const TileData& data) {
  const std::size_t series = layout.full() ? points * layout.times.size() : 0;
  for (const VariableSpec& spec : kVariables) {
    const std::size_t expected = spec.series ? series : points;
    const std::size_t size = spec.codes != nullptr ? (data.*spec.codes).size() : (data.*spec.values).size();
    if (size != expected) {
      throw std::invalid_argument(std::string("regime map: tile array ") + spec.name + " has " +
                                  std::to_string(size) + " values, the tile needs " +
                                  std::to_string(expected));
    }
  }
}

}  // namespace punchsweep::io
