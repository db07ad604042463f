#include "map/tiling.hpp"

#include <algorithm>

namespace punchsweep::map {

Tiling::Tiling(const Index& shape, std::size_t target_points)
    : shape_(shape), chunk_(shape.size(), 1), per_axis_(shape.size(), 1) {
  const std::size_t target = std::max<std::size_t>(target_points, 1);
  std::size_t product = 1;
  for (std::size_t a = shape.size(); a-- > 0;) {
    const std::size_t room = target / product;
    chunk_[a] = std::clamp<std::size_t>(room, 1, std::max<std::size_t>(shape[a], 1));
    product *= chunk_[a];
    if (chunk_[a] < shape[a]) break;  // partial axis: slower axes stay at 1
  }
  for (std::size_t a = 0; a < shape.size(); ++a) {
    per_axis_[a] = (shape[a] + chunk_[a] - 1) / chunk_[a];
    tiles_ *= per_axis_[a];
  }
}

TileBox Tiling::box(std::size_t tile) const {
  TileBox b{Index(shape_.size()), Index(shape_.size())};
  for (std::size_t a = shape_.size(); a-- > 0;) {
    const std::size_t i = tile % per_axis_[a];
    tile /= per_axis_[a];
    b.start[a] = i * chunk_[a];
    b.count[a] = std::min(chunk_[a], shape_[a] - b.start[a]);
  }
  return b;
}

}  // namespace punchsweep::map
