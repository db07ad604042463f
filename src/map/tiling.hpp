#pragma once

#include <array>
#include <cstddef>

#include "sweep/grid.hpp"

namespace punchsweep::sweep {

/// The grid cut into chunk-aligned tiles. The chunk shape fills axes from the fastest
/// (s) outwards while the product stays within the target size, then takes a part of the
/// next axis; slower axes get 1. A tile is one HDF5 chunk (edge tiles may be smaller),
/// numbered row-major over the chunk grid.
class Tiling {
 public:
  Tiling(const std::array<std::size_t, kAxes>& shape, std::size_t target_points);

  const std::array<std::size_t, kAxes>& chunk() const { return chunk_; }
  std::size_t tiles() const { return tiles_; }
  TileBox box(std::size_t tile) const;

 private:
  std::array<std::size_t, kAxes> shape_;
  std::array<std::size_t, kAxes> chunk_;
  std::array<std::size_t, kAxes> per_axis_;  ///< tiles along each axis
  std::size_t tiles_ = 1;
};

}  // namespace punchsweep::sweep
