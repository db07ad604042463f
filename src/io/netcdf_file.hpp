#pragma once
/// @file
/// A small netCDF-4 file written through HDF5's C API: coordinates as dimension scales,
/// variables over them with their attributes (written whole, or declared and written a slab
/// at a time), global attributes; what xarray (h5netcdf) and netCDF readers open. The regime
/// map has its own writer (tiles, chunks written raw); this one serves the texture's map,
/// a geometry a slab.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "io/hdf5_handle.hpp"

namespace punchsweep::io {

/// String attributes, in the order written.
using Attributes = std::vector<std::pair<std::string, std::string>>;

/// Rows of a slab's next dimension (after its fixed ones): `count` from `first`; a count of
/// 0 spans the whole dimension.
struct SlabRows {
  std::size_t first = 0, count = 0;
};

class NetcdfFile {
 public:
  /// Creates `path` (replacing what is there; nothing is half written where the caller
  /// writes to a temporary name and renames, as write_surface_map does).
  explicit NetcdfFile(const std::string& path);

  void attribute(const std::string& name, const std::string& value);
  void attribute(const std::string& name, double value);
  /// A coordinate: a dimension of its own name and its values.
  void coordinate(const std::string& name, const std::vector<double>& values, const Attributes& attributes);
  /// A variable over `dims` (coordinates made before), row-major, compressed.
  void variable(const std::string& name, const std::vector<std::string>& dims, const std::vector<double>& values,
                const Attributes& attributes);
  /// A variable over `dims` written later in slabs (write_slab): a slab fixes its first
  /// `slab_dims` indices and spans the rest (or `slab_rows` of the next dimension, where
  /// that is not 0), and is one chunk (shuffled, deflated), so that a map arriving a slab at
  /// a time is never held whole. float64, or int8 codes with flag_values where `int8`;
  /// unwritten values read as `fill` (NaN, or the not-computed code).
  void declare(const std::string& name, const std::vector<std::string>& dims, std::size_t slab_dims, bool int8,
               double fill, const Attributes& attributes, const std::vector<std::int8_t>& flag_values = {},
               std::size_t slab_rows = 0);
  using Rows = SlabRows;
  /// Writes the slab of a declared variable at `at` (one index per slab dimension), over
  /// `rows` of the next dimension where the variable has one: its values, row-major (codes
  /// converted to int8 for an int8 variable). Throws std::invalid_argument when `at`, the
  /// rows or the count does not fit.
  void write_slab(const std::string& name, const std::vector<std::size_t>& at, std::span<const double> values,
                  Rows rows = {});
  /// Closes the file (flushes); the destructor does too, without reporting failure.
  void close();

 private:
  /// The coordinate (dimension scale) called `dim`; std::invalid_argument naming `where` if none.
  hid_t scale(const std::string& dim, const std::string& where) const;
  /// The dimensions' lengths (coordinates made before).
  std::vector<hsize_t> shape_of(const std::vector<std::string>& dims, const std::string& where) const;
  /// Creation order of attributes tracked; chunked as `chunk` with shuffle and deflate
  /// (none for an empty chunk).
  static Handle creation_properties(const std::vector<hsize_t>& chunk, const std::string& where);
  Handle create(const std::string& name, const std::vector<std::string>& dims, hid_t file_type, std::size_t count);
  void finish(hid_t dataset, const std::string& name, const std::vector<std::string>& dims, const Attributes& attributes);

  std::string path_;
  Handle file_;
  std::vector<std::pair<std::string, Handle>> coordinates_;
  /// The declared variables: dataset, shape, slab dimensions, whether int8.
  struct Declared {
    Handle dataset;
    std::vector<hsize_t> shape;
    std::size_t slab_dims;
    bool int8;
  };
  std::vector<std::pair<std::string, Declared>> declared_;
  std::vector<std::int8_t> codes_;  ///< write_slab's scratch
};

}  // namespace punchsweep::io

namespace punchsweep::io {

/// A NetCDF-4 (HDF5) file's 2-D variable and the attributes of its dimensions' variables,
/// as SurfaceTopography's parallel to_netcdf writes a height map: `heights(x, y)`, and on
/// `x` and `y` the attributes `length`, `length_unit`, `periodic`.
struct NetcdfHeights {
  std::size_t nx = 0, ny = 0;   ///< along the first index (x) and the second (y)
  std::vector<double> values;   ///< C order: values[i ny + j] at (x_i, y_j)
  double length_x = 0.0, length_y = 0.0;  ///< 0 where not stated
  std::string unit;             ///< empty where not stated
  int periodic = -1;            ///< -1 where not stated
};

/// Takes what one of the variables `x` and `y` says (`axis` 'x' or 'y'; each attribute
/// where present) into `heights`: a length > 0, one unit for both, periodic only if both say
/// so. Throws std::runtime_error "PATH: WHAT (FORMAT)" for a bad length or two units. Both
/// NetCDF readers (NetCDF-4 here, NetCDF-3 in input/height_map.cpp) go through it.
void take_axis_attributes(NetcdfHeights& heights, char axis, std::optional<double> length,
                          const std::optional<std::string>& unit, std::optional<double> periodic,
                          const std::string& path, const std::string& format);

/// Reads `variable` of the HDF5 file `path` and the attributes of `x` and `y`. Throws
/// std::runtime_error naming the file and what is missing or unreadable.
NetcdfHeights read_netcdf4_heights(const std::string& path, const std::string& variable = "heights");

}  // namespace punchsweep::io
