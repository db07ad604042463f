#include "io/regime_map_writer.hpp"

#include <H5DSpublic.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "io/hdf5_attributes.hpp"
#include "io/map_variables.hpp"
#include "map/layout_version.hpp"
#include "model/point/parameters.hpp"
#include "model/contact/regime.hpp"
#include "model/point/validity.hpp"

namespace punchsweep::io {

namespace {

/// The flag_values and flag_meanings of a flag set: the model's codes 0, 1, ... by their
/// names (a file-format contract: docs/maps.md, "Validity"; never renumbered), then -1 not_computed.
struct FlagSet {
  std::vector<std::int8_t> values;
  std::string meanings;
};

FlagSet flag_set(map::Flags flags) {
  FlagSet set;
  const auto add = [&](std::int8_t code, std::string_view name) {
    set.values.push_back(code);
    if (!set.meanings.empty()) set.meanings += ' ';
    set.meanings.append(name);
  };
  if (flags == map::Flags::regime) {
    for (const model::Regime r : {model::Regime::immediate, model::Regime::delayed, model::Regime::never}) {
      add(static_cast<std::int8_t>(r), model::regime_name(r));
    }
  } else if (flags == map::Flags::convergence) {
    for (const map::Convergence c : map::kConvergences) add(static_cast<std::int8_t>(c), map::flag_meaning(c));
  } else if (flags == map::Flags::source) {
    for (const map::AnswerSource s : map::kAnswerSources) add(static_cast<std::int8_t>(s), map::flag_meaning(s));
  } else {
    for (const model::Validity v : model::kValidities) {
      add(static_cast<std::int8_t>(v), model::validity_name(v));
    }
  }
  add(kNotComputed, "not_computed");
  return set;
}

/// What the scales of the `scaled_by` attributes are (global attribute `scales`).
constexpr const char* kScales =
    "Every real variable and coordinate is a pure number (units = \"1\"); its attribute scaled_by names the "
    "scale it is measured in. R: the characteristic punch size of f(r) = C r^s / R^(s-1); E0/(1-nu^2): the "
    "instantaneous plane-strain modulus E0* (E0 the instantaneous Young's modulus, nu Poisson's ratio); "
    "R^2 E0/(1-nu^2): a load; T_eps: the creep (retardation) time of the material. A variable without "
    "scaled_by is dimensionless.";

/// How an axis is spaced, for plots: see the class comment in the header.
const char* axis_spacing(const map::Axis& axis) {
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
    : time_unit_(attributes.time_unit), path_(path), encoder_(layout) {  // the encoder checks the layout before any file exists
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
  // A new file, never one written through: whatever is at the path goes first (a reader
  // that holds an old file keeps it whole), and H5F_ACC_EXCL (O_CREAT | O_EXCL) then
  // refuses a file or symbolic link planted there meanwhile rather than follow it.
  if (::unlink(path_.c_str()) != 0 && errno != ENOENT) {
    throw std::runtime_error("cannot replace " + path_ + ": " + std::strerror(errno));
  }
  file_ = Handle(H5Fcreate(path_.c_str(), H5F_ACC_EXCL, fcpl, H5P_DEFAULT), H5Fclose, "create file " + path_);

  write_string_attribute(file_, "Conventions", "CF-1.8", in);
  write_string_attribute(file_, "title", attributes.title, in);
  write_string_attribute(file_, "source", attributes.source, in);
  write_string_attribute(file_, "history", attributes.history, in);
  write_string_attribute(file_, "config", attributes.config_text, in);
  write_string_attribute(file_, "identity", attributes.identity, in);
  write_double_attribute(file_, "layout_version", map::kRegimeLayoutVersion, in);
  write_string_attribute(file_, "creep_law", attributes.creep_law, in);
  write_double_attribute(file_, "C", attributes.C, in);
  write_string_attribute(file_, "localization", attributes.localization, in);
  write_string_attribute(file_, "time_unit", attributes.time_unit, in);
  if (!attributes.material.name.empty()) {
    write_string_attribute(file_, "material", attributes.material.name, in);
    write_string_attribute(file_, "material_file", attributes.material.text, in);
    if (attributes.material.E0_Pa > 0.0) {  // one material: its pressure scale
      write_double_attribute(file_, "E0_Pa", attributes.material.E0_Pa, in);
      write_double_attribute(file_, "E0_star_Pa", attributes.material.E0_star_Pa, in);
      write_double_attribute(file_, "poisson", attributes.material.poisson, in);
    }
  }
  if (!attributes.R.empty()) {
    write_string_attribute(file_, "R", attributes.R, in);
    write_double_attribute(file_, "R_m", attributes.R_m, in);
  }
  write_string_attribute(file_, "scales", kScales, in);
  if (layout.bem) {
    const BemSetup& bem = *layout.bem;
    const std::int32_t grid = bem.grid;
    write_attribute(file_, "bem_grid", H5T_STD_I32LE, H5T_NATIVE_INT32, &grid, 0, in);
    write_double_attribute(file_, "bem_tolerance", bem.tolerance, in);
    write_attribute(file_, "bem_sample", H5T_STD_I64LE, H5T_NATIVE_INT64, &bem.sample, 0, in);
    write_attribute(file_, "bem_seed", H5T_STD_I64LE, H5T_NATIVE_INT64, &bem.seed, 0, in);
    write_string_attribute(file_, "bem_method", bem.method, in);
    write_string_attribute(file_, "bem_sample_rule", bem.sample_rule, in);
  }
  if (!layout.tolerance.empty()) write_string_attribute(file_, "tolerance", layout.tolerance, in);
  const std::int8_t incomplete = 0;
  write_attribute(file_, "completed", H5T_STD_I8LE, H5T_NATIVE_INT8, &incomplete, 0, in);

  for (const map::Axis& axis : layout.grid.axes) {
    // Each axis is a model parameter, which declares its units and long name.
    const model::Parameter* parameter = model::find_parameter(axis.name);
    if (parameter == nullptr) throw std::invalid_argument("regime map: axis " + axis.name + " is no model parameter");
    if (!axis.labels.empty()) {
      create_label_coordinate(axis.name, axis.labels, std::string(parameter->long_name));
    } else {
      create_coordinate(axis.name, axis.values, std::string(parameter->scale), std::string(parameter->long_name));
    }
    const std::string where = "on '" + axis.name + "' " + in;
    write_string_attribute(coordinates_.back(), "axis_spec", axis.text, where);
    write_string_attribute(coordinates_.back(), "spacing", axis.labels.empty() ? axis_spacing(axis) : "list", where);
  }
  create_coordinate("time", layout.times, "T_eps", "snapshot time");

  const std::size_t axes = layout.grid.rank();
  std::vector<hsize_t> dims(axes + 1);
  const map::Index shape = layout.grid.shape();
  for (std::size_t a = 0; a < axes; ++a) dims[a] = shape[a];
  dims[axes] = layout.times.size();
  space_point_ = Handle(H5Screate_simple(static_cast<int>(axes), dims.data(), nullptr), H5Sclose,
                        "make the grid's dataspace " + in);
  space_series_ = Handle(H5Screate_simple(static_cast<int>(axes + 1), dims.data(), nullptr), H5Sclose,
                         "make the series' dataspace " + in);

  stored_ = stored_variables(layout);
  for (const std::size_t q : stored_) {
    const map::QuantitySpec& spec = map::kQuantities[q];
    const std::string name(spec.name);
    const bool series = spec.extent == map::Extent::series;
    Handle dataset = create_variable(name, spec.kind == map::Kind::flag, series);
    const std::string where = "on '" + name + "' " + in;
    const std::size_t rank = series ? axes + 1 : axes;
    for (std::size_t d = 0; d < rank; ++d) {
      check(H5DSattach_scale(dataset, coordinates_[d], static_cast<unsigned>(d)),
            "attach dimension " + (d < axes ? layout.grid.axes[d].name : std::string("time")) + " " + where);
    }
    if (!spec.scale.empty()) write_units(dataset, std::string(spec.scale), where);
    write_string_attribute(dataset, "long_name", std::string(spec.long_name), where);
    if (!spec.comment.empty()) write_string_attribute(dataset, "comment", std::string(spec.comment), where);
    if (spec.kind == map::Kind::flag) {
      const FlagSet flags = flag_set(spec.flags);
      write_attribute(dataset, "flag_values", H5T_STD_I8LE, H5T_NATIVE_INT8, flags.values.data(),
                      flags.values.size(), where);
      write_string_attribute(dataset, "flag_meanings", flags.meanings, where);
    } else {
      write_double_attribute(dataset, "_FillValue", std::numeric_limits<double>::quiet_NaN(), where);
    }
    variables_.push_back(std::move(dataset));
  }
}

Handle RegimeMapWriter::dimension_scale(const std::string& name, hid_t file_type, hid_t memory_type,
                                        std::size_t count, const void* values) {
  const std::string where = "'" + name + "' in " + path_;
  const auto n = static_cast<hsize_t>(count);
  const Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "make dataspace of " + where);
  const Handle dcpl = make_property_list(H5P_DATASET_CREATE, "make creation properties of " + where);
  check(H5Pset_attr_creation_order(dcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
        "set attribute order of " + where);
  Handle dataset(H5Dcreate2(file_, name.c_str(), file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose,
                 "create coordinate " + where);
  if (count > 0) {
    check(H5Dwrite(dataset, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values), "write coordinate " + where);
  }
  check(H5DSset_scale(dataset, name.c_str()), "make dimension scale of " + where);
  return dataset;
}

void RegimeMapWriter::create_label_coordinate(const std::string& name, const std::vector<std::string>& labels,
                                              const std::string& long_name) {
  const std::string where = "'" + name + "' in " + path_;
  const Handle type = string_type("make a string type for " + where);
  std::vector<const char*> text;
  for (const std::string& label : labels) text.push_back(label.c_str());
  Handle dataset = dimension_scale(name, type, type, text.size(), text.data());
  write_string_attribute(dataset, "long_name", long_name, "on " + where);
  coordinates_.push_back(std::move(dataset));
}

/// A time in a material's unit and a temperature have real units; everything else is a
/// pure number with its scale (write_scale).
void RegimeMapWriter::write_units(hid_t object, const std::string& scale, const std::string& where) const {
  if (scale == "T_eps" && time_unit_ != "T_eps") {
    write_string_attribute(object, "units", time_unit_, where);
  } else if (scale == "degC") {
    write_string_attribute(object, "units", "degC", where);
  } else {
    write_scale(object, scale, where);
  }
}

void RegimeMapWriter::create_coordinate(const std::string& name, const std::vector<double>& values,
                                        const std::string& scale, const std::string& long_name) {
  const std::string where = "'" + name + "' in " + path_;
  Handle dataset = dimension_scale(name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.size(), values.data());
  const std::string on = "on " + where;
  write_units(dataset, scale, on);
  write_string_attribute(dataset, "long_name", long_name, on);
  coordinates_.push_back(std::move(dataset));
}

Handle RegimeMapWriter::create_variable(const std::string& name, bool codes, bool series) {
  const std::string where = "'" + name + "' in " + path_;
  const Handle dcpl = make_property_list(H5P_DATASET_CREATE, "make creation properties of " + where);
  check(H5Pset_attr_creation_order(dcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED),
        "set attribute order of " + where);
  const MapLayout& layout = encoder_.layout();
  const std::size_t axes = layout.grid.rank();
  std::vector<hsize_t> chunk(axes + 1);
  for (std::size_t a = 0; a < axes; ++a) chunk[a] = layout.chunk[a];
  chunk[axes] = layout.times.size();
  const int rank = static_cast<int>(series ? axes + 1 : axes);
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
      H5Dcreate2(file_, name.c_str(), type, series ? space_series_ : space_point_, H5P_DEFAULT, dcpl, H5P_DEFAULT),
      H5Dclose, "create variable " + where);
}

void RegimeMapWriter::require_open(const char* operation) const {
  if (file_.get() < 0)
    throw std::logic_error(std::string("regime map ") + path_ + ": " + operation + " after finish()");
}

void RegimeMapWriter::write_tile(const map::TileBox& box, const map::TileData& data) {
  require_open("write_tile");
  const MapLayout& layout = encoder_.layout();
  require_inside_grid(layout, box);
  require_tile_arrays(layout, box.points(), data);
  if (is_one_chunk(layout, box)) {
    write_encoded(box, encoder_.encode(0, box, data));  // the tile index is not stored in the map
  } else {
    write_hyperslab(box, data);
  }
}

void RegimeMapWriter::write_encoded(const map::TileBox& box, const EncodedTile& tile) {
  require_open("write_encoded");
  require_one_chunk(encoder_.layout(), box);
  if (tile.chunks.size() != variables_.size() || tile.summary.points != box.points()) {
    throw std::invalid_argument("regime map: encoded tile " + std::to_string(tile.tile) + " has " +
                                std::to_string(tile.chunks.size()) + " chunks and " +
                                std::to_string(tile.summary.points) + " points, the map needs " +
                                std::to_string(variables_.size()) + " chunks and the box has " +
                                std::to_string(box.points()) + " points");
  }
  std::vector<hsize_t> offset(box.start.size() + 1, 0);
  for (std::size_t a = 0; a < box.start.size(); ++a) offset[a] = box.start[a];
  for (std::size_t v = 0; v < variables_.size(); ++v) {
    check(H5Dwrite_chunk(variables_[v], H5P_DEFAULT, 0, offset.data(), tile.chunks[v].size(),
                         tile.chunks[v].data()),
          "write a chunk of variable '" + std::string(map::kQuantities[stored_[v]].name) + "' to " + path_);
  }
}

void RegimeMapWriter::write_hyperslab(const map::TileBox& box, const map::TileData& data) {
  const std::size_t axes = box.start.size();
  std::vector<hsize_t> start(axes + 1, 0);
  std::vector<hsize_t> count(axes + 1, 0);
  for (std::size_t a = 0; a < axes; ++a) {
    start[a] = box.start[a];
    count[a] = box.count[a];
  }
  const MapLayout& layout = encoder_.layout();
  count[axes] = layout.times.size();
  const std::string in = " to " + path_;
  const int rank = static_cast<int>(axes);
  check(H5Sselect_hyperslab(space_point_, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
        "select tile" + in);
  const Handle memory_point(H5Screate_simple(rank, count.data(), nullptr), H5Sclose, "make tile dataspace" + in);
  Handle memory_series;
  if (layout.has_series()) {
    check(H5Sselect_hyperslab(space_series_, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr),
          "select tile series" + in);
    memory_series = Handle(H5Screate_simple(rank + 1, count.data(), nullptr), H5Sclose,
                           "make series dataspace" + in);
  }
  for (std::size_t v = 0; v < variables_.size(); ++v) {
    const std::size_t q = stored_[v];
    const map::QuantitySpec& spec = map::kQuantities[q];
    const bool series = spec.extent == map::Extent::series;
    const hid_t memory = series ? memory_series.get() : memory_point.get();
    const hid_t file = series ? space_series_.get() : space_point_.get();
    const herr_t status = spec.kind == map::Kind::flag
                              ? H5Dwrite(variables_[v], H5T_NATIVE_INT8, memory, file, H5P_DEFAULT, data.flag(q).data())
                              : H5Dwrite(variables_[v], H5T_NATIVE_DOUBLE, memory, file, H5P_DEFAULT,
                                         data.real(q).data());
    check(status, "write variable '" + std::string(spec.name) + "'" + in);
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
  space_series_.reset();
  space_point_.reset();
  variables_.clear();
  stored_.clear();
  coordinates_.clear();
  file_.reset();
}

}  // namespace punchsweep::io
