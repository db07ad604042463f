#include "sweep/tiling.hpp"

#include <algorithm>

namespace punchsweep::sweep {

Tiling::Tiling(const std::array<std::size_t, kAxes>& shape, std::size_t target_points)
    : shape_(shape) {
  const std::size_t target = std::max<std::size_t>(target_points, 1);
  std::size_t product = 1;
  chunk_.fill(1);
  for (std::size_t a = kAxes; a-- > 0;) {
    const std::size_t room = target / product;
    chunk_[a] = std::clamp<std::size_t>(room, 1, std::max<std::size_t>(shape[a], 1));
    product *= chunk_[a];
    if (chunk_[a] < shape[a]) break;  // partial axis: slower axes stay at 1
  }
  for (std::size_t a = 0; a < kAxes; ++a) {
    per_axis_[a] = (shape[a] + chunk_[a] - 1) / chunk_[a];
    tiles_ *= per_axis_[a];
  }
}

TileBox Tiling::box(std::size_t tile) const {
  TileBox b;
  for (std::size_t a = kAxes; a-- > 0;) {
    const std::size_t i = tile % per_axis_[a];
    tile /= per_axis_[a];
    b.start[a] = i * chunk_[a];
    b.count[a] = std::min(chunk_[a], shape_[a] - b.start[a]);
  }
  return b;
}

}  // namespace punchsweep::sweep
