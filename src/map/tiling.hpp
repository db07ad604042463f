#pragma once

#include <cstddef>

#include "map/grid.hpp"

namespace punchsweep::map {

/// The grid cut into chunk-aligned tiles. The chunk shape fills axes from the fastest
/// (the last) outwards while the product stays within the target size, then takes a part
/// of the next axis; slower axes get 1. A tile is one HDF5 chunk (edge tiles may be
/// smaller), numbered row-major over the chunk grid.
class Tiling {
 public:
  Tiling(const Index& shape, std::size_t target_points);

  const Index& chunk() const { return chunk_; }
  std::size_t tiles() const { return tiles_; }
  TileBox box(std::size_t tile) const;

 private:
  Index shape_;
  Index chunk_;
  Index per_axis_;  ///< tiles along each axis
  std::size_t tiles_ = 1;
};

}  // namespace punchsweep::map
