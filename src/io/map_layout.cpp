#include "io/map_layout.hpp"

#include <stdexcept>
#include <string>

namespace punchsweep::io {

void require_valid(const MapLayout& layout) {
  const auto shape = layout.grid.shape();
  for (std::size_t a = 0; a < sweep::kAxes; ++a) {
    if (shape[a] == 0)
      throw std::invalid_argument(std::string("regime map: axis ") + sweep::kAxisNames[a] + " is empty");
    if (layout.chunk[a] < 1 || layout.chunk[a] > shape[a]) {
      throw std::invalid_argument(std::string("regime map: chunk length ") + std::to_string(layout.chunk[a]) +
                                  " on axis " + sweep::kAxisNames[a] + " is outside [1, " +
                                  std::to_string(shape[a]) + "]");
    }
  }
  if (layout.has_series() && layout.times.empty())
    throw std::invalid_argument("regime map: the full quantities and the BEM reference need at least one time");
}

void require_inside_grid(const MapLayout& layout, const sweep::TileBox& box) {
  const auto shape = layout.grid.shape();
  for (std::size_t a = 0; a < sweep::kAxes; ++a) {
    if (box.count[a] == 0 || box.start[a] + box.count[a] > shape[a]) {
      throw std::invalid_argument(std::string("regime map: tile range [") + std::to_string(box.start[a]) +
                                  ", " + std::to_string(box.start[a] + box.count[a]) + ") on axis " +
                                  sweep::kAxisNames[a] + " is empty or outside [0, " +
                                  std::to_string(shape[a]) + ")");
    }
  }
}

bool is_one_chunk(const MapLayout& layout, const sweep::TileBox& box) {
  const auto shape = layout.grid.shape();
  for (std::size_t a = 0; a < sweep::kAxes; ++a) {
    if (box.start[a] % layout.chunk[a] != 0) return false;
    const bool whole = box.count[a] == layout.chunk[a];
    const bool rest_of_grid = box.count[a] < layout.chunk[a] && box.start[a] + box.count[a] == shape[a];
    if (!whole && !rest_of_grid) return false;
  }
  return true;
}

void require_one_chunk(const MapLayout& layout, const sweep::TileBox& box) {
  require_inside_grid(layout, box);
  if (!is_one_chunk(layout, box)) {
    std::string range;
    for (std::size_t a = 0; a < sweep::kAxes; ++a) {
      range += std::string(a ? ", " : "") + sweep::kAxisNames[a] + " [" + std::to_string(box.start[a]) +
               ", " + std::to_string(box.start[a] + box.count[a]) + ")";
    }
    throw std::invalid_argument("regime map: the tile " + range +
                                " is not one chunk (nor the part of one inside the grid)");
  }
}

}  // namespace punchsweep::io
