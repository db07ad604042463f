#pragma once
/// @file
/// A measured height map of one period of a texture, as a profilometer exports it: a CSV
/// grid (one row per line, values separated by commas, semicolons, tabs or spaces), a
/// NumPy .npy array (2-D, float64 or float32, little-endian, C or Fortran order), rows along y; or the
/// NetCDF container the SurfaceTopography ecosystem writes (Topography.to_netcdf: classic or
/// 64-bit-offset NetCDF-3 in serial, NetCDF-4 in parallel; a variable `heights(x, y)`, and
/// on the variables `x` and `y` the attributes `length`, `periodic` and `length_unit`; the
/// heights in that unit too).

#include <cstddef>
#include <string>
#include <vector>

namespace punchsweep::input {

struct HeightMap {
  std::size_t nx = 0;          ///< columns: pixels along x
  std::size_t ny = 0;          ///< rows: pixels along y
  std::vector<double> height;  ///< row-major: height[j nx + i] at pixel (i, j), in the file's unit
  /// What a NetCDF map states of itself (0, empty, -1 where it does not): its lengths along
  /// x and y, the unit of lengths and heights, and whether it is periodic.
  double length_x = 0.0, length_y = 0.0;
  std::string unit;
  int periodic = -1;
  /// What the reader found worth saying of the map, one sentence each, for the run's notes:
  /// where its opposite edges do not meet (the step across an edge more than twice the
  /// largest between neighbouring rows or columns inside it), so that it looks like no whole
  /// period. (A map that says it is not periodic, periodic = 0, gets no such note here.)
  std::vector<std::string> notes;
};

/// The map in `path` (.npy and NetCDF by their magic strings, else CSV). Throws UsageError naming the
/// file and the problem (ragged rows, a value that is no finite number, a CSV layout that
/// mixes commas and blanks between values, an unsupported dtype, a .npy shape that
/// is no two decimal counts or does not match its data, fewer than 4 x 4 pixels).
/// A CSV map's separator is its first row's: with ';' or tabs between values a decimal comma
/// is a point ("1,5;2,25"), as spreadsheets in many locales write it (input/csv_cells.hpp).
/// A Fortran-order .npy (numpy's Z.T) is read as the array it is.
/// A NetCDF map's unit "µm" (either micro sign) comes back as "um".
HeightMap read_height_map(const std::string& path);

}  // namespace punchsweep::input
