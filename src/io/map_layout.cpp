#include "io/map_layout.hpp"

#include <stdexcept>
#include <string>

namespace punchsweep::io {

void require_valid(const MapLayout& layout) {
  const auto shape = layout.grid.shape();
  if (shape.empty()) throw std::invalid_argument("regime map: the grid has no axes");
  if (layout.chunk.size() != shape.size()) {
    throw std::invalid_argument("regime map: the chunk shape has " + std::to_string(layout.chunk.size()) +
                                " lengths for " + std::to_string(shape.size()) + " axes");
  }
  for (std::size_t a = 0; a < shape.size(); ++a) {
    if (shape[a] == 0)
      throw std::invalid_argument("regime map: axis " + layout.grid.axes[a].name + " is empty");
    if (layout.chunk[a] < 1 || layout.chunk[a] > shape[a]) {
      throw std::invalid_argument(std::string("regime map: chunk length ") + std::to_string(layout.chunk[a]) +
                                  " on axis " + layout.grid.axes[a].name + " is outside [1, " +
                                  std::to_string(shape[a]) + "]");
    }
  }
  if (layout.has_series() && layout.times.empty())
    throw std::invalid_argument("regime map: the full quantities and the BEM reference need at least one time");
}

void require_inside_grid(const MapLayout& layout, const map::TileBox& box) {
  const auto shape = layout.grid.shape();
  if (box.start.size() != shape.size() || box.count.size() != shape.size()) {
    throw std::invalid_argument("regime map: a tile of " + std::to_string(box.count.size()) + " axes in a grid of " +
                                std::to_string(shape.size()));
  }
  for (std::size_t a = 0; a < shape.size(); ++a) {
    if (box.count[a] == 0 || box.start[a] + box.count[a] > shape[a]) {
      throw std::invalid_argument(std::string("regime map: tile range [") + std::to_string(box.start[a]) +
                                  ", " + std::to_string(box.start[a] + box.count[a]) + ") on axis " +
                                  layout.grid.axes[a].name + " is empty or outside [0, " +
                                  std::to_string(shape[a]) + ")");
    }
  }
}

bool is_one_chunk(const MapLayout& layout, const map::TileBox& box) {
  const auto shape = layout.grid.shape();
  for (std::size_t a = 0; a < shape.size(); ++a) {
    if (box.start[a] % layout.chunk[a] != 0) return false;
    const bool whole = box.count[a] == layout.chunk[a];
    const bool rest_of_grid = box.count[a] < layout.chunk[a] && box.start[a] + box.count[a] == shape[a];
    if (!whole && !rest_of_grid) return false;
  }
  return true;
}

void require_one_chunk(const MapLayout& layout, const map::TileBox& box) {
  require_inside_grid(layout, box);
  if (!is_one_chunk(layout, box)) {
    std::string range;
    for (std::size_t a = 0; a < box.count.size(); ++a) {
      range += std::string(a ? ", " : "") + layout.grid.axes[a].name + " [" + std::to_string(box.start[a]) +
               ", " + std::to_string(box.start[a] + box.count[a]) + ")";
    }
    throw std::invalid_argument("regime map: the tile " + range +
                                " is not one chunk (nor the part of one inside the grid)");
  }
}

}  // namespace punchsweep::io
