#include "input/height_map.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>

#include "input/usage_error.hpp"

namespace punchsweep::input {

namespace {

constexpr std::size_t kMaxPixels = std::size_t{1} << 24;  // 4096 x 4096

HeightMap checked(HeightMap map, const std::string& path) {
  if (map.nx < 4 || map.ny < 4) {
    throw UsageError(path + ": a height map of " + std::to_string(map.nx) + " x " + std::to_string(map.ny) +
                     " pixels; valid: at least 4 x 4");
  }
  return map;
}

HeightMap read_npy(const std::string& path, const std::string& bytes) {
  const auto fail = [&](const std::string& what) { throw UsageError(path + ": " + what); };
  if (bytes.size() < 10) fail("a .npy file too short for its header");
  const unsigned major = static_cast<unsigned char>(bytes[6]);
  std::size_t header_length = 0, start = 0;
  if (major == 1) {
    header_length = static_cast<unsigned char>(bytes[8]) | (static_cast<std::size_t>(static_cast<unsigned char>(bytes[9])) << 8);
    start = 10;
  } else if (major == 2 || major == 3) {
    if (bytes.size() < 12) fail("a .npy file too short for its header");
    for (int k = 3; k >= 0; --k) header_length = (header_length << 8) | static_cast<unsigned char>(bytes[8 + static_cast<std::size_t>(k)]);
    start = 12;
  } else {
    fail(".npy format version " + std::to_string(major) + "; valid: 1, 2 or 3");
  }
  if (start + header_length > bytes.size()) fail("a .npy header longer than the file");
  const std::string header = bytes.substr(start, header_length);
  std::smatch m;
  if (!std::regex_search(header, m, std::regex(R"('descr'\s*:\s*'([<>|=]?)([fi])(\d+)')"))) fail("a .npy header without 'descr'");
  const std::string order = m[1], kind = m[2];
  const int size = std::stoi(m[3]);
  if (order == ">" || kind != "f" || (size != 8 && size != 4)) {
    fail("dtype '" + order + kind + std::to_string(size) + "'; valid: little-endian float64 or float32 ('<f8', '<f4')");
  }
  if (std::regex_search(header, std::regex(R"('fortran_order'\s*:\s*True)"))) fail("a Fortran-order array; valid: C order");
  if (!std::regex_search(header, m, std::regex(R"('shape'\s*:\s*\(\s*(\d+)\s*,\s*(\d+)\s*,?\s*\))"))) {
    fail("a .npy array that is not 2-D");
  }
  HeightMap map;
  map.ny = std::stoull(m[1]);
  map.nx = std::stoull(m[2]);
  if (map.nx * map.ny > kMaxPixels) fail("more than 4096 x 4096 pixels");
  const std::size_t data = start + header_length;
  if (bytes.size() != data + map.nx * map.ny * static_cast<std::size_t>(size)) fail("a .npy file whose size does not match its shape");
  map.height.resize(map.nx * map.ny);
  for (std::size_t k = 0; k < map.height.size(); ++k) {
    if (size == 8) {
      std::memcpy(&map.height[k], bytes.data() + data + 8 * k, 8);
    } else {
      float v;
      std::memcpy(&v, bytes.data() + data + 4 * k, 4);
      map.height[k] = v;
    }
    if (!std::isfinite(map.height[k])) fail("pixel " + std::to_string(k) + " is not a finite number");
  }
  return map;
}

HeightMap read_csv(const std::string& path, std::istream& lines) {
  HeightMap map;
  int line_number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++line_number;
    for (char& c : line) {
      if (c == ',' || c == ';' || c == '\t' || c == '\r') c = ' ';
    }
    std::istringstream values(line);
    std::size_t count = 0;
    for (std::string value; values >> value; ++count) {
      char* end = nullptr;
      const double v = std::strtod(value.c_str(), &end);
      if (end != value.c_str() + value.size() || !std::isfinite(v)) {
        throw UsageError(path + ":" + std::to_string(line_number) + ": '" + value + "' is not a finite number");
      }
      map.height.push_back(v);
    }
    if (count == 0) continue;
    if (map.nx == 0) map.nx = count;
    if (count != map.nx) {
      throw UsageError(path + ":" + std::to_string(line_number) + ": " + std::to_string(count) + " values; the first row has " +
                       std::to_string(map.nx) + " (a height map is a full grid)");
    }
    ++map.ny;
    if (map.height.size() > kMaxPixels) throw UsageError(path + ": more than 4096 x 4096 pixels");
  }
  return map;
}

}  // namespace

HeightMap read_height_map(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw UsageError(path + ": no regular file (a height map: CSV or .npy)");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw UsageError(path + ": cannot be read (a height map: CSV or .npy)");
  char magic[6] = {};
  file.read(magic, 6);
  if (file.gcount() == 6 && std::memcmp(magic, "\x93NUMPY", 6) == 0) {
    file.seekg(0);
    const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    return checked(read_npy(path, bytes), path);
  }
  file.seekg(0);
  return checked(read_csv(path, file), path);
}

}  // namespace punchsweep::input
