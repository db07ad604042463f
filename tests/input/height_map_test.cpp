// Height maps as files bring them (input/height_map.hpp): a .npy header that lies about its
// shape or dtype, a spreadsheet's CSV with decimal commas, a NetCDF map in µm, a map that is no
// whole period. Each file is written here byte by byte, as its format lays it out.
#include "input/height_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <unistd.h>

#include "input/usage_error.hpp"

namespace punchsweep::input {
namespace {

std::string write_file(const std::string& name, const std::string& bytes) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("height_map_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

/// A .npy file (format 1.0) with `header`'s dictionary and the doubles `values` after it.
std::string npy(const std::string& dictionary, const std::vector<double>& values) {
  std::string header = dictionary;
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::string bytes = "\x93NUMPY";
  bytes += '\x01';
  bytes += '\x00';
  bytes += static_cast<char>(header.size() & 0xff);
  bytes += static_cast<char>(header.size() >> 8);
  bytes += header;
  for (const double v : values) bytes.append(reinterpret_cast<const char*>(&v), 8);
  return bytes;
}

std::vector<double> ramp(std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = std::sin(2.0 * std::numbers::pi * static_cast<double>(k % 4) / 4.0);
  return v;
}

/// What read_height_map says of `path`: its UsageError's message, or "accepted".
std::string refusal(const std::string& path) {
  try {
    const HeightMap map = read_height_map(path);
    return "accepted as " + std::to_string(map.nx) + " x " + std::to_string(map.ny);
  } catch (const UsageError& e) {
    return e.what();
  }
}

TEST(HeightMap, a_npy_shape_whose_product_overflows_is_refused_naming_the_shape) {
  // 4 (2^62 + 4) is 16 modulo 2^64: the 16 values would pass for a 4 x 4 map.
  const std::string path = write_file("wrap.npy", npy("{'descr': '<f8', 'fortran_order': False, 'shape': (4, 4611686018427387908), }", ramp(16)));
  const std::string message = refusal(path);
  EXPECT_NE(message.find(path + ": 'shape' (4, 4611686018427387908) does not match the data"), std::string::npos) << message;
  EXPECT_NE(message.find("the file holds 16 values of 8 bytes after its header; valid: two counts whose product"), std::string::npos)
      << message;
}

TEST(HeightMap, a_npy_shape_of_two_to_the_64_pixels_is_refused_not_read) {
  // 2^32 x 2^32 is 0 modulo 2^64: it matched an empty data block and the reader then
  // indexed 2^64 pixels.
  const std::string path = write_file("zero.npy", npy("{'descr': '<f8', 'fortran_order': False, 'shape': (4294967296, 4294967296), }", {}));
  EXPECT_NE(refusal(path).find("'shape' (4294967296, 4294967296) does not match the data"), std::string::npos) << refusal(path);
}

TEST(HeightMap, a_npy_shape_or_dtype_too_long_for_an_integer_is_a_usage_error) {
  const std::string long_shape =
      write_file("long.npy", npy("{'descr': '<f8', 'fortran_order': False, 'shape': (123456789012345678901234567890, 4), }", ramp(16)));
  EXPECT_NE(refusal(long_shape).find("'shape' (123456789012345678901234567890, 4): '123456789012345678901234567890' is no count"),
            std::string::npos)
      << refusal(long_shape);
  const std::string long_dtype = write_file("dtype.npy", npy("{'descr': '<f99999999999', 'fortran_order': False, 'shape': (4, 4), }", ramp(16)));
  EXPECT_NE(refusal(long_dtype).find("'descr' (dtype) '<f99999999999'; valid: little-endian float64 or float32"), std::string::npos)
      << refusal(long_dtype);
  const std::string three_d = write_file("cube.npy", npy("{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2, 4), }", ramp(16)));
  EXPECT_NE(refusal(three_d).find("not 2-D"), std::string::npos) << refusal(three_d);
  const std::string sign = write_file("sign.npy", npy("{'descr': '<f8', 'fortran_order': False, 'shape': (-4, 4), }", ramp(16)));
  EXPECT_NE(refusal(sign).find("'-4' is no count"), std::string::npos) << refusal(sign);
}

TEST(HeightMap, a_npy_map_whose_shape_matches_its_data_is_read_rows_along_y) {
  std::vector<double> z(32);
  for (std::size_t k = 0; k < z.size(); ++k) z[k] = std::sin(2.0 * std::numbers::pi * static_cast<double>(k % 8) / 8.0);
  const HeightMap map = read_height_map(write_file("good.npy", npy("{'descr': '<f8', 'fortran_order': False, 'shape': (4, 8), }", z)));
  EXPECT_EQ(map.nx, 8u);
  EXPECT_EQ(map.ny, 4u);
  EXPECT_EQ(map.height, z);
  EXPECT_TRUE(map.notes.empty());
}

TEST(HeightMap, a_fortran_order_npy_map_is_the_same_array_its_columns_stored_first) {
  // numpy writes Z.T (or np.asfortranarray(Z)) column after column with fortran_order True:
  // the same 4 x 8 array as its C-order copy, every pixel where that puts it.
  std::vector<double> z(32), columns;
  for (std::size_t k = 0; k < z.size(); ++k) z[k] = static_cast<double>(k) + 0.25 * static_cast<double>(k % 3);
  for (std::size_t c = 0; c < 8; ++c) {
    for (std::size_t r = 0; r < 4; ++r) columns.push_back(z[r * 8 + c]);
  }
  const HeightMap map = read_height_map(write_file("fortran.npy", npy("{'descr': '<f8', 'fortran_order': True, 'shape': (4, 8), }", columns)));
  EXPECT_EQ(map.nx, 8u);
  EXPECT_EQ(map.ny, 4u);
  EXPECT_EQ(map.height, z);
  const HeightMap c_order = read_height_map(write_file("c_order.npy", npy("{'descr': '<f8', 'fortran_order': False, 'shape': (4, 8), }", z)));
  EXPECT_EQ(c_order.height, map.height);
}

/// A 4 x 4 grid, each row one period of a sinusoid along x (1.5, 1.75, 1.5, 1.25), as text
/// with `sep` between values and `point` as the decimal mark.
std::string grid_text(const std::string& sep, char point) {
  std::string text;
  for (int j = 0; j < 4; ++j) {
    int i = 0;
    for (const char* written : {"1.5", "1.75", "1.5", "1.25"}) {
      std::string v = written;
      if (point == ',') std::replace(v.begin(), v.end(), '.', ',');
      text += i++ > 0 ? sep : "";
      text += v;
    }
    text += "\r\n";
  }
  return text;
}

TEST(HeightMap, a_csv_with_decimal_commas_between_semicolons_or_tabs_reads_them_as_points) {
  const HeightMap points = read_height_map(write_file("points.csv", grid_text(",", '.')));
  for (const std::string sep : {";", "\t", "; "}) {
    const HeightMap commas = read_height_map(write_file("commas.csv", grid_text(sep, ',')));
    EXPECT_EQ(commas.nx, 4u) << sep;
    EXPECT_EQ(commas.ny, 4u) << sep;
    EXPECT_EQ(commas.height, points.height) << sep;
  }
  const HeightMap spreadsheet =
      read_height_map(write_file("excel.csv", "1,5;2,25;3;2,25\n1,5;2,25;3;2,25\n1,5;2,25;3;2,25\n1,5;2,25;3;2,25;\n;;;\n"));
  EXPECT_EQ(spreadsheet.nx, 4u);
  EXPECT_EQ(spreadsheet.ny, 4u);  // the row of separators alone is no row
  EXPECT_EQ(spreadsheet.height[1], 2.25);
  EXPECT_EQ(spreadsheet.height[15], 2.25);
}

TEST(HeightMap, a_csv_whose_commas_may_be_decimal_or_separators_is_refused) {
  // Blanks between values and a comma inside each: "1,5 2,25" is 1 | 5 2 | 25 read at commas.
  const std::string path = write_file("blanks.csv", "1,5 2,25 3,0 2,25\n1,5 2,25 3,0 2,25\n1,5 2,25 3,0 2,25\n1,5 2,25 3,0 2,25\n");
  EXPECT_NE(refusal(path).find(path + ":1: '5 2' between two commas: values separated by commas and by blanks"), std::string::npos)
      << refusal(path);
  // A row in another layout than the first: its values are no numbers in the first's.
  const std::string mixed = write_file("mixed.csv", "1,5;2;3;2\n1,5;2;3;2\n1.5,2,3,2\n1,5;2;3;2\n");
  EXPECT_NE(refusal(mixed).find(mixed + ":3: '1.5,2,3,2' is not a finite number (values separated by ';'"), std::string::npos)
      << refusal(mixed);
}

TEST(HeightMap, a_csv_row_of_another_length_is_refused_naming_the_row) {
  const std::string path = write_file("ragged.csv", "1,5;2;3;2\n\n1,5;2;3;2\n1,5;2;3\n1,5;2;3;2\n");
  EXPECT_NE(refusal(path).find(path + ":4: 3 values; the first row has 4 (row 3 of the map"), std::string::npos) << refusal(path);
  const std::string empty = write_file("empty.csv", "1;2;;2\n1;2;3;2\n1;2;3;2\n1;2;3;2\n");
  EXPECT_NE(refusal(empty).find(empty + ":1: an empty value"), std::string::npos) << refusal(empty);
}

TEST(HeightMap, a_map_whose_opposite_edges_do_not_meet_comes_with_a_note) {
  // One period of a sinusoid along x and y: the edges meet (the step across them is one of
  // the map's own). The same tilted by a plane: the step across is 8 times the others.
  const int n = 8;
  std::string periodic, tilted;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double z = std::sin(2 * std::numbers::pi * i / n) * std::cos(2 * std::numbers::pi * j / n);
      periodic += i ? "," : "";
      periodic += std::to_string(z);
      tilted += i ? "," : "";
      tilted += std::to_string(z + 0.5 * j);
    }
    periodic += "\n";
    tilted += "\n";
  }
  EXPECT_TRUE(read_height_map(write_file("periodic.csv", periodic)).notes.empty());
  const std::string path = write_file("tilted.csv", tilted);
  const HeightMap map = read_height_map(path);
  ASSERT_EQ(map.notes.size(), 1u);
  EXPECT_NE(map.notes[0].find(path + ": its opposite edges do not meet (its last row to its first steps"), std::string::npos)
      << map.notes[0];
  EXPECT_EQ(map.notes[0].find("column"), std::string::npos) << map.notes[0];
}

/// A classic NetCDF file (CDF-1, Unidata's layout) as SurfaceTopography writes a map:
/// heights(x, y), and x with `length` and `length_unit` (the bytes as given).
std::string netcdf(std::size_t nx, std::size_t ny, const std::string& unit) {
  std::string out = "CDF";
  out += '\x01';
  const auto u32 = [&](std::uint32_t v) {
    for (int k = 3; k >= 0; --k) out += static_cast<char>((v >> (8 * k)) & 0xff);
  };
  const auto pad = [&] {
    while (out.size() % 4 != 0) out += '\0';
  };
  const auto name = [&](const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    out += s;
    pad();
  };
  const auto f64 = [&](double d) {
    std::uint64_t r;
    std::memcpy(&r, &d, 8);
    for (int k = 7; k >= 0; --k) out += static_cast<char>((r >> (8 * k)) & 0xff);
  };
  u32(0);  // numrecs
  u32(0x0A);
  u32(2);
  name("x");
  u32(static_cast<std::uint32_t>(nx));
  name("y");
  u32(static_cast<std::uint32_t>(ny));
  u32(0);  // no global attributes
  u32(0);
  u32(0x0B);
  u32(2);
  name("x");
  u32(1);
  u32(0);
  u32(0x0C);
  u32(2);
  name("length");
  u32(6);
  u32(1);
  f64(static_cast<double>(nx));
  name("length_unit");
  u32(2);
  u32(static_cast<std::uint32_t>(unit.size()));
  out += unit;
  pad();
  u32(6);
  u32(static_cast<std::uint32_t>(8 * nx));
  const std::size_t x_begin = out.size();
  u32(0);
  name("heights");
  u32(2);
  u32(0);
  u32(1);
  u32(0);
  u32(0);
  u32(6);
  u32(static_cast<std::uint32_t>(8 * nx * ny));
  const std::size_t heights_begin = out.size();
  u32(0);
  const auto patch = [&](std::size_t at, std::size_t value) {
    for (int k = 3; k >= 0; --k) out[at + 3 - static_cast<std::size_t>(k)] = static_cast<char>((value >> (8 * k)) & 0xff);
  };
  patch(x_begin, out.size());
  for (std::size_t i = 0; i < nx; ++i) f64(static_cast<double>(i) + 0.5);
  patch(heights_begin, out.size());
  for (std::size_t i = 0; i < nx; ++i) {
    for (std::size_t j = 0; j < ny; ++j) f64(std::sin(2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(nx)));
  }
  return out;
}

TEST(HeightMap, a_netcdf_map_in_micrometres_with_either_micro_sign_is_in_um) {
  const HeightMap plain = read_height_map(write_file("um.nc", netcdf(8, 4, "um")));
  EXPECT_EQ(plain.unit, "um");
  EXPECT_EQ(plain.length_x, 8.0);
  for (const std::string micro : {"\xC2\xB5m", "\xCE\xBCm", "\xB5m"}) {  // U+00B5, U+03BC in UTF-8; Latin-1's micro sign
    const HeightMap map = read_height_map(write_file("micro.nc", netcdf(8, 4, micro)));
    EXPECT_EQ(map.unit, "um") << micro;
    EXPECT_EQ(map.height, plain.height);
  }
}

}  // namespace
}  // namespace punchsweep::input
