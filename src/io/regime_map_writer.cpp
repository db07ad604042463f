#include "io/regime_map_writer.hpp"

#include <H5DSpublic.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace punchsweep::io {

namespace {

/// One data variable of the map and the TileData array it comes from.
struct VariableSpec {
  const char* name;
  bool series;        ///< over (l, dh, T, pbar, s, time) rather than the 5 axes
  const char* units;  ///< nullptr for the flag variables, which have none
  const char* long_name;
  const char* comment;                        ///< nullptr when there is none
  std::vector<std::int8_t> TileData::*codes;  ///< int8 source, or nullptr
  std::vector<double> TileData::*values;      ///< float64 source, or nullptr
};

constexpr std::array<VariableSpec, 13> kVariables{{
    {"regime", false, nullptr, "contact regime of the level-2 punches", nullptr, &TileData::regime, nullptr},
    {"valid", false, nullptr, "validity of the localization method", nullptr, &TileData::valid, nullptr},
    {"t_star", false, "T_eps", "time at which the level-2 punches touch",
     "0 for the immediate regime, NaN for never", nullptr, &TileData::t_star},
    {"h_0", false, "R", "displacement difference between punch tip and square centre at t = 0", nullptr,
     nullptr, &TileData::h_0},
    {"h_inf", false, "R", "displacement difference between punch tip and square centre as t -> infinity",
     nullptr, nullptr, &TileData::h_inf},
    {"a1_inf", false, "R", "long-term contact radius of a level-1 punch", nullptr, nullptr,
     &TileData::a1_inf},
    {"a2_inf", false, "R", "long-term contact radius of a level-2 punch", nullptr, nullptr,
     &TileData::a2_inf},
    {"area_fraction_inf", false, "1", "long-term contact area fraction", nullptr, nullptr,
     &TileData::area_fraction_inf},
    {"a1", true, "R", "contact radius of a level-1 punch", nullptr, nullptr, &TileData::a1},
    {"a2", true, "R", "contact radius of a level-2 punch", nullptr, nullptr, &TileData::a2},
    {"P1", true, "R^2 E0/(1-nu^2)", "load on one level-1 punch", nullptr, nullptr, &TileData::P1},
    {"P2", true, "R^2 E0/(1-nu^2)", "load on one level-2 punch", nullptr, nullptr, &TileData::P2},
    {"area_fraction", true, "1", "contact area fraction", nullptr, nullptr, &TileData::area_fraction},
}};

// The codes are a file-format contract (README, "Validity"); never renumber them.
constexpr std::array<std::int8_t, 4> kRegimeFlags{0, 1, 2, -1};
constexpr const char* kRegimeMeanings = "immediate delayed never not_computed";
constexpr std::array<std::int8_t, 5> kValidFlags{0, 1, 2, 3, -1};
constexpr const char* kValidMeanings =
    "valid same_level_overlap cross_level_overlap no_solution not_computed";

constexpr std::int8_t kNotComputed = -1;
constexpr unsigned kDeflateLevel = 1;  // level 1: the sweep must write > 2e6 points/s

struct CoordinateSpec {
  const char* units;
  const char* long_name;
};
constexpr std::array<CoordinateSpec, sweep::kAxes> kAxisCoordinates{{
    {"R", "lattice pitch"},
    {"R", "height difference of the punch levels"},
    {"1", "creep ratio T_eps/T_sigma"},
    {"E0/(1-nu^2)", "nominal pressure"},
    {"1", "shape exponent"},
}};

Handle make_property_list(hid_t cls, const std::string& what) {
  return Handle(H5Pcreate(cls), H5Pclose, what);
}

Handle string_type(const std::string& what) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, what);
  check(H5Tset_size(type, H5T_VARIABLE), what);
  check(H5Tset_cset(type, H5T_CSET_UTF8), what);
  return type;
}

/// Creates attribute `name` on `object` with `count` values (0: a scalar) and writes them.
void write_attribute(hid_t object, const char* name, hid_t file_type, hid_t memory_type, const void* values,
                     hsize_t count, const std::string& where) {
  const std::string what = std::string("write attribute '") + name + "' " + where;
  Handle space(count == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr), H5Sclose, what);
  Handle attribute(H5Acreate2(object, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, what);
  check(H5Awrite(attribute, memory_type, values), what);
}

void write_string_attribute(hid_t object, const char* name, const std::string& value,
                            const std::string& where) {
  const Handle type = string_type(std::string("make a string type for '") + name + "' " + where);
  const char* text = value.c_str();
  write_attribute(object, name, type, type, &text, 0, where);
}

void write_double_attribute(hid_t object, const char* name, double value, const std::string& where) {
  write_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value, 0, where);
}

/// Copies a tile at the grid's edge into a whole chunk (row-major over `chunk`, `inner`
/// values per point), with `fill` in the part that lies outside the grid.
void pad_to_chunk(const std::byte* tile, std::size_t element, const void* fill, std::size_t inner,
                  const std::array<std::size_t, sweep::kAxes>& count,
                  const std::array<std::size_t, sweep::kAxes>& chunk, std::vector<std::byte>* out) {
  std::size_t values = inner;
  for (const std::size_t c : chunk) values *= c;
  out->resize(values * element);
  for (std::size_t i = 0; i < values; ++i) std::memcpy(out->data() + i * element, fill, element);
  const std::size_t run = count[4] * inner * element;  // the fastest axis is contiguous in both
  const std::byte* from = tile;
  for (std::size_t i0 = 0; i0 < count[0]; ++i0) {
    for (std::size_t i1 = 0; i1 < count[1]; ++i1) {
      for (std::size_t i2 = 0; i2 < count[2]; ++i2) {
        for (std::size_t i3 = 0; i3 < count[3]; ++i3) {
          const std::size_t to = (((i0 * chunk[1] + i1) * chunk[2] + i2) * chunk[3] + i3) * chunk[4];
          std::memcpy(out->data() + to * inner * element, from, run);
          from += run;
        }
      }
    }
  }
}

/// How an axis is spaced, for plots: see the class comment in the header.
const char* axis_spacing(const sweep::Axis& axis) {
  if (axis.log_spaced) return "log";
  const std::vector<double>& v = axis.values;
  if (v.size() < 3) return "linear";
  const double step = (v.back() - v.front()) / static_cast<double>(v.size() - 1);
  const double tolerance = 1e-9 * std::abs(v.back() - v.front());
  for (std::size_t i = 1; i < v.size(); ++i) {
    if (std::abs(v[i] - v[i - 1] - step) > tolerance) return "list";
  }
  return "linear";
}

}  // namespace

RegimeMapWriter::RegimeMapWriter(const std::string& path, const MapLayout& layout,
                                 const MapAttributes& attributes)
    : path_(path),
      shape_(layout.grid.shape()),
      chunk_(layout.chunk),
      times_(layout.times.size()),
      full_(layout.quantities == sweep::Quantities::full),
      compressor_(static_cast<int>(kDeflateLevel)) {
  for (std::size_t a = 0; a < sweep::kAxes; ++a) {
    if (shape_[a] == 0)
      throw std::invalid_argument(std::string("regime map: axis ") + sweep::kAxisNames[a] + " is empty");
    if (layout.chunk[a] < 1 || layout.chunk[a] > shape_[a]) {
      throw std::invalid_argument(std::string("regime map: chunk length ") + std::to_string(layout.chunk[a]) +
                                  " on axis " + sweep::kAxisNames[a] + " is outside [1, " +
                                  std::to_string(shape_[a]) + "]");
    }
  }
  if (full_ && times_ == 0)
    throw std::invalid_argument("regime map: the full quantities need at least one time");

  // Our exceptions name the file and the operation; HDF5's own stack dump would only
  // bury them (this is process-wide, and nothing in punchsweep wants the dump).
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);

  const std::string in = "in " + path_;
  const Handle fcpl = make_property_list(H5P_FILE_CREATE, "make file creation properties for " + path_);
  // netCDF-4 files track the creation order of links and attributes; netCDF readers list
  // variables and attributes in that order (definition order, not alphabetical).
  check(H5Pset_link_creation_order(fcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
        "set link order " + in);
  check(H5Pset_attr_creation_order(fcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
        "set attribute order " + in);
  file_ =
      Handle(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, fcpl, H5P_DEFAULT), H5Fclose, "create file " + path_);

  write_string_attribute(file_, "Conventions", "CF-1.8", in);
  write_string_attribute(file_, "title", attributes.title, in);
  write_string_attribute(file_, "source", attributes.source, in);
  write_string_attribute(file_, "history", attributes.history, in);
  write_string_attribute(file_, "config", attributes.config_text, in);
  write_string_attribute(file_, "creep_law", attributes.creep_law, in);
  write_double_attribute(file_, "C", attributes.C, in);
  const std::int8_t incomplete = 0;
  write_attribute(file_, "completed", H5T_STD_I8LE, H5T_NATIVE_INT8, &incomplete, 0, in);

  for (std::size_t a = 0; a < sweep::kAxes; ++a) {
    const sweep::Axis& axis = layout.grid.axes[a];
    create_coordinate(sweep::kAxisNames[a], axis.values, kAxisCoordinates[a].units,
                      kAxisCoordinates[a].long_name);
    const std::string where = std::string("on '") + sweep::kAxisNames[a] + "' " + in;
    write_string_attribute(coordinates_.back(), "axis_spec", axis.text, where);
    write_string_attribute(coordinates_.back(), "spacing", axis_spacing(axis), where);
  }
  create_coordinate("time", layout.times, "T_eps", "snapshot time");

  std::array<hsize_t, sweep::kAxes + 1> dims{};
  for (std::size_t a = 0; a < sweep::kAxes; ++a) dims[a] = shape_[a];
  dims[sweep::kAxes] = times_;
  space5_ =
      Handle(H5Screate_simple(sweep::kAxes, dims.data(), nullptr), H5Sclose, "make 5-D dataspace " + in);
  space6_ =
      Handle(H5Screate_simple(sweep::kAxes + 1, dims.data(), nullptr), H5Sclose, "make 6-D dataspace " + in);

  for (const VariableSpec& spec : kVariables) {
    if (spec.series && !full_) continue;
    Handle dataset = create_variable(spec.name, spec.codes != nullptr, spec.series);
    const std::string where = std::string("on '") + spec.name + "' " + in;
    const std::size_t rank = spec.series ? sweep::kAxes + 1 : sweep::kAxes;
    for (std::size_t d = 0; d < rank; ++d) {
      check(H5DSattach_scale(dataset, coordinates_[d], static_cast<unsigned>(d)),
            std::string("attach dimension ") + (d < sweep::kAxes ? sweep::kAxisNames[d] : "time") + " " +
                where);
    }
    if (spec.units != nullptr) write_string_attribute(dataset, "units", spec.units, where);
    write_string_attribute(dataset, "long_name", spec.long_name, where);
    if (spec.comment != nullptr) write_string_attribute(dataset, "comment", spec.comment, where);
    if (spec.codes == &TileData::regime) {
      write_attribute(dataset, "flag_values", H5T_STD_I8LE, H5T_NATIVE_INT8, kRegimeFlags.data(),
                      kRegimeFlags.size(), where);
      write_string_attribute(dataset, "flag_meanings", kRegimeMeanings, where);
    } else if (spec.codes == &TileData::valid) {
      write_attribute(dataset, "flag_values", H5T_STD_I8LE, H5T_NATIVE_INT8, kValidFlags.data(),
                      kValidFlags.size(), where);
      write_string_attribute(dataset, "flag_meanings", kValidMeanings, where);
    } else {
      write_double_attribute(dataset, "_FillValue", std::numeric_limits<double>::quiet_NaN(), where);
    }
    variables_.push_back(std::move(dataset));
  }
}

void RegimeMapWriter::create_coordinate(const char* name, const std::vector<double>& values,
                                        const char* units, const char* long_name) {
  const std::string where = std::string("'") + name + "' in " + path_;
  const auto n = static_cast<hsize_t>(values.size());
  const Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "make dataspace of " + where);
  const Handle dcpl = make_property_list(H5P_DATASET_CREATE, "make creation properties of " + where);
  check(H5Pset_attr_creation_order(dcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
        "set attribute order of " + where);
  Handle dataset(H5Dcreate2(file_, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose,
                 "create coordinate " + where);
  if (!values.empty()) {
    check(H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
          "write coordinate " + where);
  }
  check(H5DSset_scale(dataset, name), "make dimension scale of " + where);
  const std::string on = "on " + where;
  write_string_attribute(dataset, "units", units, on);
  write_string_attribute(dataset, "long_name", long_name, on);
  coordinates_.push_back(std::move(dataset));
}

Handle RegimeMapWriter::create_variable(const std::string& name, bool codes, bool series) {
  const std::string where = "'" + name + "' in " + path_;
  const Handle dcpl = make_property_list(H5P_DATASET_CREATE, "make creation properties of " + where);
  check(H5Pset_attr_creation_order(dcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
        "set attribute order of " + where);
  std::array<hsize_t, sweep::kAxes + 1> chunk{};
  for (std::size_t a = 0; a < sweep::kAxes; ++a) chunk[a] = chunk_[a];
  chunk[sweep::kAxes] = times_;
  const int rank = series ? sweep::kAxes + 1 : sweep::kAxes;
  check(H5Pset_chunk(dcpl, rank, chunk.data()), "set chunk shape of " + where);
  check(H5Pset_shuffle(dcpl), "set shuffle filter of " + where);
  check(H5Pset_deflate(dcpl, kDeflateLevel), "set deflate filter of " + where);
  // The HDF5 fill value is what never-written cells read as: not_computed, or NaN.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  check(codes ? H5Pset_fill_value(dcpl, H5T_NATIVE_INT8, &kNotComputed)
              : H5Pset_fill_value(dcpl, H5T_NATIVE_DOUBLE, &nan),
        "set fill value of " + where);
  // Tiles that are not one chunk go through the default chunk cache (1 MiB per dataset).
  const hid_t type = codes ? H5T_STD_I8LE : H5T_IEEE_F64LE;
  return Handle(
      H5Dcreate2(file_, name.c_str(), type, series ? space6_ : space5_, H5P_DEFAULT, dcpl, H5P_DEFAULT),
      H5Dclose, "create variable " + where);
}

void RegimeMapWriter::require_open(const char* operation) const {
  if (file_.get() < 0)
    throw std::logic_error(std::string("regime map ") + path_ + ": " + operation + " after finish()");
}

void RegimeMapWriter::write_tile(const sweep::TileBox& box, const TileData& data) {
  require_open("write_tile");
  for (std::size_t a = 0; a < sweep::kAxes; ++a) {
    if (box.count[a] == 0 || box.start[a] + box.count[a] > shape_[a]) {
      throw std::invalid_argument(std::string("regime map: tile range [") + std::to_string(box.start[a]) +
                                  ", " + std::to_string(box.start[a] + box.count[a]) + ") on axis " +
                                  sweep::kAxisNames[a] + " is empty or outside [0, " +
                                  std::to_string(shape_[a]) + ")");
    }
  }
  const std::size_t points = box.points();
  const std::size_t series = full_ ? points * times_ : 0;
  for (const VariableSpec& spec : kVariables) {
    const std::size_t expected = spec.series ? series : points;
    const std::size_t size = spec.codes != nullptr ? (data.*spec.codes).size() : (data.*spec.values).size();
    if (size != expected) {
      throw std::invalid_argument(std::string("regime map: tile array ") + spec.name + " has " +
                                  std::to_string(size) + " values, the tile needs " +
                                  std::to_string(expected));
    }
  }

  if (is_one_chunk(box)) {
    write_chunk(box, data);
  } else {
    write_hyperslab(box, data);
  }
}

bool RegimeMapWriter::is_one_chunk(const sweep::TileBox& box) const {
  // Encoded chunks hold the file's little-endian bytes, which only a little-endian host has.
  if constexpr (std::endian::native != std::endian::little) return false;
  for (std::size_t a = 0; a < sweep::kAxes; ++a) {
    if (box.start[a] % chunk_[a] != 0) return false;
    const bool whole = box.count[a] == chunk_[a];
    const bool rest_of_grid = box.count[a] < chunk_[a] && box.start[a] + box.count[a] == shape_[a];
    if (!whole && !rest_of_grid) return false;
  }
  return true;
}

void RegimeMapWriter::write_chunk(const sweep::TileBox& box, const TileData& data) {
  std::array<hsize_t, sweep::kAxes + 1> offset{};
  for (std::size_t a = 0; a < sweep::kAxes; ++a) offset[a] = box.start[a];
  const bool edge = box.count != chunk_;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::size_t v = 0;
  for (const VariableSpec& spec : kVariables) {
    if (spec.series && !full_) continue;
    const bool codes = spec.codes != nullptr;
    const std::size_t element = codes ? sizeof(std::int8_t) : sizeof(double);
    const std::size_t inner = spec.series ? times_ : 1;
    const auto* tile = codes ? reinterpret_cast<const std::byte*>((data.*spec.codes).data())
                             : reinterpret_cast<const std::byte*>((data.*spec.values).data());
    std::span<const std::byte> encoded;
    if (edge) {
      const void* fill = codes ? static_cast<const void*>(&kNotComputed) : static_cast<const void*>(&nan);
      pad_to_chunk(tile, element, fill, inner, box.count, chunk_, &padded_);
      encoded = compressor_.compress(padded_.data(), padded_.size(), element);
    } else {
      encoded = compressor_.compress(tile, box.points() * inner * element, element);
    }
    check(H5Dwrite_chunk(variables_[v], H5P_DEFAULT, 0, offset.data(), encoded.size(), encoded.data()),
          std::string("write a chunk of variable '") + spec.name + "' to " + path_);
    ++v;
  }
}

void RegimeMapWriter::write_hyperslab(const sweep::TileBox& box, const TileData& data) {
  std::array<hsize_t, sweep::kAxes + 1> start{};
  std::array<hsize_t, sweep::kAxes + 1> count{};
  for (std::size_t a = 0; a < sweep::kAxes; ++a) {
    start[a] = box.start[a];
    count[a] = box.count[a];
  }
  count[sweep::kAxes] = times_;
  const std::string in = " to " + path_;
  check(H5Sselect_hyperslab(space5_, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
        "select tile" + in);
  const Handle memory5(H5Screate_simple(sweep::kAxes, count.data(), nullptr), H5Sclose,
                       "make tile dataspace" + in);
  Handle memory6;
  if (full_) {
    check(H5Sselect_hyperslab(space6_, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
          "select tile series" + in);
    memory6 = Handle(H5Screate_simple(sweep::kAxes + 1, count.data(), nullptr), H5Sclose,
                     "make series dataspace" + in);
  }
  std::size_t v = 0;
  for (const VariableSpec& spec : kVariables) {
    if (spec.series && !full_) continue;
    const hid_t memory = spec.series ? memory6.get() : memory5.get();
    const hid_t file = spec.series ? space6_.get() : space5_.get();
    const herr_t status = spec.codes != nullptr ? H5Dwrite(variables_[v], H5T_NATIVE_INT8, memory, file,
                                                           H5P_DEFAULT, (data.*spec.codes).data())
                                                : H5Dwrite(variables_[v], H5T_NATIVE_DOUBLE, memory, file,
                                                           H5P_DEFAULT, (data.*spec.values).data());
    check(status, std::string("write variable '") + spec.name + "'" + in);
    ++v;
  }
}

void RegimeMapWriter::flush() {
  require_open("flush");
  check(H5Fflush(file_, H5F_SCOPE_LOCAL), "flush " + path_);
}

void RegimeMapWriter::finish(int ranks, double wall_seconds, double points_per_second) {
  require_open("finish");
  const std::string in = "in " + path_;
  write_attribute(file_, "ranks", H5T_STD_I32LE, H5T_NATIVE_INT32, &ranks, 0, in);
  write_double_attribute(file_, "wall_seconds", wall_seconds, in);
  write_double_attribute(file_, "points_per_second", points_per_second, in);
  {
    const Handle completed(H5Aopen(file_, "completed", H5P_DEFAULT), H5Aclose,
                           "open attribute 'completed' " + in);
    const std::int8_t done = 1;
    check(H5Awrite(completed, H5T_NATIVE_INT8, &done), "write attribute 'completed' " + in);
  }
  // Flush with a checked status first: closing reports no errors through Handle.
  check(H5Fflush(file_, H5F_SCOPE_LOCAL), "flush " + path_);
  space6_.reset();
  space5_.reset();
  variables_.clear();
  coordinates_.clear();
  file_.reset();
}

}  // namespace punchsweep::io
