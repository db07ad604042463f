#include "io/map_variables.hpp"

#include <stdexcept>
#include <string>

namespace punchsweep::io {

std::vector<const VariableSpec*> stored_variables(const MapLayout& layout) {
  std::vector<const VariableSpec*> stored;
  for (const VariableSpec& spec : kVariables) {
    if (is_stored(spec, layout)) stored.push_back(&spec);
  }
  return stored;
}

std::size_t uncompressed_bytes_per_point(const MapLayout& layout) {
  std::size_t bytes = 0;
  for (const VariableSpec* spec : stored_variables(layout)) {
    const std::size_t element = spec->codes != nullptr ? sizeof(std::int8_t) : sizeof(double);
    bytes += element * (spec->series ? layout.times.size() : 1);
  }
  return bytes;
}

void require_tile_arrays(const MapLayout& layout, std::size_t points, const TileData& data) {
  for (const VariableSpec& spec : kVariables) {
    const std::size_t expected = !is_stored(spec, layout) ? 0 : spec.series ? points * layout.times.size() : points;
    const std::size_t size = spec.codes != nullptr ? (data.*spec.codes).size() : (data.*spec.values).size();
    if (size != expected) {
      throw std::invalid_argument(std::string("regime map: tile array ") + spec.name + " has " +
                                  std::to_string(size) + " values, the tile needs " +
                                  std::to_string(expected));
    }
  }
}

}  // namespace punchsweep::io
