#pragma once

#include <hdf5.h>

#include <string>
#include <vector>

#include "io/encoded_tile.hpp"
#include "io/hdf5_handle.hpp"
#include "io/map_layout.hpp"
#include "io/map_variables.hpp"
#include "io/tile_encoder.hpp"
#include "map/grid.hpp"
#include "map/tile_data.hpp"

namespace punchsweep::io {

/// Provenance stored as global attributes of a regime map.
struct MapAttributes {
  std::string title;
  std::string source;
  std::string history;
  std::string config_text;  ///< the resolved configuration (global attribute `config`)
  /// The lines that define the map's content (sweep::SweepConfig::identity), joined by
  /// '\n' (global attribute `identity`): what --resume compares, also on a finished map.
  std::string identity;
  std::string creep_law;
  double C = 0.0;  ///< shape constant of f(r) = C r^s / R^(s-1)
  /// The unit of every time: "T_eps" (then a scale, written as scaled_by) or a material's
  /// time unit ("s", "ms", "min", "h"; then written as units).
  std::string time_unit = "T_eps";
  /// A material map (empty name: none): the file's name line and text, its instantaneous
  /// Young's modulus E_0 and the plane-strain E0* = E_0/(1 - nu^2) in Pa, nu.
  struct Material {
    std::string name;
    std::string text;
    double E0_Pa = 0.0;
    double E0_star_Pa = 0.0;
    double poisson = 0.0;
  } material;
  /// The punch's radius of curvature R as a UDUNITS-2 string ("50 um", global attribute
  /// `R`): the physical size of the scale R, in the unit the user gave it; empty: not given.
  std::string R{};
  double R_m = 0.0;  ///< the same in metres (global attribute `R_m`), for loads in N
  std::string localization = "paper";  ///< the localization model's spelling (model/problem/localization.hpp)
};

/// Writes a regime map: an HDF5 file laid out as a netCDF-4/CF-1.8 dataset, which
/// netCDF4, xarray (engine="h5netcdf") and the postprocess scripts read. The layout is a
/// contract:
///
/// - Link and attribute creation order are tracked and indexed, as in netCDF-4 files.
/// - Coordinates: one per grid axis, in the grid's order (for the standard linear solid
///   `l`, `dh`, `T`, `pbar`, `s`), then `time`: 1-D float64 dimension scales with `units`
///   "1" and `long_name`, and `scaled_by` the scale of a scaled quantity ("R",
///   "E0/(1-nu^2)", "T_eps"; none for pure numbers), as the axis's model parameter declares
///   them (model/point/parameters.hpp). Every real data variable has `units` "1" and `scaled_by`
///   likewise (map::QuantitySpec::scale); the global attribute `scales` says what the scales
///   are. So UDUNITS-based tools (cf-units, pint-xarray) read every `units` correctly.
///   Integer axes such as `s` are float64 too, so every coordinate has one type and a
///   non-integer value could never be truncated silently. The grid axes also carry
///   `axis_spec` (the text the axis was given as) and `spacing`: "log" for logspace() axes,
///   "linear" for evenly spaced values (one or two values included), "list" for anything
///   else. `time` is written for regime-only maps too, as a record of the configured times
///   (only the bem_* series use it there).
/// - The data variables are map::kQuantities that the layout stores, in that order, over
///   the grid's axes (and `time` for a series): flags are int8 with flag_values /
///   flag_meanings (HDF5 fill value -1 = not_computed; no _FillValue attribute, so readers
///   do not turn the codes into floats), reals float64 with `_FillValue` and HDF5 fill NaN.
///   The model's series are stored with Quantities::full, the bem_* variables with a BEM
///   reference (MapLayout::bem) whatever the quantities; cells outside the reference
///   sample read -1 or NaN.
/// - Every variable is chunked by MapLayout::chunk (times whole for the series) and
///   compressed with shuffle + deflate level 1. A tile that is exactly one chunk (or the
///   part of one inside the grid) is stored encoded (TileEncoder) with H5Dwrite_chunk; any
///   other box goes through HDF5's filter pipeline. Readers see no difference.
/// - Global attributes: Conventions "CF-1.8", title, source, history, config, identity, creep_law,
///   C, time_unit, for a material map material, material_file (its text), E0_Pa, E0_star_Pa
///   (the pressure scale) and poisson, R (a UDUNITS-2 string "50 um") and R_m (float64, metres) where the sweep was given model.R, with a BEM reference bem_grid (int32), bem_tolerance (float64), bem_sample and
///   bem_seed (int64), bem_method (string), bem_sample_rule (string: all, random, invalid or boundary), then completed (int8, 0 until finish() sets 1),
///   and from finish(): ranks, wall_seconds, points_per_second.
///
/// All strings are scalar variable-length UTF-8 attributes (one-character fixed-length
/// strings such as units "1" would come back from h5netcdf as bytes).
/// Errors throw Hdf5Error naming the file and the operation. Not thread-safe.
class RegimeMapWriter {
 public:
  /// Creates `path` anew (an existing file or symbolic link there is removed, never
  /// followed or truncated) with every coordinate, variable and attribute.
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
  void write_tile(const map::TileBox& box, const map::TileData& data);

  /// Stores a tile that a TileEncoder of this map's layout encoded, one H5Dwrite_chunk per
  /// variable (no compression here). Throws std::invalid_argument if `box` is not one chunk
  /// (or the part of one inside the grid), or `tile` has another number of chunks or points.
  void write_encoded(const map::TileBox& box, const EncodedTile& tile);

  /// Hands everything written so far to the operating system.
  void flush();

  /// Stores the run statistics, sets `completed` = 1 and closes the file. The writer can
  /// do nothing afterwards. A writer destroyed without finish() leaves `completed` = 0.
  void finish(int ranks, double wall_seconds, double points_per_second);

  const std::string& path() const { return path_; }

 private:
  /// units (and scaled_by) of a value measured in `scale` (see write_units in the .cpp).
  void write_units(hid_t object, const std::string& scale, const std::string& where) const;
  /// A 1-D dimension scale `name` of `count` values (file and memory types given), with
  /// attribute creation order tracked, as every coordinate is created.
  Handle dimension_scale(const std::string& name, hid_t file_type, hid_t memory_type, std::size_t count,
                         const void* values);
  /// A categorical axis: a variable-length UTF-8 string coordinate of its labels.
  void create_label_coordinate(const std::string& name, const std::vector<std::string>& labels,
                               const std::string& long_name);
  void create_coordinate(const std::string& name, const std::vector<double>& values, const std::string& scale,
                         const std::string& long_name);
  /// An int8 flag variable when `codes`, else float64; over the time axis too when `series`.
  Handle create_variable(const std::string& name, bool codes, bool series);
  void write_hyperslab(const map::TileBox& box, const map::TileData& data);
  void require_open(const char* operation) const;

  std::string time_unit_;
  std::string path_;
  TileEncoder encoder_;  ///< holds the layout; encodes write_tile's whole-chunk tiles
  Handle file_;
  std::vector<Handle> coordinates_;  ///< the grid's axes, then time
  std::vector<std::size_t> stored_;  ///< the map::kQuantities the map stores, in order
  std::vector<Handle> variables_;    ///< their datasets, one per entry of stored_
  Handle space_point_;               ///< file dataspace over the grid (selection reused)
  Handle space_series_;              ///< file dataspace over the grid and the times
};

}  // namespace punchsweep::io
