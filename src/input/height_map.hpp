#pragma once
/// @file
/// A measured height map of one period of a texture, as a profilometer exports it: a CSV
/// grid (one row per line, values separated by commas, semicolons, tabs or spaces) or a
/// NumPy .npy array (2-D, float64 or float32, little-endian, C order), rows along y.

#include <cstddef>
#include <string>
#include <vector>

namespace punchsweep::input {

struct HeightMap {
  std::size_t nx = 0;          ///< columns: pixels along x
  std::size_t ny = 0;          ///< rows: pixels along y
  std::vector<double> height;  ///< row-major: height[j nx + i] at pixel (i, j), in the file's unit
};

/// The map in `path` (.npy by its magic string, else CSV). Throws UsageError naming the
/// file and the problem (ragged rows, a value that is no finite number, an unsupported
/// dtype or order, fewer than 4 x 4 pixels).
HeightMap read_height_map(const std::string& path);

}  // namespace punchsweep::input
