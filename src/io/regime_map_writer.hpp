#pragma once

#include <hdf5.h>

#include <string>
#include <vector>

#include "io/encoded_tile.hpp"
#include "io/hdf5_handle.hpp"
#include "io/map_layout.hpp"
#include "io/map_variables.hpp"
#include "io/tile_data.hpp"
#include "io/tile_encoder.hpp"
#include "sweep/grid.hpp"

namespace punchsweep::io {

/// Provenance stored as global attributes of a regime map.
struct MapAttributes {
  std::string title;
  std::string source;
  std::string history;
  std::string config_text;  ///< the resolved configuration (global attribute `config`)
  std::string creep_law;
  double C = 0.0;  ///< shape constant of f(r) = C r^s / R^(s-1)
};

/// Writes a regime map: an HDF5 file laid out as a netCDF-4/CF-1.8 dataset, which
/// netCDF4, xarray (engine="h5netcdf") and the postprocess scripts read. The layout is a
/// contract:
///
/// - Link and attribute creation order are tracked and indexed, as in netCDF-4 files.
/// - Coordinates `l`, `dh`, `T`, `pbar`, `s`, `time`: 1-D float64 dimension scales with
///   `units` and `long_name`. `s` is float64 too (its values are whole numbers), so every
///   coordinate has one type and a non-integer s could never be truncated silently. The
///   five grid axes also carry `axis_spec` (the text the axis was given as) and `spacing`:
///   "log" for logspace() axes, "linear" for evenly spaced values (one or two values
///   included), "list" for anything else. `time` is written for regime-only maps too, as a
///   record of the configured times (only the bem_* series use it there).
/// - Over (l, dh, T, pbar, s): `regime` and `valid` (int8 flag variables with
///   flag_values/flag_meanings; HDF5 fill value -1 = not_computed; no _FillValue attribute,
///   so readers do not turn the codes into floats), `t_star`, `h_0`, `h_inf`, `a1_inf`,
///   `a2_inf`, `area_fraction_inf` (float64, `_FillValue` and HDF5 fill NaN).
/// - With Quantities::full, over (l, dh, T, pbar, s, time): `a1`, `a2`, `P1`, `P2`,
///   `area_fraction` (float64, fill NaN).
/// - With a BEM reference (MapLayout::bem), whatever the quantities: `bem_regime` (int8,
///   the flags of `regime`, no _FillValue) and `bem_t_star` over the five axes, and
///   `bem_a1`, `bem_a2`, `bem_P1`, `bem_P2`, `bem_area_fraction` over the time axis too
///   (float64, fill NaN); cells outside the reference sample read -1 or NaN.
/// - Every variable is chunked by MapLayout::chunk (times whole for the 6-D ones) and
///   compressed with shuffle + deflate level 1. A tile that is exactly one chunk (or the
///   part of one inside the grid) is stored encoded (TileEncoder) with H5Dwrite_chunk; any
///   other box goes through HDF5's filter pipeline. Readers see no difference.
/// - Global attributes: Conventions "CF-1.8", title, source, history, config, creep_law,
///   C, with a BEM reference bem_grid (int32), bem_tolerance (float64), bem_sample and
///   bem_seed (int64), bem_method (string), then completed (int8, 0 until finish() sets 1),
///   and from finish(): ranks, wall_seconds, points_per_second.
///
/// All strings are scalar variable-length UTF-8 attributes (one-character fixed-length
/// strings such as units "1" would come back from h5netcdf as bytes).
/// Errors throw Hdf5Error naming the file and the operation. Not thread-safe.
class RegimeMapWriter {
 public:
  /// Creates (or truncates) `path` with every coordinate, variable and attribute.
  /// Throws std::invalid_argument for an empty axis, a chunk outside [1, axis length],
  /// or time series without times.
  RegimeMapWriter(const std::string& path, const MapLayout& layout, const MapAttributes& attributes);
  ~RegimeMapWriter() = default;
  RegimeMapWriter(RegimeMapWriter&&) noexcept = default;
  RegimeMapWriter& operator=(RegimeMapWriter&&) noexcept = default;
  RegimeMapWriter(const RegimeMapWriter&) = delete;
  RegimeMapWriter& operator=(const RegimeMapWriter&) = delete;

  /// Writes one tile into every variable. `data` is row-major over `box` (time last for
  /// the series); `box` may be any box of the grid. Throws std::invalid_argument if the box
  /// leaves the grid or an array has the wrong length (the arrays of variables the map does
  /// not store must be empty).
  void write_tile(const sweep::TileBox& box, const TileData& data);

  /// Stores a tile that a TileEncoder of this map's layout encoded, one H5Dwrite_chunk per
  /// variable (no compression here). Throws std::invalid_argument if `box` is not one chunk
  /// (or the part of one inside the grid), or `tile` has another number of chunks or points.
  void write_encoded(const sweep::TileBox& box, const EncodedTile& tile);

  /// Hands everything written so far to the operating system.
  void flush();

  /// Stores the run statistics, sets `completed` = 1 and closes the file. The writer can
  /// do nothing afterwards. A writer destroyed without finish() leaves `completed` = 0.
  void finish(int ranks, double wall_seconds, double points_per_second);

  const std::string& path() const { return path_; }

 private:
  void create_coordinate(const char* name, const std::vector<double>& values, const char* units,
                         const char* long_name);
  /// An int8 flag variable when `codes`, else float64; over the time axis too when `series`.
  Handle create_variable(const std::string& name, bool codes, bool series);
  void write_hyperslab(const sweep::TileBox& box, const TileData& data);
  void require_open(const char* operation) const;

  std::string path_;
  TileEncoder encoder_;  ///< holds the layout; encodes write_tile's whole-chunk tiles
  Handle file_;
  std::vector<Handle> coordinates_;  ///< l, dh, T, pbar, s, time
  std::vector<const VariableSpec*> stored_;  ///< the kVariables entries the map stores, in order
  std::vector<Handle> variables_;            ///< their datasets, one per entry of stored_
  Handle space5_;                    ///< file dataspace of the 5-D variables (selection reused)
  Handle space6_;                    ///< file dataspace of the 6-D variables
};

}  // namespace punchsweep::io
