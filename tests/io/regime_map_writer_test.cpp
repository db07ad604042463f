#include "io/regime_map_reader.hpp"
#include "io/regime_map_writer.hpp"

#include <H5DSpublic.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "io/hdf5_handle.hpp"
#include "io/map_variables.hpp"
#include "io/tile_encoder.hpp"
#include "sample_tiles.hpp"
#include "scratch_dir.hpp"
#include "map/tiling.hpp"

namespace punchsweep::io {
namespace {

using namespace testing;
using testing::nan_with_payload;
using testing::ScratchDir;

// In map::kQuantities order, which is also the point command's key order.
const std::vector<std::string> kAxisVariables{"regime", "t_star", "h_0",    "h_inf",
                                              "valid",  "a1_inf", "a2_inf", "area_fraction_inf"};
const std::vector<std::string> kFullPointVariables{"dt_star_ddh", "dt_star_dpbar", "dt_star_dl"};  // full mode only
const std::vector<std::string> kSeriesVariables{"a1", "a2", "P1", "P2", "area_fraction"};
const std::vector<std::string> kCoordinates{"l", "dh", "T", "pbar", "s", "time"};
const std::vector<std::string> kFloatVariables{
    "t_star", "h_0", "h_inf", "a1_inf", "a2_inf",       "area_fraction_inf",
    "a1",     "a2",  "P1",    "P2",     "area_fraction"};

/// A reference setup as the sweep records it.
BemSetup small_bem() { return {32, 1e-10, 40, 7, "periodic BEM test method"}; }

MapLayout small_layout(map::Quantities quantities, bool bem = false) {
  MapLayout layout;
  layout.grid = sls_grid();
  layout.grid.axes[kL] = {"l", {0.5, 0.75, 1.0}, "linspace(0.5, 1, 3)", false};
  layout.grid.axes[kDh] = {"dh", {0.0, 0.01, 0.05, 0.1}, "0, 0.01, 0.05, 0.1", false};
  layout.grid.axes[kT] = {"T", {1.0, 10.0}, "logspace(0, 1, 2)", true};
  layout.grid.axes[kPbar] = {"pbar", {0.01, 0.02, 0.03, 0.04, 0.05}, "linspace(0.01, 0.05, 5)", false};
  layout.grid.axes[kS] = {"s", {1.0, 2.0}, "1, 2", false};
  layout.times = {0.0, 0.5, 2.0};
  layout.quantities = quantities;
  layout.chunk = map::Tiling(layout.grid.shape(), 7).chunk();  // (1, 1, 1, 3, 2): pbar has edge tiles
  if (bem) layout.bem = small_bem();
  return layout;
}

MapAttributes small_attributes() {
  return {"regime map test",
          "punchsweep test",
          "written by regime_map_writer_test",
          "[grid]\nl = linspace(0.5, 1, 3)\n",
          "grid.l = 0.5, 0.75, 1\nmodel.C = 0.5",
          "standard_linear_solid",
          0.5,
          "T_eps",
          {}};
}

/// Row-major flat index of a grid point.
std::size_t flat_index(const map::Index& shape,
                       const map::Index& at) {
  std::size_t g = 0;
  for (std::size_t a = 0; a < kAxes; ++a) g = g * shape[a] + at[a];
  return g;
}

/// The value every test map holds for float variable `var` at grid point g (and time t):
/// distinct per variable, point and time, with NaN payloads and -0.0 mixed in.
double cell_value(std::size_t var, std::size_t g, std::size_t t) {
  if ((g + var) % 7 == 0) return nan_with_payload(g * 16 + var);
  if ((g + t) % 13 == 5) return -0.0;
  return static_cast<double>(var) * 1000.0 + static_cast<double>(g) + 0.125 * static_cast<double>(t) +
         1.0 / 3.0;
}
std::int8_t regime_code(std::size_t g) { return static_cast<std::int8_t>(g % 3); }
std::int8_t valid_code(std::size_t g) { return static_cast<std::int8_t>(g % 4); }
/// Tiles left unwritten, so fill values can be checked.
bool skipped(std::size_t tile) { return tile % 5 == 1; }
/// Grid points in the sample map's reference sample (the others stay not computed).
bool bem_sampled(std::size_t g) { return g % 3 == 0; }
std::int8_t bem_regime_code(std::size_t g) { return static_cast<std::int8_t>((g / 3) % 3); }
/// The bem_* float variables, and the index of the first in cell_value's numbering.
const std::vector<std::string> kBemFloatVariables{"bem_t_star", "bem_a1", "bem_a2", "bem_P1", "bem_P2",
                                                  "bem_area_fraction"};
constexpr std::size_t kFirstBemVar = 20;

/// The sample map's values for every point of `box`.
map::TileData tile_for(const map::TileBox& box, const MapLayout& layout) {
  const auto shape = layout.grid.shape();
  const std::size_t times = layout.times.size();
  const bool full = layout.quantities == map::Quantities::full;
  const bool bem = layout.bem.has_value();
  map::TileData data;
  data.resize(box.points(), times, full ? map::Quantities::full : map::Quantities::regime, bem);
  std::size_t i = 0;
  map::Index at(kAxes);
  for (at[0] = box.start[0]; at[0] < box.start[0] + box.count[0]; ++at[0])
    for (at[1] = box.start[1]; at[1] < box.start[1] + box.count[1]; ++at[1])
      for (at[2] = box.start[2]; at[2] < box.start[2] + box.count[2]; ++at[2])
        for (at[3] = box.start[3]; at[3] < box.start[3] + box.count[3]; ++at[3])
          for (at[4] = box.start[4]; at[4] < box.start[4] + box.count[4]; ++at[4], ++i) {
            const std::size_t g = flat_index(shape, at);
            flag(data, "regime")[i] = regime_code(g);
            flag(data, "valid")[i] = valid_code(g);
            std::size_t var = 0;
            for (auto* v : {&real(data, "t_star"), &real(data, "h_0"), &real(data, "h_inf"), &real(data, "a1_inf"), &real(data, "a2_inf"),
                            &real(data, "area_fraction_inf")}) {
              (*v)[i] = cell_value(var++, g, 0);
            }
            if (bem && bem_sampled(g)) {
              flag(data, "bem_regime")[i] = bem_regime_code(g);
              real(data, "bem_t_star")[i] = cell_value(kFirstBemVar, g, 0);
              std::size_t bem_var = kFirstBemVar + 1;
              for (auto* v : {&real(data, "bem_a1"), &real(data, "bem_a2"), &real(data, "bem_P1"), &real(data, "bem_P2"), &real(data, "bem_area_fraction")}) {
                for (std::size_t t = 0; t < times; ++t) (*v)[i * times + t] = cell_value(bem_var, g, t);
                ++bem_var;
              }
            }
            if (!full) continue;
            for (auto* v : {&real(data, "a1"), &real(data, "a2"), &real(data, "P1"), &real(data, "P2"), &real(data, "area_fraction")}) {
              for (std::size_t t = 0; t < times; ++t) (*v)[i * times + t] = cell_value(var, g, t);
              ++var;
            }
          }
  return data;
}

/// Marks the points of `box` in `written` (row-major over the grid).
void mark(const map::TileBox& box, const map::Index& shape,
          std::vector<bool>* written) {
  map::Index at(kAxes);
  for (at[0] = box.start[0]; at[0] < box.start[0] + box.count[0]; ++at[0])
    for (at[1] = box.start[1]; at[1] < box.start[1] + box.count[1]; ++at[1])
      for (at[2] = box.start[2]; at[2] < box.start[2] + box.count[2]; ++at[2])
        for (at[3] = box.start[3]; at[3] < box.start[3] + box.count[3]; ++at[3])
          for (at[4] = box.start[4]; at[4] < box.start[4] + box.count[4]; ++at[4])
            (*written)[flat_index(shape, at)] = true;
}

/// Writes the sample map tile by tile (one chunk each), skipping some tiles; returns which
/// grid points were written.
std::vector<bool> write_sample_map(RegimeMapWriter* writer, const MapLayout& layout) {
  const map::Tiling tiling(layout.grid.shape(), 7);
  std::vector<bool> written(layout.grid.points(), false);
  for (std::size_t tile = 0; tile < tiling.tiles(); ++tile) {
    if (skipped(tile)) continue;
    const map::TileBox box = tiling.box(tile);
    writer->write_tile(box, tile_for(box, layout));
    mark(box, layout.grid.shape(), &written);
  }
  return written;
}

Handle open_file(const std::string& path) {
  return Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "open " + path);
}
Handle open_dataset(hid_t file, const std::string& name) {
  return Handle(H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + name);
}

std::string read_string_attribute(hid_t object, const char* name) {
  const Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, std::string("open attribute ") + name);
  const Handle type(H5Aget_type(attribute), H5Tclose, "get type");
  EXPECT_GT(H5Tis_variable_str(type), 0) << name << " is not a variable-length string";
  EXPECT_EQ(H5Tget_cset(type), H5T_CSET_UTF8) << name;
  char* text = nullptr;
  check(H5Aread(attribute, type, &text), std::string("read ") + name);
  std::string value(text);
  H5free_memory(text);
  return value;
}

template <typename T>
std::vector<T> read_attribute(hid_t object, const char* name, hid_t memory_type) {
  const Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, std::string("open attribute ") + name);
  const Handle space(H5Aget_space(attribute), H5Sclose, "get space");
  std::vector<T> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  check(H5Aread(attribute, memory_type, values.data()), std::string("read ") + name);
  return values;
}

bool attribute_type_is(hid_t object, const char* name, hid_t file_type) {
  const Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, std::string("open attribute ") + name);
  const Handle type(H5Aget_type(attribute), H5Tclose, "get type");
  return H5Tequal(type, file_type) > 0;
}

template <typename T>
std::vector<T> read_dataset(hid_t dataset, hid_t memory_type) {
  const Handle space(H5Dget_space(dataset), H5Sclose, "get space");
  std::vector<T> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  check(H5Dread(dataset, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "read dataset");
  return values;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// A float variable's `_FillValue` attribute (one float64) and HDF5 fill value are NaN.
void expect_nan_fill(hid_t file, const std::string& name) {
  SCOPED_TRACE(name);
  const Handle dataset = open_dataset(file, name);
  ASSERT_GT(H5Aexists(dataset, "_FillValue"), 0);
  EXPECT_TRUE(attribute_type_is(dataset, "_FillValue", H5T_IEEE_F64LE));
  const std::vector<double> fill = read_attribute<double>(dataset, "_FillValue", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(fill.size(), 1U);
  EXPECT_TRUE(std::isnan(fill[0]));
  const Handle dcpl(H5Dget_create_plist(dataset), H5Pclose, "get dcpl");
  double hdf5_fill = 0.0;
  ASSERT_GE(H5Pget_fill_value(dcpl, H5T_NATIVE_DOUBLE, &hdf5_fill), 0);
  EXPECT_TRUE(std::isnan(hdf5_fill));
}

class RegimeMapWriterTest : public ::testing::Test {
 protected:
  /// Writes the sample map at `path_` and finishes it (unless `finish` is false).
  void make_map(map::Quantities quantities, bool finish = true, bool bem = false) {
    layout_ = small_layout(quantities, bem);
    RegimeMapWriter writer(path_, layout_, small_attributes());
    written_ = write_sample_map(&writer, layout_);
    writer.flush();
    if (finish) writer.finish(4, 12.5, 1234.5);
  }

  ScratchDir dir_;
  std::string path_ = dir_.file("map.h5");
  MapLayout layout_;
  std::vector<bool> written_;
};

// Every real is a pure number (units "1", which UDUNITS reads; "R" would be the roentgen)
// with its scale in scaled_by; "" here means no scaled_by (dimensionless) or, for flags, no
// units at all.
void expect_scale(hid_t object, const std::string& scale, const std::string& what) {
  EXPECT_EQ(read_string_attribute(object, "units"), "1") << what;
  if (scale.empty()) {
    EXPECT_EQ(H5Aexists(object, "scaled_by"), 0) << what;
  } else {
    EXPECT_EQ(read_string_attribute(object, "scaled_by"), scale) << what;
  }
}

TEST_F(RegimeMapWriterTest, map_has_dimension_scales_and_units) {
  make_map(map::Quantities::full);
  const Handle file = open_file(path_);
  std::vector<Handle> coordinates;
  const std::vector<std::string> scales{"R", "R", "", "E0/(1-nu^2)", "", "T_eps"};
  const std::vector<std::string> long_names{"lattice pitch",
                                            "height difference of the punch levels",
                                            "creep ratio T_eps/T_sigma",
                                            "nominal pressure",
                                            "shape exponent",
                                            "snapshot time"};
  for (std::size_t c = 0; c < kCoordinates.size(); ++c) {
    coordinates.push_back(open_dataset(file, kCoordinates[c]));
    EXPECT_GT(H5DSis_scale(coordinates.back()), 0) << kCoordinates[c];
    char name[16] = {};
    ASSERT_GT(H5DSget_scale_name(coordinates.back(), name, sizeof name), 0);
    EXPECT_EQ(std::string(name), kCoordinates[c]);
    expect_scale(coordinates.back(), scales[c], kCoordinates[c]);
    EXPECT_EQ(read_string_attribute(coordinates.back(), "long_name"), long_names[c]);
  }
  const std::vector<std::string> variable_scales{
      "-", "T_eps", "R", "R", "-", "R", "R", "", "R", "R", "R^2 E0/(1-nu^2)", "R^2 E0/(1-nu^2)", ""};  // -: a flag
  std::vector<std::string> variables = kAxisVariables;
  variables.insert(variables.end(), kSeriesVariables.begin(), kSeriesVariables.end());
  for (std::size_t v = 0; v < variables.size(); ++v) {
    const Handle dataset = open_dataset(file, variables[v]);
    const Handle space(H5Dget_space(dataset), H5Sclose, "get space");
    const int rank = H5Sget_simple_extent_ndims(space);
    EXPECT_EQ(rank, v < kAxisVariables.size() ? 5 : 6) << variables[v];
    for (int d = 0; d < rank; ++d) {
      EXPECT_EQ(H5DSget_num_scales(dataset, static_cast<unsigned>(d)), 1) << variables[v] << " dim " << d;
      EXPECT_GT(H5DSis_attached(dataset, coordinates[static_cast<std::size_t>(d)], static_cast<unsigned>(d)),
                0)
          << variables[v] << " is not attached to " << kCoordinates[static_cast<std::size_t>(d)];
    }
    EXPECT_FALSE(read_string_attribute(dataset, "long_name").empty()) << variables[v];
    if (variable_scales[v] == "-") {
      EXPECT_EQ(H5Aexists(dataset, "units"), 0) << variables[v];
    } else {
      expect_scale(dataset, variable_scales[v], variables[v]);
    }
  }
  const Handle t_star = open_dataset(file, "t_star");
  EXPECT_NE(read_string_attribute(t_star, "comment").find("NaN for never"), std::string::npos);
}

TEST_F(RegimeMapWriterTest, map_coordinates_hold_the_axis_values_and_their_spacing) {
  make_map(map::Quantities::regime);
  const Handle file = open_file(path_);
  const std::vector<std::string> spacing{"linear", "list", "log", "linear", "linear"};
  for (std::size_t a = 0; a < kAxes; ++a) {
    const Handle coordinate = open_dataset(file, kCoordinates[a]);
    const Handle type(H5Dget_type(coordinate), H5Tclose, "get type");
    EXPECT_GT(H5Tequal(type, H5T_IEEE_F64LE), 0) << kCoordinates[a];
    EXPECT_EQ(read_dataset<double>(coordinate, H5T_NATIVE_DOUBLE), layout_.grid.axes[a].values);
    EXPECT_EQ(read_string_attribute(coordinate, "axis_spec"), layout_.grid.axes[a].text);
    EXPECT_EQ(read_string_attribute(coordinate, "spacing"), spacing[a]) << kCoordinates[a];
  }
  EXPECT_EQ(read_dataset<double>(open_dataset(file, "time"), H5T_NATIVE_DOUBLE), layout_.times);
}

TEST_F(RegimeMapWriterTest, flag_variables_carry_flag_values_and_meanings) {
  make_map(map::Quantities::regime);
  const Handle file = open_file(path_);
  const Handle regime = open_dataset(file, "regime");
  EXPECT_TRUE(attribute_type_is(regime, "flag_values", H5T_STD_I8LE));
  EXPECT_EQ(read_attribute<std::int8_t>(regime, "flag_values", H5T_NATIVE_INT8),
            (std::vector<std::int8_t>{0, 1, 2, -1}));
  EXPECT_EQ(read_string_attribute(regime, "flag_meanings"), "immediate delayed never not_computed");
  const Handle valid = open_dataset(file, "valid");
  EXPECT_TRUE(attribute_type_is(valid, "flag_values", H5T_STD_I8LE));
  EXPECT_EQ(read_attribute<std::int8_t>(valid, "flag_values", H5T_NATIVE_INT8),
            (std::vector<std::int8_t>{0, 1, 2, 3, 4, 5, 6, -1}));
  EXPECT_EQ(read_string_attribute(valid, "flag_meanings"),
            "valid same_level_overlap cross_level_overlap no_solution inaccurate outside_table unloading "
            "not_computed");
  for (const hid_t dataset : {regime.get(), valid.get()}) {
    const Handle type(H5Dget_type(dataset), H5Tclose, "get type");
    EXPECT_GT(H5Tequal(type, H5T_STD_I8LE), 0);
  }
}

TEST_F(RegimeMapWriterTest, float_variables_have_a_nan_fill_value_and_flag_variables_have_none) {
  make_map(map::Quantities::full);
  const Handle file = open_file(path_);
  for (const std::string& name : kFloatVariables) expect_nan_fill(file, name);
  for (const char* name : {"regime", "valid"}) {
    const Handle dataset = open_dataset(file, name);
    EXPECT_EQ(H5Aexists(dataset, "_FillValue"), 0) << name;
    const Handle dcpl(H5Dget_create_plist(dataset), H5Pclose, "get dcpl");
    std::int8_t hdf5_fill = 0;
    ASSERT_GE(H5Pget_fill_value(dcpl, H5T_NATIVE_INT8, &hdf5_fill), 0);
    EXPECT_EQ(hdf5_fill, -1) << name;
  }
}

TEST_F(RegimeMapWriterTest, unwritten_cells_read_as_not_computed) {
  make_map(map::Quantities::full);
  const Handle file = open_file(path_);
  const std::size_t unwritten = static_cast<std::size_t>(std::count(written_.begin(), written_.end(), false));
  ASSERT_GT(unwritten, 0U);
  ASSERT_LT(unwritten, written_.size());
  for (const char* name : {"regime", "valid"}) {
    const std::vector<std::int8_t> codes =
        read_dataset<std::int8_t>(open_dataset(file, name), H5T_NATIVE_INT8);
    for (std::size_t g = 0; g < codes.size(); ++g) {
      if (!written_[g]) {
        ASSERT_EQ(codes[g], -1) << name << " at " << g;
      }
    }
  }
  const std::size_t times = layout_.times.size();
  for (const std::string& name : kFloatVariables) {
    const std::vector<double> values = read_dataset<double>(open_dataset(file, name), H5T_NATIVE_DOUBLE);
    const std::size_t per_point = values.size() / written_.size();
    ASSERT_EQ(
        per_point,
        name.find("_inf") != std::string::npos || name == "t_star" || name.rfind("h_", 0) == 0 ? 1U : times);
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!written_[i / per_point]) {
        ASSERT_TRUE(std::isnan(values[i])) << name << " at " << i;
      }
    }
  }
}

/// Checks that every point marked in `written` holds the sample map's values, bit for bit.
void expect_sample_values(const std::string& path, const MapLayout& layout,
                          const std::vector<bool>& written) {
  const Handle file = open_file(path);
  const std::vector<std::int8_t> regime =
      read_dataset<std::int8_t>(open_dataset(file, "regime"), H5T_NATIVE_INT8);
  const std::vector<std::int8_t> valid =
      read_dataset<std::int8_t>(open_dataset(file, "valid"), H5T_NATIVE_INT8);
  std::size_t checked = 0;
  for (std::size_t g = 0; g < written.size(); ++g) {
    if (!written[g]) continue;
    ASSERT_EQ(regime[g], regime_code(g)) << g;
    ASSERT_EQ(valid[g], valid_code(g)) << g;
    ++checked;
  }
  EXPECT_GT(checked, 0U);
  const std::size_t times = layout.times.size();
  const std::size_t variables = layout.quantities == map::Quantities::full ? kFloatVariables.size() : 6;
  for (std::size_t var = 0; var < variables; ++var) {
    const std::vector<double> values =
        read_dataset<double>(open_dataset(file, kFloatVariables[var]), H5T_NATIVE_DOUBLE);
    const bool series = var >= 6;
    for (std::size_t g = 0; g < written.size(); ++g) {
      if (!written[g]) continue;
      for (std::size_t t = 0; t < (series ? times : 1); ++t) {
        const double got = values[series ? g * times + t : g];
        ASSERT_TRUE(same_bits(got, cell_value(var, g, t)))
            << kFloatVariables[var] << " at " << g << ", " << t;
      }
    }
  }
}

TEST_F(RegimeMapWriterTest, written_tiles_read_back_bit_exactly) {
  make_map(map::Quantities::full);
  expect_sample_values(path_, layout_, written_);
}

TEST_F(RegimeMapWriterTest, tiles_that_are_not_one_chunk_read_back_bit_exactly) {
  layout_ = small_layout(map::Quantities::full);  // chunk (1, 1, 1, 3, 2)
  const auto shape = layout_.grid.shape();
  std::vector<bool> written(layout_.grid.points(), false);
  {
    RegimeMapWriter writer(path_, layout_, small_attributes());
    // One whole chunk first, then boxes that straddle chunks (one of them overlapping it),
    // then a whole chunk over one that the pipeline left half written in its cache: encoded
    // chunks and the filter pipeline meet in the same chunks in both orders.
    std::vector<map::TileBox> boxes(5);
    boxes[0].start = {0, 0, 0, 0, 0};
    boxes[0].count = {1, 1, 1, 3, 2};
    boxes[1].start = {0, 0, 0, 2, 0};
    boxes[1].count = {2, 2, 2, 3, 1};
    boxes[2].start = {1, 2, 0, 1, 0};
    boxes[2].count = {2, 2, 2, 4, 2};
    boxes[3].start = {0, 3, 1, 0, 1};
    boxes[3].count = {3, 1, 1, 5, 1};
    boxes[4].start = {1, 2, 0, 0, 0};  // boxes[2] wrote only pbar 1, 2 of this chunk
    boxes[4].count = {1, 1, 1, 3, 2};
    for (const map::TileBox& box : boxes) {
      writer.write_tile(box, tile_for(box, layout_));
      mark(box, shape, &written);
    }
    writer.finish(1, 1.0, 1.0);
  }
  expect_sample_values(path_, layout_, written);
  const Handle file = open_file(path_);
  const std::vector<std::int8_t> regime =
      read_dataset<std::int8_t>(open_dataset(file, "regime"), H5T_NATIVE_INT8);
  for (std::size_t g = 0; g < written.size(); ++g) {
    if (!written[g]) {
      ASSERT_EQ(regime[g], -1) << g;
    }
  }
}

TEST_F(RegimeMapWriterTest, edge_tiles_spanning_several_rows_read_back_bit_exactly) {
  layout_ = small_layout(map::Quantities::full);
  layout_.chunk = {2, 3, 2, 3, 2};  // edges on l, dh and pbar, with whole rows around them
  const auto shape = layout_.grid.shape();
  std::vector<bool> written(layout_.grid.points(), false);
  {
    RegimeMapWriter writer(path_, layout_, small_attributes());
    map::TileBox box{map::Index(kAxes), map::Index(kAxes)};
    for (box.start[0] = 0; box.start[0] < shape[0]; box.start[0] += layout_.chunk[0])
      for (box.start[1] = 0; box.start[1] < shape[1]; box.start[1] += layout_.chunk[1])
        for (box.start[2] = 0; box.start[2] < shape[2]; box.start[2] += layout_.chunk[2])
          for (box.start[3] = 0; box.start[3] < shape[3]; box.start[3] += layout_.chunk[3]) {
            for (std::size_t a = 0; a < kAxes; ++a) {
              box.count[a] = std::min(layout_.chunk[a], shape[a] - box.start[a]);
            }
            if (box.start[0] == 0 && box.start[1] == 0 && box.start[3] == 0) continue;  // stays unwritten
            writer.write_tile(box, tile_for(box, layout_));
            mark(box, shape, &written);
          }
    writer.finish(1, 1.0, 1.0);
  }
  expect_sample_values(path_, layout_, written);
  const Handle file = open_file(path_);
  const std::vector<double> a2 = read_dataset<double>(open_dataset(file, "a2"), H5T_NATIVE_DOUBLE);
  for (std::size_t i = 0; i < a2.size(); ++i) {
    if (!written[i / layout_.times.size()]) {
      ASSERT_TRUE(std::isnan(a2[i])) << i;
    }
  }
}

TEST_F(RegimeMapWriterTest, finished_map_records_its_run_and_completion) {
  make_map(map::Quantities::regime);
  const Handle file = open_file(path_);
  EXPECT_EQ(read_string_attribute(file, "Conventions"), "CF-1.8");
  const MapAttributes expected = small_attributes();
  EXPECT_EQ(read_string_attribute(file, "title"), expected.title);
  EXPECT_EQ(read_string_attribute(file, "source"), expected.source);
  EXPECT_EQ(read_string_attribute(file, "history"), expected.history);
  EXPECT_EQ(read_string_attribute(file, "config"), expected.config_text);
  EXPECT_EQ(read_string_attribute(file, "creep_law"), expected.creep_law);
  EXPECT_EQ(read_string_attribute(file, "identity"), expected.identity);
  EXPECT_EQ(read_map_identity(path_), expected.identity);
  EXPECT_TRUE(attribute_type_is(file, "C", H5T_IEEE_F64LE));
  EXPECT_EQ(read_attribute<double>(file, "C", H5T_NATIVE_DOUBLE), std::vector<double>{0.5});
  EXPECT_TRUE(attribute_type_is(file, "ranks", H5T_STD_I32LE));
  EXPECT_EQ(read_attribute<std::int32_t>(file, "ranks", H5T_NATIVE_INT32), std::vector<std::int32_t>{4});
  EXPECT_EQ(read_attribute<double>(file, "wall_seconds", H5T_NATIVE_DOUBLE), std::vector<double>{12.5});
  EXPECT_EQ(read_attribute<double>(file, "points_per_second", H5T_NATIVE_DOUBLE),
            std::vector<double>{1234.5});
  EXPECT_TRUE(attribute_type_is(file, "completed", H5T_STD_I8LE));
  EXPECT_EQ(read_attribute<std::int8_t>(file, "completed", H5T_NATIVE_INT8), std::vector<std::int8_t>{1});
}

TEST_F(RegimeMapWriterTest, unfinished_map_is_marked_incomplete) {
  make_map(map::Quantities::regime, /*finish=*/false);
  const Handle file = open_file(path_);
  EXPECT_EQ(read_attribute<std::int8_t>(file, "completed", H5T_NATIVE_INT8), std::vector<std::int8_t>{0});
  EXPECT_EQ(H5Aexists(file, "ranks"), 0);
  const std::vector<std::int8_t> regime =
      read_dataset<std::int8_t>(open_dataset(file, "regime"), H5T_NATIVE_INT8);
  for (std::size_t g = 0; g < written_.size(); ++g) {
    ASSERT_EQ(regime[g], written_[g] ? regime_code(g) : -1) << g;
  }
}

herr_t collect_link(hid_t, const char* name, const H5L_info_t*, void* names) {
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}
herr_t collect_attribute(hid_t, const char* name, const H5A_info_t*, void* names) {
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}

TEST_F(RegimeMapWriterTest, map_tracks_creation_order_of_links_and_attributes) {
  make_map(map::Quantities::full);
  const Handle file = open_file(path_);
  // Asked of the root group as netCDF-C asks it (HDF5 1.10's H5Fget_create_plist does not
  // report the root group's creation-order flags).
  const Handle root(H5Gopen2(file, "/", H5P_DEFAULT), H5Gclose, "open root group");
  const Handle gcpl(H5Gget_create_plist(root), H5Pclose, "get root group creation properties");
  unsigned links = 0;
  unsigned attributes = 0;
  ASSERT_GE(H5Pget_link_creation_order(gcpl, &links), 0);
  ASSERT_GE(H5Pget_attr_creation_order(gcpl, &attributes), 0);
  EXPECT_EQ(links, unsigned{H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED});
  EXPECT_EQ(attributes, unsigned{H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED});

  std::vector<std::string> names;
  ASSERT_GE(H5Literate(file, H5_INDEX_CRT_ORDER, H5_ITER_INC, nullptr, collect_link, &names), 0);
  std::vector<std::string> expected = kCoordinates;
  expected.insert(expected.end(), kAxisVariables.begin(), kAxisVariables.end());
  expected.insert(expected.end(), kFullPointVariables.begin(), kFullPointVariables.end());
  expected.insert(expected.end(), kSeriesVariables.begin(), kSeriesVariables.end());
  EXPECT_EQ(names, expected);

  names.clear();
  ASSERT_GE(H5Aiterate2(file, H5_INDEX_CRT_ORDER, H5_ITER_INC, nullptr, collect_attribute, &names), 0);
  EXPECT_EQ(names,
            (std::vector<std::string>{"Conventions", "title", "source", "history", "config", "identity", "layout_version", "creep_law", "C", "localization", "time_unit", "scales",
                                      "completed", "ranks", "wall_seconds", "points_per_second"}));

  const Handle regime = open_dataset(file, "regime");
  const Handle dcpl(H5Dget_create_plist(regime), H5Pclose, "get dcpl");
  ASSERT_GE(H5Pget_attr_creation_order(dcpl, &attributes), 0);
  EXPECT_EQ(attributes, unsigned{H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED});
}

TEST_F(RegimeMapWriterTest, every_variable_is_chunked_and_compressed) {
  make_map(map::Quantities::full);
  const Handle file = open_file(path_);
  std::vector<std::string> variables = kAxisVariables;
  variables.insert(variables.end(), kSeriesVariables.begin(), kSeriesVariables.end());
  for (const std::string& name : variables) {
    const Handle dataset = open_dataset(file, name);
    const Handle dcpl(H5Dget_create_plist(dataset), H5Pclose, "get dcpl");
    ASSERT_EQ(H5Pget_layout(dcpl), H5D_CHUNKED) << name;
    std::array<hsize_t, 6> chunk{};
    const int rank = H5Pget_chunk(dcpl, 6, chunk.data());
    for (std::size_t a = 0; a < kAxes; ++a)
      EXPECT_EQ(chunk[a], layout_.chunk[a]) << name << " axis " << a;
    if (rank == 6) {
      EXPECT_EQ(chunk[5], layout_.times.size()) << name;
    }
    ASSERT_EQ(H5Pget_nfilters(dcpl), 2) << name;
    unsigned flags = 0;
    std::size_t n = 1;
    unsigned level = 0;
    EXPECT_EQ(H5Pget_filter2(dcpl, 0, &flags, &n, &level, 0, nullptr, nullptr), H5Z_FILTER_SHUFFLE) << name;
    n = 1;
    EXPECT_EQ(H5Pget_filter2(dcpl, 1, &flags, &n, &level, 0, nullptr, nullptr), H5Z_FILTER_DEFLATE) << name;
    EXPECT_GE(level, 1U);
    EXPECT_LE(level, 2U);
  }
}

TEST_F(RegimeMapWriterTest, regime_only_map_has_no_time_series) {
  make_map(map::Quantities::regime);
  const Handle file = open_file(path_);
  for (const std::string& name : kSeriesVariables)
    EXPECT_EQ(H5Lexists(file, name.c_str(), H5P_DEFAULT), 0) << name;
  for (const std::string& name : kAxisVariables)
    EXPECT_GT(H5Lexists(file, name.c_str(), H5P_DEFAULT), 0) << name;
  EXPECT_GT(H5Lexists(file, "time", H5P_DEFAULT), 0);
}

TEST_F(RegimeMapWriterTest, writer_rejects_bad_layouts) {
  MapLayout layout = small_layout(map::Quantities::full);
  layout.chunk[kPbar] = 6;  // longer than the axis
  EXPECT_THROW(RegimeMapWriter(path_, layout, small_attributes()), std::invalid_argument);
  layout = small_layout(map::Quantities::full);
  layout.chunk[kL] = 0;
  EXPECT_THROW(RegimeMapWriter(path_, layout, small_attributes()), std::invalid_argument);
  layout = small_layout(map::Quantities::full);
  layout.times.clear();
  EXPECT_THROW(RegimeMapWriter(path_, layout, small_attributes()), std::invalid_argument);
  layout = small_layout(map::Quantities::full);
  layout.grid.axes[kS].values.clear();
  EXPECT_THROW(RegimeMapWriter(path_, layout, small_attributes()), std::invalid_argument);
}

TEST_F(RegimeMapWriterTest, writer_rejects_tiles_that_do_not_fit) {
  const MapLayout layout = small_layout(map::Quantities::full);
  RegimeMapWriter writer(path_, layout, small_attributes());
  map::TileBox box{map::Index(kAxes), map::Index(kAxes)};
  box.start = {2, 3, 1, 3, 0};
  box.count = {1, 1, 1, 2, 2};
  map::TileData data;
  data.resize(box.points(), layout.times.size(), map::Quantities::full, false);
  EXPECT_NO_THROW(writer.write_tile(box, data));
  box.count[kPbar] = 3;  // runs past the last pbar
  EXPECT_THROW(writer.write_tile(box, data), std::invalid_argument);
  box.count[kPbar] = 2;
  real(data, "P1").pop_back();
  EXPECT_THROW(writer.write_tile(box, data), std::invalid_argument);
  data.resize(box.points(), layout.times.size(), map::Quantities::regime, false);  // series missing from a full map
  EXPECT_THROW(writer.write_tile(box, data), std::invalid_argument);
  data.resize(box.points(), layout.times.size(), map::Quantities::full, true);  // bem_* arrays in a map without them
  EXPECT_THROW(writer.write_tile(box, data), std::invalid_argument);
  writer.finish(1, 0.0, 0.0);
  data.resize(box.points(), layout.times.size(), map::Quantities::full, false);
  EXPECT_THROW(writer.write_tile(box, data), std::logic_error);
  EXPECT_THROW(writer.finish(1, 0.0, 0.0), std::logic_error);
}

TEST_F(RegimeMapWriterTest, writer_error_names_the_file) {
  const std::string path = dir_.file("no/such/dir/map.h5");
  try {
    RegimeMapWriter writer(path, small_layout(map::Quantities::regime), small_attributes());
    FAIL() << "created a map in a missing directory";
  } catch (const Hdf5Error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST_F(RegimeMapWriterTest, map_stores_a_configuration_text_larger_than_64_kib) {
  MapAttributes attributes = small_attributes();
  for (int i = 0; attributes.config_text.size() < 200000; ++i) {
    attributes.config_text += "# line " + std::to_string(i) + ": a comment naming where the key came from\n";
  }
  {
    RegimeMapWriter writer(path_, small_layout(map::Quantities::regime), attributes);
    writer.finish(1, 1.0, 1.0);
  }
  const Handle file = open_file(path_);
  EXPECT_EQ(read_string_attribute(file, "config"), attributes.config_text);
}

/// Every chunk of every variable of the map at `path`, as stored (still encoded), in
/// variable order and then chunk order; an unwritten chunk is an empty entry.
std::vector<std::vector<std::byte>> stored_chunks(const std::string& path, const MapLayout& layout) {
  const Handle file = open_file(path);
  std::vector<std::vector<std::byte>> chunks;
  const map::Tiling tiling(layout.grid.shape(), 7);
  for (const std::size_t q : stored_variables(layout)) {
    const std::string name(map::kQuantities[q].name);
    const Handle dataset = open_dataset(file, name);
    for (std::size_t tile = 0; tile < tiling.tiles(); ++tile) {
      std::array<hsize_t, kAxes + 1> offset{};
      for (std::size_t a = 0; a < kAxes; ++a) offset[a] = tiling.box(tile).start[a];
      hsize_t size = 0;
      chunks.emplace_back();
      if (H5Dget_chunk_storage_size(dataset, offset.data(), &size) < 0 || size == 0) continue;
      chunks.back().resize(size);
      std::uint32_t filters = 0;
      check(H5Dread_chunk(dataset, H5P_DEFAULT, offset.data(), &filters, chunks.back().data()),
            "read a chunk of " + name);
    }
  }
  return chunks;
}

/// Every variable of the map at `path`, read through HDF5's filters as raw bytes.
std::vector<std::vector<std::byte>> variable_bytes(const std::string& path, const MapLayout& layout) {
  const Handle file = open_file(path);
  std::vector<std::vector<std::byte>> out;
  for (const std::size_t q : stored_variables(layout)) {
    const Handle dataset = open_dataset(file, std::string(map::kQuantities[q].name));
    if (map::kQuantities[q].kind == map::Kind::flag) {
      const auto codes = read_dataset<std::int8_t>(dataset, H5T_NATIVE_INT8);
      const auto* p = reinterpret_cast<const std::byte*>(codes.data());
      out.emplace_back(p, p + codes.size());
    } else {
      const auto values = read_dataset<double>(dataset, H5T_NATIVE_DOUBLE);
      const auto* p = reinterpret_cast<const std::byte*>(values.data());
      out.emplace_back(p, p + values.size() * sizeof(double));
    }
  }
  return out;
}

TEST_F(RegimeMapWriterTest, write_encoded_and_write_tile_store_identical_data) {
  for (const auto& [quantities, bem] : {std::pair{map::Quantities::regime, false},
                                        std::pair{map::Quantities::full, false},
                                        std::pair{map::Quantities::regime, true}}) {
    layout_ = small_layout(quantities, bem);
    const std::string by_tile = dir_.file("by_tile.h5");
    const std::string encoded = dir_.file("encoded.h5");
    std::vector<bool> written;
    {
      RegimeMapWriter writer(by_tile, layout_, small_attributes());
      written = write_sample_map(&writer, layout_);
      writer.finish(1, 1.0, 1.0);
    }
    {
      // As in the sweep: the tiles are encoded by another object than the writer, in
      // another order, and some of them twice (a tile written again after a resume).
      RegimeMapWriter writer(encoded, layout_, small_attributes());
      TileEncoder encoder(layout_);
      const map::Tiling tiling(layout_.grid.shape(), 7);
      for (std::size_t tile = tiling.tiles(); tile-- > 0;) {
        if (skipped(tile)) continue;
        const map::TileBox box = tiling.box(tile);
        const EncodedTile encoded_tile = encoder.encode(tile, box, tile_for(box, layout_));
        writer.write_encoded(box, encoded_tile);
        if (tile % 4 == 0) writer.write_encoded(box, encoded_tile);
      }
      writer.finish(1, 1.0, 1.0);
    }
    expect_sample_values(encoded, layout_, written);
    EXPECT_EQ(variable_bytes(encoded, layout_), variable_bytes(by_tile, layout_));
    const auto chunks = stored_chunks(encoded, layout_);
    EXPECT_EQ(chunks, stored_chunks(by_tile, layout_));
    EXPECT_GT(std::count_if(chunks.begin(), chunks.end(), [](const auto& c) { return c.empty(); }), 0)
        << "some chunks must stay unwritten for this test to mean anything";
  }
}

TEST_F(RegimeMapWriterTest, write_encoded_refuses_a_tile_that_does_not_fit) {
  layout_ = small_layout(map::Quantities::full);  // chunk (1, 1, 1, 3, 2)
  RegimeMapWriter writer(path_, layout_, small_attributes());
  TileEncoder full(layout_);
  TileEncoder regime_only(small_layout(map::Quantities::regime));
  map::TileBox box{map::Index(kAxes), map::Index(kAxes)};
  box.start = {0, 0, 0, 3, 0};
  box.count = {1, 1, 1, 2, 2};  // the edge of pbar
  const EncodedTile tile = full.encode(7, box, tile_for(box, layout_));
  EXPECT_NO_THROW(writer.write_encoded(box, tile));
  map::TileBox other = box;
  other.count[kPbar] = 1;  // not the whole part of the chunk inside the grid
  EXPECT_THROW(writer.write_encoded(other, tile), std::invalid_argument);
  other = box;
  other.start[kL] = 3;  // outside the grid
  EXPECT_THROW(writer.write_encoded(other, tile), std::invalid_argument);
  other = box;
  other.start[kPbar] = 0;
  other.count[kPbar] = 3;  // a whole chunk: more points than the tile has
  EXPECT_THROW(writer.write_encoded(other, tile), std::invalid_argument);
  // A tile encoded for a regime-only map lacks the series chunks.
  EXPECT_THROW(writer.write_encoded(
                   box, regime_only.encode(7, box, tile_for(box, small_layout(map::Quantities::regime)))),
               std::invalid_argument);
  writer.finish(1, 0.0, 0.0);
  EXPECT_THROW(writer.write_encoded(box, tile), std::logic_error);
}


const std::vector<std::string> kBemVariables{"bem_regime", "bem_converged", "bem_iterations", "bem_residual",
                                             "bem_t_star", "bem_a1",        "bem_a2",         "bem_P1",
                                             "bem_P2",     "bem_area_fraction"};
const std::vector<std::string> kAnswerVariables{"answer_regime", "answer_t_star", "answer_source"};

TEST_F(RegimeMapWriterTest, bem_variables_are_stored_only_with_a_reference) {
  make_map(map::Quantities::full);
  {
    const Handle file = open_file(path_);
    for (const std::string& name : kBemVariables) EXPECT_EQ(H5Lexists(file, name.c_str(), H5P_DEFAULT), 0) << name;
    for (const char* name : {"bem_grid", "bem_tolerance", "bem_sample", "bem_seed", "bem_method", "bem_sample_rule"})
      EXPECT_EQ(H5Aexists(file, name), 0) << name;
  }
  // With the regime quantities the reference keeps its series (over the time coordinate).
  make_map(map::Quantities::regime, /*finish=*/true, /*bem=*/true);
  const Handle file = open_file(path_);
  for (const std::string& name : kBemVariables) EXPECT_GT(H5Lexists(file, name.c_str(), H5P_DEFAULT), 0) << name;
  for (const std::string& name : kSeriesVariables) EXPECT_EQ(H5Lexists(file, name.c_str(), H5P_DEFAULT), 0) << name;
  std::vector<std::string> names;
  ASSERT_GE(H5Literate(file, H5_INDEX_CRT_ORDER, H5_ITER_INC, nullptr, collect_link, &names), 0);
  std::vector<std::string> expected = kCoordinates;
  expected.insert(expected.end(), kAxisVariables.begin(), kAxisVariables.end());
  expected.insert(expected.end(), kBemVariables.begin(), kBemVariables.end());
  expected.insert(expected.end(), kAnswerVariables.begin(), kAnswerVariables.end());
  EXPECT_EQ(names, expected);
}

TEST_F(RegimeMapWriterTest, bem_variables_carry_units_flags_dimensions_and_fill_values) {
  make_map(map::Quantities::full, /*finish=*/true, /*bem=*/true);
  const Handle file = open_file(path_);
  std::vector<Handle> coordinates;
  for (const std::string& name : kCoordinates) coordinates.push_back(open_dataset(file, name));
  const std::vector<std::string> units{"", "", "1", "1", "T_eps", "R", "R", "R^2 E0/(1-nu^2)", "R^2 E0/(1-nu^2)", "1"};
  for (std::size_t v = 0; v < kBemVariables.size(); ++v) {
    const std::string& name = kBemVariables[v];
    const Handle dataset = open_dataset(file, name);
    const Handle space(H5Dget_space(dataset), H5Sclose, "get space");
    const int rank = H5Sget_simple_extent_ndims(space);
    EXPECT_EQ(rank, v < 5 ? 5 : 6) << name;  // the per-point ones, then the series
    for (int d = 0; d < rank; ++d) {
      EXPECT_GT(H5DSis_attached(dataset, coordinates[static_cast<std::size_t>(d)], static_cast<unsigned>(d)), 0)
          << name << " dim " << d;
    }
    EXPECT_EQ(read_string_attribute(dataset, "long_name").rfind("periodic BEM reference: ", 0), 0U) << name;
    EXPECT_NE(read_string_attribute(dataset, "comment").find("outside the reference sample"), std::string::npos)
        << name;
    if (units[v].empty()) {
      EXPECT_EQ(H5Aexists(dataset, "units"), 0) << name;
    } else {
      expect_scale(dataset, units[v] == "1" ? "" : units[v], name);
    }
  }
  const Handle regime = open_dataset(file, "bem_regime");
  const Handle type(H5Dget_type(regime), H5Tclose, "get type");
  EXPECT_GT(H5Tequal(type, H5T_STD_I8LE), 0);
  EXPECT_EQ(read_attribute<std::int8_t>(regime, "flag_values", H5T_NATIVE_INT8),
            (std::vector<std::int8_t>{0, 1, 2, -1}));
  EXPECT_EQ(read_string_attribute(regime, "flag_meanings"), "immediate delayed never not_computed");
  const Handle converged = open_dataset(file, "bem_converged");
  EXPECT_EQ(read_attribute<std::int8_t>(converged, "flag_values", H5T_NATIVE_INT8), (std::vector<std::int8_t>{0, 1, -1}));
  EXPECT_EQ(read_string_attribute(converged, "flag_meanings"), "not_converged converged not_computed");
  const Handle source = open_dataset(file, "answer_source");
  EXPECT_EQ(read_attribute<std::int8_t>(source, "flag_values", H5T_NATIVE_INT8), (std::vector<std::int8_t>{0, 1, 2, -1}));
  EXPECT_EQ(read_string_attribute(source, "flag_meanings"), "model bem none not_computed");
  EXPECT_EQ(H5Aexists(regime, "_FillValue"), 0);
  const Handle regime_dcpl(H5Dget_create_plist(regime), H5Pclose, "get dcpl");
  std::int8_t code_fill = 0;
  ASSERT_GE(H5Pget_fill_value(regime_dcpl, H5T_NATIVE_INT8, &code_fill), 0);
  EXPECT_EQ(code_fill, -1);
  EXPECT_NE(read_string_attribute(open_dataset(file, "bem_t_star"), "comment")
                .find("NaN for never, for delayed beyond the last snapshot time"),
            std::string::npos);
  for (const std::string& name : kBemFloatVariables) expect_nan_fill(file, name);
}

TEST_F(RegimeMapWriterTest, map_with_a_reference_records_its_grid_tolerance_sample_and_seed) {
  make_map(map::Quantities::regime, /*finish=*/true, /*bem=*/true);
  const Handle file = open_file(path_);
  const BemSetup bem = small_bem();
  EXPECT_TRUE(attribute_type_is(file, "bem_grid", H5T_STD_I32LE));
  EXPECT_EQ(read_attribute<std::int32_t>(file, "bem_grid", H5T_NATIVE_INT32), std::vector<std::int32_t>{bem.grid});
  EXPECT_TRUE(attribute_type_is(file, "bem_tolerance", H5T_IEEE_F64LE));
  EXPECT_EQ(read_attribute<double>(file, "bem_tolerance", H5T_NATIVE_DOUBLE), std::vector<double>{bem.tolerance});
  EXPECT_TRUE(attribute_type_is(file, "bem_sample", H5T_STD_I64LE));
  EXPECT_EQ(read_attribute<std::int64_t>(file, "bem_sample", H5T_NATIVE_INT64),
            std::vector<std::int64_t>{bem.sample});
  EXPECT_TRUE(attribute_type_is(file, "bem_seed", H5T_STD_I64LE));
  EXPECT_EQ(read_attribute<std::int64_t>(file, "bem_seed", H5T_NATIVE_INT64), std::vector<std::int64_t>{bem.seed});
  EXPECT_EQ(read_string_attribute(file, "bem_method"), bem.method);
  EXPECT_EQ(read_string_attribute(file, "bem_sample_rule"), bem.sample_rule);
}

TEST_F(RegimeMapWriterTest, bem_values_read_back_bit_exactly_and_unsampled_cells_as_not_computed) {
  make_map(map::Quantities::regime, /*finish=*/true, /*bem=*/true);
  const Handle file = open_file(path_);
  const std::vector<std::int8_t> codes =
      read_dataset<std::int8_t>(open_dataset(file, "bem_regime"), H5T_NATIVE_INT8);
  std::size_t sampled = 0;
  for (std::size_t g = 0; g < written_.size(); ++g) {
    const bool computed = written_[g] && bem_sampled(g);
    ASSERT_EQ(codes[g], computed ? bem_regime_code(g) : -1) << g;
    sampled += computed ? 1 : 0;
  }
  EXPECT_GT(sampled, 0U);
  const std::size_t times = layout_.times.size();
  for (std::size_t v = 0; v < kBemFloatVariables.size(); ++v) {
    const std::vector<double> values =
        read_dataset<double>(open_dataset(file, kBemFloatVariables[v]), H5T_NATIVE_DOUBLE);
    const std::size_t per_point = v == 0 ? 1 : times;
    ASSERT_EQ(values.size(), written_.size() * per_point);
    for (std::size_t i = 0; i < values.size(); ++i) {
      const std::size_t g = i / per_point;
      if (written_[g] && bem_sampled(g)) {
        ASSERT_TRUE(same_bits(values[i], cell_value(kFirstBemVar + v, g, i % per_point)))
            << kBemFloatVariables[v] << " at " << i;
      } else {
        ASSERT_TRUE(std::isnan(values[i])) << kBemFloatVariables[v] << " at " << i;
      }
    }
  }
  expect_sample_values(path_, layout_, written_);  // the model's variables are untouched
}

}  // namespace
}  // namespace punchsweep::io
