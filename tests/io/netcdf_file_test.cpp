// A texture map is written a geometry at a time (NetcdfFile::declare, write_slab): the
// values read back are those written, wherever and in whatever order their slabs came, a
// slab never written reads as the fill (NaN, or the not-computed code), each slab is one
// chunk, and a slab that does not fit is refused.
#include "io/netcdf_file.hpp"

#include <hdf5.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "scratch_dir.hpp"

namespace punchsweep::io {
namespace {

using testing::ScratchDir;

template <class T>
std::vector<T> read_all(const std::string& path, const char* name, hid_t memory_type, std::vector<hsize_t>* chunk) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
  const hid_t space = H5Dget_space(dataset);
  std::vector<T> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  EXPECT_GE(H5Dread(dataset, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  const hid_t dcpl = H5Dget_create_plist(dataset);
  chunk->assign(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)), 0);
  H5Pget_chunk(dcpl, static_cast<int>(chunk->size()), chunk->data());
  H5Pclose(dcpl);
  H5Sclose(space);
  H5Dclose(dataset);
  H5Fclose(file);
  return values;
}

TEST(NetcdfFile, slabs_come_back_where_they_were_written_and_the_rest_reads_as_the_fill) {
  const ScratchDir dir;
  const std::string path = dir.file("map.nc");
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  {
    NetcdfFile file(path);
    file.coordinate("l", {1.0, 2.0, 3.0}, {});
    file.coordinate("dh", {0.1, 0.2}, {});
    file.coordinate("level", {0.0, 1.0, 2.0, 3.0}, {});
    // A geometry (l, dh) a slab of four levels.
    file.declare("t_star", {"l", "dh", "level"}, 2, false, kNaN, {{"units", "1"}});
    file.declare("regime", {"l", "dh", "level"}, 2, true, -1.0, {{"long_name", "each level's regime"}}, {0, 1, 2});
    // Out of order; (1, 0) never written.
    for (const std::size_t l : {2u, 0u, 1u}) {
      for (const std::size_t dh : {1u, 0u}) {
        if (l == 1 && dh == 0) continue;
        const double g = static_cast<double>(2 * l + dh);
        file.write_slab("t_star", {l, dh}, std::vector<double>{g, g + 0.25, g + 0.5, g + 0.75});
        file.write_slab("regime", {l, dh}, std::vector<double>{0, 1, 2, static_cast<double>(dh)});
      }
    }
    EXPECT_THROW(file.write_slab("t_star", {3, 0}, std::vector<double>(4, 0.0)), std::invalid_argument);  // l has 3
    EXPECT_THROW(file.write_slab("t_star", {0, 0}, std::vector<double>(3, 0.0)), std::invalid_argument);  // 4 levels
    EXPECT_THROW(file.write_slab("t_star", {0}, std::vector<double>(8, 0.0)), std::invalid_argument);     // 2 indices
    EXPECT_THROW(file.write_slab("area", {0, 0}, std::vector<double>(4, 0.0)), std::invalid_argument);   // not declared
    file.close();
  }
  std::vector<hsize_t> chunk;
  const std::vector<double> t = read_all<double>(path, "t_star", H5T_NATIVE_DOUBLE, &chunk);
  EXPECT_EQ(chunk, (std::vector<hsize_t>{1, 1, 4}));
  const std::vector<std::int8_t> r = read_all<std::int8_t>(path, "regime", H5T_NATIVE_INT8, &chunk);
  EXPECT_EQ(chunk, (std::vector<hsize_t>{1, 1, 4}));
  for (std::size_t g = 0; g < 6; ++g) {
    for (std::size_t level = 0; level < 4; ++level) {
      const std::size_t k = g * 4 + level;
      if (g == 2) {  // (l, dh) = (1, 0): never written
        EXPECT_TRUE(std::isnan(t[k])) << k;
        EXPECT_EQ(r[k], -1) << k;
      } else {
        EXPECT_EQ(t[k], static_cast<double>(g) + 0.25 * static_cast<double>(level)) << k;
        EXPECT_EQ(r[k], level < 3 ? static_cast<std::int8_t>(level) : static_cast<std::int8_t>(g % 2)) << k;
      }
    }
  }
}

TEST(NetcdfFile, slabs_of_rows_tile_the_next_dimension_and_chunk_it) {
  const ScratchDir dir;
  const std::string path = dir.file("tiles.nc");
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  {
    NetcdfFile file(path);
    file.coordinate("l", {1.0, 2.0}, {});
    file.coordinate("pbar", {0.1, 0.2, 0.3, 0.4, 0.5}, {});
    file.coordinate("T", {20.0, 40.0}, {});
    // A geometry (l) a slab; its pressures in tiles of 2 rows (the last of one), each tile
    // every temperature.
    file.declare("t_star", {"l", "pbar", "T"}, 1, false, kNaN, {}, {}, 2);
    file.declare("X_star", {"l"}, 1, false, kNaN, {}, {}, 2);  // (no dimension after the slab's)
    for (const std::size_t l : {1u, 0u}) {
      for (const std::size_t first : {4u, 0u, 2u}) {
        const std::size_t rows = first == 4 ? 1 : 2;
        if (l == 1 && first == 2) continue;  // never written
        std::vector<double> values;
        for (std::size_t p = first; p < first + rows; ++p) {
          for (std::size_t T = 0; T < 2; ++T) values.push_back(static_cast<double>(100 * l + 10 * p + T));
        }
        file.write_slab("t_star", {l}, values, {first, rows});
      }
      file.write_slab("X_star", {l}, std::vector<double>{static_cast<double>(l)}, {0, 2});  // (rows: no such dimension)
    }
    EXPECT_THROW(file.write_slab("t_star", {0}, std::vector<double>(4, 0.0), {4, 2}), std::invalid_argument);  // past 5
    EXPECT_THROW(file.write_slab("t_star", {0}, std::vector<double>(2, 0.0), {0, 2}), std::invalid_argument);  // 4 values
    file.close();
  }
  std::vector<hsize_t> chunk;
  const std::vector<double> t = read_all<double>(path, "t_star", H5T_NATIVE_DOUBLE, &chunk);
  EXPECT_EQ(chunk, (std::vector<hsize_t>{1, 2, 2}));
  for (std::size_t l = 0; l < 2; ++l) {
    for (std::size_t p = 0; p < 5; ++p) {
      for (std::size_t T = 0; T < 2; ++T) {
        const std::size_t k = (l * 5 + p) * 2 + T;
        if (l == 1 && (p == 2 || p == 3)) {
          EXPECT_TRUE(std::isnan(t[k])) << k;
        } else {
          EXPECT_EQ(t[k], static_cast<double>(100 * l + 10 * p + T)) << k;
        }
      }
    }
  }
  EXPECT_EQ(read_all<double>(path, "X_star", H5T_NATIVE_DOUBLE, &chunk), (std::vector<double>{0.0, 1.0}));
}

}  // namespace
}  // namespace punchsweep::io
