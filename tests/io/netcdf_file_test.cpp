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

}  // namespace
}  // namespace punchsweep::io
