#include "io/netcdf_file.hpp"

#include <H5DSpublic.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <optional>
#include <stdexcept>

#include "io/hdf5_attributes.hpp"

namespace punchsweep::io {

NetcdfFile::NetcdfFile(const std::string& path) : path_(path) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const Handle fcpl = make_property_list(H5P_FILE_CREATE, "make file creation properties for " + path_);
  // netCDF-4 tracks the creation order of links and attributes (readers list them so).
  check(H5Pset_link_creation_order(fcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED), "set link order in " + path_);
  check(H5Pset_attr_creation_order(fcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED), "set attribute order in " + path_);
  if (::unlink(path_.c_str()) != 0 && errno != ENOENT) {
    throw std::runtime_error("cannot replace " + path_ + ": " + std::strerror(errno));
  }
  file_ = Handle(H5Fcreate(path_.c_str(), H5F_ACC_EXCL, fcpl, H5P_DEFAULT), H5Fclose, "create " + path_);
}

void NetcdfFile::attribute(const std::string& name, const std::string& value) {
  write_string_attribute(file_, name.c_str(), value, "in " + path_);
}

void NetcdfFile::attribute(const std::string& name, double value) {
  write_double_attribute(file_, name.c_str(), value, "in " + path_);
}

hid_t NetcdfFile::scale(const std::string& dim, const std::string& where) const {
  const auto found = std::find_if(coordinates_.begin(), coordinates_.end(), [&](const auto& c) { return c.first == dim; });
  if (found == coordinates_.end()) throw std::invalid_argument("NetcdfFile: no coordinate '" + dim + "' for " + where);
  return found->second;
}

std::vector<hsize_t> NetcdfFile::shape_of(const std::vector<std::string>& dims, const std::string& where) const {
  std::vector<hsize_t> shape;
  for (const std::string& dim : dims) {
    shape.push_back(static_cast<hsize_t>(
        H5Sget_simple_extent_npoints(Handle(H5Dget_space(scale(dim, where)), H5Sclose, "space of " + dim))));
  }
  return shape;
}

Handle NetcdfFile::creation_properties(const std::vector<hsize_t>& chunk, const std::string& where) {
  Handle dcpl = make_property_list(H5P_DATASET_CREATE, "make creation properties of " + where);
  check(H5Pset_attr_creation_order(dcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED), "set attribute order of " + where);
  if (!chunk.empty()) {
    check(H5Pset_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data()), "set chunk shape of " + where);
    check(H5Pset_shuffle(dcpl), "set shuffle filter of " + where);
    check(H5Pset_deflate(dcpl, 4), "set deflate filter of " + where);
  }
  return dcpl;
}

Handle NetcdfFile::create(const std::string& name, const std::vector<std::string>& dims, hid_t file_type,
                          std::size_t count) {
  const std::string where = "'" + name + "' in " + path_;
  const std::vector<hsize_t> shape = shape_of(dims, where);
  std::size_t expected = 1;
  for (const hsize_t n : shape) expected *= static_cast<std::size_t>(n);
  if (expected != count) throw std::invalid_argument("NetcdfFile: " + where + " has " + std::to_string(count) + " values for " + std::to_string(expected));
  const Handle space(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), H5Sclose, "make dataspace of " + where);
  // One chunk, the whole variable.
  const Handle dcpl = creation_properties(count > 0 ? shape : std::vector<hsize_t>{}, where);
  return Handle(H5Dcreate2(file_, name.c_str(), file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose, "create " + where);
}

void NetcdfFile::finish(hid_t dataset, const std::string& name, const std::vector<std::string>& dims,
                        const Attributes& attributes) {
  const std::string where = "on '" + name + "' in " + path_;
  for (std::size_t d = 0; d < dims.size(); ++d) {
    check(H5DSattach_scale(dataset, scale(dims[d], where), static_cast<unsigned>(d)), "attach dimension " + dims[d] + " " + where);
  }
  for (const auto& [key, value] : attributes) write_string_attribute(dataset, key.c_str(), value, where);
}

void NetcdfFile::coordinate(const std::string& name, const std::vector<double>& values, const Attributes& attributes) {
  const std::string where = "'" + name + "' in " + path_;
  const auto n = static_cast<hsize_t>(values.size());
  const Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "make dataspace of " + where);
  const Handle dcpl = make_property_list(H5P_DATASET_CREATE, "make creation properties of " + where);
  check(H5Pset_attr_creation_order(dcpl, H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED), "set attribute order of " + where);
  Handle dataset(H5Dcreate2(file_, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose,
                 "create coordinate " + where);
  if (!values.empty()) check(H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write " + where);
  check(H5DSset_scale(dataset, name.c_str()), "make dimension scale of " + where);
  for (const auto& [key, value] : attributes) write_string_attribute(dataset, key.c_str(), value, "on " + where);
  coordinates_.emplace_back(name, std::move(dataset));
}

void NetcdfFile::variable(const std::string& name, const std::vector<std::string>& dims, const std::vector<double>& values,
                          const Attributes& attributes) {
  const Handle dataset = create(name, dims, H5T_IEEE_F64LE, values.size());
  check(H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write '" + name + "' in " + path_);
  finish(dataset, name, dims, attributes);
}

void NetcdfFile::declare(const std::string& name, const std::vector<std::string>& dims, std::size_t slab_dims,
                         bool int8, double fill, const Attributes& attributes, const std::vector<std::int8_t>& flag_values,
                         std::size_t slab_rows) {
  const std::string where = "'" + name + "' in " + path_;
  if (slab_dims > dims.size()) throw std::invalid_argument("NetcdfFile: " + where + " has fewer dimensions than its slabs'");
  const std::vector<hsize_t> shape = shape_of(dims, where);
  std::vector<hsize_t> chunk = shape;  // a slab: 1 along its first slab_dims dimensions
  std::fill(chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(slab_dims), hsize_t{1});
  // (slab_rows of the next dimension, at most its length)
  if (slab_rows > 0 && slab_dims < shape.size()) chunk[slab_dims] = std::min<hsize_t>(slab_rows, std::max<hsize_t>(shape[slab_dims], 1));
  const Handle space(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), H5Sclose, "make dataspace of " + where);
  const Handle dcpl = creation_properties(chunk, where);
  const std::int8_t code = static_cast<std::int8_t>(fill);
  check(int8 ? H5Pset_fill_value(dcpl, H5T_NATIVE_INT8, &code) : H5Pset_fill_value(dcpl, H5T_NATIVE_DOUBLE, &fill),
        "set fill value of " + where);
  Handle dataset(H5Dcreate2(file_, name.c_str(), int8 ? H5T_STD_I8LE : H5T_IEEE_F64LE, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
                 H5Dclose, "create " + where);
  finish(dataset, name, dims, attributes);
  if (int8 && !flag_values.empty()) {
    write_attribute(dataset, "flag_values", H5T_STD_I8LE, H5T_NATIVE_INT8, flag_values.data(), flag_values.size(), "on " + where);
  }
  declared_.emplace_back(name, Declared{std::move(dataset), shape, slab_dims, int8});
}

void NetcdfFile::write_slab(const std::string& name, const std::vector<std::size_t>& at, std::span<const double> values,
                            Rows rows) {
  const std::string where = "'" + name + "' in " + path_;
  const auto found = std::find_if(declared_.begin(), declared_.end(), [&](const auto& d) { return d.first == name; });
  if (found == declared_.end()) throw std::invalid_argument("NetcdfFile: " + where + " was not declared");
  const Declared& v = found->second;
  if (at.size() != v.slab_dims) throw std::invalid_argument("NetcdfFile: a slab of " + where + " needs " + std::to_string(v.slab_dims) + " indices");
  std::vector<hsize_t> start(v.shape.size(), 0), count = v.shape;
  std::size_t n = 1;
  for (std::size_t d = 0; d < v.shape.size(); ++d) {
    if (d < v.slab_dims) {
      if (at[d] >= v.shape[d]) throw std::invalid_argument("NetcdfFile: slab index outside " + where);
      start[d] = at[d];
      count[d] = 1;
    } else if (d == v.slab_dims && rows.count > 0) {
      if (rows.first + rows.count > v.shape[d]) {
        throw std::invalid_argument("NetcdfFile: rows " + std::to_string(rows.first) + " to " +
                                    std::to_string(rows.first + rows.count) + " outside " + where);
      }
      start[d] = rows.first;
      count[d] = rows.count;
    }
    n *= static_cast<std::size_t>(count[d]);
  }
  if (values.size() != n) {
    throw std::invalid_argument("NetcdfFile: a slab of " + where + " has " + std::to_string(n) + " values, not " + std::to_string(values.size()));
  }
  const Handle file_space(H5Dget_space(v.dataset), H5Sclose, "space of " + where);
  if (!v.shape.empty()) {
    check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr), "select a slab of " + where);
  }
  const hsize_t m = static_cast<hsize_t>(n);
  const Handle memory_space(H5Screate_simple(1, &m, nullptr), H5Sclose, "memory space of " + where);
  if (v.int8) {
    codes_.resize(n);
    for (std::size_t k = 0; k < n; ++k) codes_[k] = static_cast<std::int8_t>(values[k]);
    check(H5Dwrite(v.dataset, H5T_NATIVE_INT8, memory_space, file_space, H5P_DEFAULT, codes_.data()), "write a slab of " + where);
  } else {
    check(H5Dwrite(v.dataset, H5T_NATIVE_DOUBLE, memory_space, file_space, H5P_DEFAULT, values.data()), "write a slab of " + where);
  }
}

void NetcdfFile::close() {
  declared_.clear();
  coordinates_.clear();
  if (file_.get() >= 0) check(H5Fflush(file_, H5F_SCOPE_GLOBAL), "flush " + path_);
  file_.reset();
}

}  // namespace punchsweep::io

namespace punchsweep::io {
namespace {

/// A numeric attribute's first value, if `object` has `name` and it is numeric.
std::optional<double> number_attribute(hid_t object, const char* name) {
  if (H5Aexists(object, name) <= 0) return std::nullopt;
  Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, std::string("open attribute ") + name);
  Handle type(H5Aget_type(attribute), H5Tclose, std::string("type of attribute ") + name);
  const H5T_class_t cls = H5Tget_class(type);
  if (cls != H5T_INTEGER && cls != H5T_FLOAT) return std::nullopt;
  Handle space(H5Aget_space(attribute), H5Sclose, std::string("space of attribute ") + name);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  if (n < 1) return std::nullopt;
  std::vector<double> values(static_cast<std::size_t>(n));
  check(H5Aread(attribute, H5T_NATIVE_DOUBLE, values.data()), std::string("read attribute ") + name);
  return values.front();
}

/// A string attribute (fixed or variable length), if `object` has `name` and it is one.
std::optional<std::string> text_attribute(hid_t object, const char* name) {
  if (H5Aexists(object, name) <= 0) return std::nullopt;
  Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, std::string("open attribute ") + name);
  Handle type(H5Aget_type(attribute), H5Tclose, std::string("type of attribute ") + name);
  if (H5Tget_class(type) != H5T_STRING) return std::nullopt;
  if (H5Tis_variable_str(type) > 0) {
    Handle memory = string_type(std::string("string type for ") + name);
    char* text = nullptr;
    check(H5Aread(attribute, memory, &text), std::string("read attribute ") + name);
    std::string out = text ? text : "";
    H5free_memory(text);
    return out;
  }
  const std::size_t size = H5Tget_size(type);
  std::string out(size, '\0');
  check(H5Aread(attribute, type, out.data()), std::string("read attribute ") + name);
  while (!out.empty() && out.back() == '\0') out.pop_back();
  return out;
}

}  // namespace

void take_axis_attributes(NetcdfHeights& heights, char axis, std::optional<double> length,
                          const std::optional<std::string>& unit, std::optional<double> periodic,
                          const std::string& path, const std::string& format) {
  const auto fail = [&](const std::string& what) { return std::runtime_error(path + ": " + what + " (" + format + ")"); };
  if (length) {
    if (!(std::isfinite(*length) && *length > 0.0)) throw fail(std::string(1, axis) + ":length is not a length > 0");
    (axis == 'x' ? heights.length_x : heights.length_y) = *length;
  }
  if (unit && !unit->empty()) {
    if (!heights.unit.empty() && heights.unit != *unit) {
      throw fail("x and y have different length units (" + heights.unit + ", " + *unit + ")");
    }
    heights.unit = *unit;
  }
  if (periodic) heights.periodic = std::min(heights.periodic < 0 ? 1 : heights.periodic, *periodic != 0.0 ? 1 : 0);
}

NetcdfHeights read_netcdf4_heights(const std::string& path, const std::string& variable) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const auto fail = [&](const std::string& what) { return std::runtime_error(path + ": " + what + " (NetCDF-4)"); };
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open " + path);
  if (H5Lexists(file, variable.c_str(), H5P_DEFAULT) <= 0) {
    throw fail("no variable '" + variable + "' (a SurfaceTopography map holds heights(x, y))");
  }
  Handle dataset(H5Dopen2(file, variable.c_str(), H5P_DEFAULT), H5Dclose, "open " + variable + " in " + path);
  Handle space(H5Dget_space(dataset), H5Sclose, "space of " + variable + " in " + path);
  if (H5Sget_simple_extent_ndims(space) != 2) throw fail("'" + variable + "' is not 2-D (x, y)");
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(space, dims, nullptr);
  NetcdfHeights out;
  out.nx = static_cast<std::size_t>(dims[0]);
  out.ny = static_cast<std::size_t>(dims[1]);
  if (out.nx * out.ny > (std::size_t{1} << 24)) throw fail("more than 4096 x 4096 pixels");
  Handle type(H5Dget_type(dataset), H5Tclose, "type of " + variable);
  if (H5Tget_class(type) != H5T_FLOAT && H5Tget_class(type) != H5T_INTEGER) throw fail("'" + variable + "' holds no numbers");
  out.values.resize(out.nx * out.ny);
  check(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.values.data()), "read " + variable + " in " + path);
  for (const char axis : {'x', 'y'}) {
    const std::string name(1, axis);
    if (H5Lexists(file, name.c_str(), H5P_DEFAULT) <= 0) continue;
    Handle v(H5Oopen(file, name.c_str(), H5P_DEFAULT), H5Oclose, "open " + name + " in " + path);
    take_axis_attributes(out, axis, number_attribute(v, "length"), text_attribute(v, "length_unit"),
                         number_attribute(v, "periodic"), path, "NetCDF-4");
  }
  return out;
}

}  // namespace punchsweep::io
