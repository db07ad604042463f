#include "input/height_map.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <regex>
#include <sstream>

#include "input/csv_cells.hpp"
#include "input/usage_error.hpp"
#include "input/value_parsing.hpp"
#include "io/netcdf_file.hpp"
#include "model/numerics/number_text.hpp"
#include "model/numerics/units.hpp"

namespace punchsweep::input {

namespace {

constexpr std::size_t kMaxPixels = std::size_t{1} << 24;  // 4096 x 4096

void note_edges(HeightMap& map, const std::string& path);

HeightMap checked(HeightMap map, const std::string& path) {
  if (map.nx < 4 || map.ny < 4) {
    throw UsageError(path + ": a height map of " + std::to_string(map.nx) + " x " + std::to_string(map.ny) +
                     " pixels; valid: at least 4 x 4");
  }
  note_edges(map, path);
  return map;
}

/// a b, or nothing where it does not fit in 64 bits.
std::optional<std::uint64_t> product(std::uint64_t a, std::uint64_t b) {
  if (a != 0 && b > std::numeric_limits<std::uint64_t>::max() / a) return std::nullopt;
  return a * b;
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
  if (header_length > bytes.size() - start) fail("a .npy header longer than the file");
  const std::string header = bytes.substr(start, header_length);
  const std::string valid_dtype = "valid: little-endian float64 or float32 ('<f8', '<f4')";
  std::smatch m;
  if (!std::regex_search(header, m, std::regex(R"('descr'\s*:\s*'([^']*)')"))) fail("a .npy header without 'descr'");
  const std::string descr = m[1];
  // The item size is read as written, digits only: "<f99999999999" is a dtype, no number to parse.
  std::size_t size = 0;
  if (std::regex_match(descr, m, std::regex(R"(([<|=]?)f(\d+))"))) {
    const std::optional<std::uint64_t> written = decimal_uint64(m[2].str());
    if (written && (*written == 4 || *written == 8)) size = static_cast<std::size_t>(*written);
  }
  if (size == 0) fail("'descr' (dtype) '" + descr + "'; " + valid_dtype);
  // Fortran order (numpy writes it for a transposed array, Z.T, without saying): the same
  // array, its columns stored one after another.
  const bool fortran = std::regex_search(header, std::regex(R"('fortran_order'\s*:\s*True)"));
  if (!std::regex_search(header, m, std::regex(R"('shape'\s*:\s*\(([^)]*)\))"))) fail("a .npy header without 'shape'");
  const std::string shape = m[1];
  std::vector<std::uint64_t> dims;
  {
    std::istringstream counts(shape);
    for (std::string item; std::getline(counts, item, ',');) {
      const std::string count(model::trim(item, " \t"));
      if (count.empty() && counts.eof() && !dims.empty()) break;  // "(16, )": a tuple's last comma
      const std::optional<std::uint64_t> n = decimal_uint64(count);
      if (!n) fail("'shape' (" + shape + "): '" + count + "' is no count of pixels (a decimal integer below 2^64)");
      dims.push_back(*n);
    }
  }
  if (dims.size() != 2) fail("'shape' (" + shape + "): a .npy array that is not 2-D");
  const std::size_t data = start + header_length;
  const std::size_t items = (bytes.size() - data) / size;
  const std::optional<std::uint64_t> pixels = product(dims[0], dims[1]);
  if (!pixels || *pixels != items || (bytes.size() - data) % size != 0) {
    const std::size_t left = (bytes.size() - data) % size;
    fail("'shape' (" + shape + ") does not match the data: the file holds " + std::to_string(items) + " values of " +
         std::to_string(size) + " bytes after its header" + (left != 0 ? " and " + std::to_string(left) + " bytes more" : std::string()) +
         "; valid: two counts whose product is the number of values");
  }
  if (*pixels > kMaxPixels) fail("'shape' (" + shape + "): more than 4096 x 4096 pixels");
  HeightMap map;
  map.ny = static_cast<std::size_t>(dims[0]);
  map.nx = static_cast<std::size_t>(dims[1]);
  map.height.resize(map.nx * map.ny);
  for (std::size_t k = 0; k < map.height.size(); ++k) {
    // Item k of the file is row k / nx, column k % nx in C order; row k % ny, column
    // k / ny in Fortran order.
    const std::size_t at = fortran ? (k % map.ny) * map.nx + k / map.ny : k;
    if (size == 8) {
      std::memcpy(&map.height[at], bytes.data() + data + 8 * k, 8);
    } else {
      float v;
      std::memcpy(&v, bytes.data() + data + 4 * k, 4);
      map.height[at] = v;
    }
    if (!std::isfinite(map.height[at])) {
      fail("pixel (row " + std::to_string(at / map.nx) + ", column " + std::to_string(at % map.nx) + ") is not a finite number");
    }
  }
  return map;
}

/// NetCDF-3 (classic, 64-bit offset, CDF-5) as Unidata's format specification lays it out:
/// a header of dimensions, attributes and variables, big-endian, then the variables' data.
class NetcdfClassic {
 public:
  NetcdfClassic(const std::string& path, const std::string& bytes) : path_(path), bytes_(bytes) {
    version_ = static_cast<unsigned char>(bytes_.at(3));
    if (version_ != 1 && version_ != 2 && version_ != 5) fail("NetCDF version byte " + std::to_string(version_) + "; valid: 1, 2 or 5");
    at_ = 4;
    count();  // numrecs
    if (tag() == kDimension) {
      for (std::uint64_t n = count(), k = 0; k < n; ++k) {
        const std::string name = text();
        dims_.push_back({name, count()});
      }
    }
    global_ = attributes();
    if (tag() == kVariable) {
      for (std::uint64_t n = count(), k = 0; k < n; ++k) {
        Variable v;
        v.name = text();
        for (std::uint64_t d = count(), i = 0; i < d; ++i) {
          const std::uint64_t id = count();
          if (id >= dims_.size()) fail("variable " + v.name + " names dimension " + std::to_string(id) + ", which is not there");
          v.dims.push_back(id);
        }
        v.attributes = attributes();
        v.type = static_cast<int>(unsigned_of(4));
        count();  // vsize
        v.begin = version_ == 1 ? unsigned_of(4) : unsigned_of(8);
        variables_.push_back(std::move(v));
      }
    }
  }

  struct Dimension {
    std::string name;
    std::uint64_t length = 0;
  };
  struct Attribute {
    int type = 0;
    std::string text;            ///< NC_CHAR
    std::vector<double> values;  ///< the numeric types
  };
  using Attributes = std::vector<std::pair<std::string, Attribute>>;
  struct Variable {
    std::string name;
    std::vector<std::uint64_t> dims;
    Attributes attributes;
    int type = 0;
    std::uint64_t begin = 0;
  };

  const Variable* variable(const std::string& name) const {
    for (const Variable& v : variables_) {
      if (v.name == name) return &v;
    }
    return nullptr;
  }
  const Dimension& dimension(std::uint64_t id) const { return dims_[id]; }
  static const Attribute* attribute(const Variable& v, const std::string& name) {
    for (const auto& [key, a] : v.attributes) {
      if (key == name) return &a;
    }
    return nullptr;
  }
  /// The values of a fixed-size numeric variable, in the file's (C) order.
  std::vector<double> values(const Variable& v) const {
    std::optional<std::uint64_t> n = 1;
    for (const std::uint64_t d : v.dims) {
      if (dims_[d].length == 0) fail("variable " + v.name + " is a record variable (unlimited dimension): valid: fixed dimensions");
      if (n) n = product(*n, dims_[d].length);
    }
    std::size_t at = v.begin;
    const std::size_t size = type_size(v.type);
    const std::optional<std::uint64_t> length = n ? product(*n, size) : std::nullopt;
    if (!length || at > bytes_.size() || *length > bytes_.size() - at) {
      fail("variable " + v.name + "'s data runs past the end of the file");
    }
    std::vector<double> out;
    out.reserve(*n);
    for (std::uint64_t k = 0; k < *n; ++k, at += size) out.push_back(number(v.type, at));
    return out;
  }
  [[noreturn]] void fail(const std::string& what) const { throw UsageError(path_ + ": " + what + " (NetCDF)"); }

 private:
  static constexpr std::uint32_t kDimension = 0x0A, kVariable = 0x0B, kAttribute = 0x0C;

  std::uint64_t unsigned_of(std::size_t width) {
    if (at_ + width > bytes_.size()) fail("the header ends early");
    std::uint64_t v = 0;
    for (std::size_t k = 0; k < width; ++k) v = (v << 8) | static_cast<unsigned char>(bytes_[at_ + k]);
    at_ += width;
    return v;
  }
  std::uint64_t count() { return unsigned_of(version_ == 5 ? 8 : 4); }
  /// A list's tag: the list's kind, or 0 (ABSENT, its count 0 then).
  std::uint32_t tag() {
    const auto t = static_cast<std::uint32_t>(unsigned_of(4));
    if (t == 0) count();
    return t;
  }
  void pad() { at_ = (at_ + 3) / 4 * 4; }
  std::string text() {
    const std::uint64_t n = count();
    if (at_ > bytes_.size() || n > bytes_.size() - at_) fail("the header ends early");
    std::string out = bytes_.substr(at_, n);
    at_ += n;
    pad();
    return out;
  }
  static std::size_t type_size(int type) {
    switch (type) {
      case 1: case 2: case 7: return 1;
      case 3: case 8: return 2;
      case 4: case 5: case 9: return 4;
      case 6: case 10: case 11: return 8;
      default: return 0;
    }
  }
  double number(int type, std::size_t at) const {
    std::uint64_t raw = 0;
    const std::size_t size = type_size(type);
    for (std::size_t k = 0; k < size; ++k) raw = (raw << 8) | static_cast<unsigned char>(bytes_[at + k]);
    switch (type) {
      case 1: return static_cast<std::int8_t>(raw);
      case 3: return static_cast<std::int16_t>(raw);
      case 4: return static_cast<std::int32_t>(raw);
      case 5: {
        const auto bits = static_cast<std::uint32_t>(raw);
        float f;
        std::memcpy(&f, &bits, 4);
        return f;
      }
      case 6: {
        double d;
        std::memcpy(&d, &raw, 8);
        return d;
      }
      case 7: case 8: case 9: case 11: return static_cast<double>(raw);
      case 10: return static_cast<double>(static_cast<std::int64_t>(raw));
      default: fail("a value of NetCDF type " + std::to_string(type) + ", which is no number");
    }
  }
  Attributes attributes() {
    Attributes out;
    if (tag() != kAttribute) return out;
    for (std::uint64_t n = count(), k = 0; k < n; ++k) {
      std::string name = text();
      Attribute a;
      a.type = static_cast<int>(unsigned_of(4));
      const std::uint64_t values = count();
      const std::size_t size = type_size(a.type);
      if (size == 0) fail("attribute " + name + " has NetCDF type " + std::to_string(a.type));
      if (at_ > bytes_.size() || values > (bytes_.size() - at_) / size) fail("the header ends early");
      if (a.type == 2) {
        a.text = bytes_.substr(at_, values);
        while (!a.text.empty() && a.text.back() == '\0') a.text.pop_back();
      } else {
        for (std::uint64_t i = 0; i < values; ++i) a.values.push_back(number(a.type, at_ + i * size));
      }
      at_ += values * size;
      pad();
      out.emplace_back(std::move(name), std::move(a));
    }
    return out;
  }

  std::string path_;
  const std::string& bytes_;
  int version_ = 1;
  std::size_t at_ = 0;
  std::vector<Dimension> dims_;
  Attributes global_;
  std::vector<Variable> variables_;
};

/// SurfaceTopography's NetCDF-3 map: heights(x, y), the first index along x; the lengths,
/// unit and periodicity from the variables x and y where they say them.
io::NetcdfHeights read_netcdf(const std::string& path, const std::string& bytes) {
  const NetcdfClassic nc(path, bytes);
  const NetcdfClassic::Variable* heights = nc.variable("heights");
  if (!heights) nc.fail("no variable 'heights' (a SurfaceTopography map holds heights(x, y))");
  if (heights->dims.size() != 2) nc.fail("'heights' has " + std::to_string(heights->dims.size()) + " dimensions; valid: 2 (x, y)");
  io::NetcdfHeights out;
  out.nx = nc.dimension(heights->dims[0]).length;
  out.ny = nc.dimension(heights->dims[1]).length;
  const std::optional<std::uint64_t> pixels = product(out.nx, out.ny);
  if (!pixels || *pixels > kMaxPixels) nc.fail("more than 4096 x 4096 pixels");
  out.values = nc.values(*heights);
  for (const char axis : {'x', 'y'}) {
    const NetcdfClassic::Variable* v = nc.variable(std::string(1, axis));
    if (!v) continue;
    const auto number = [&](const char* name) -> std::optional<double> {
      const auto* a = NetcdfClassic::attribute(*v, name);
      return a && a->values.size() == 1 ? std::optional<double>(a->values[0]) : std::nullopt;
    };
    const auto* unit = NetcdfClassic::attribute(*v, "length_unit");
    io::take_axis_attributes(out, axis, number("length"), unit ? std::optional<std::string>(unit->text) : std::nullopt,
                             number("periodic"), path, "NetCDF");
  }
  return out;
}

/// A NetCDF map (either format) in the map's order: rows along y.
HeightMap from_netcdf(const io::NetcdfHeights& nc, const std::string& path) {
  HeightMap map;
  map.nx = nc.nx;
  map.ny = nc.ny;
  map.height.resize(nc.values.size());
  for (std::size_t i = 0; i < map.nx; ++i) {
    for (std::size_t j = 0; j < map.ny; ++j) {
      const double v = nc.values[i * map.ny + j];
      if (!std::isfinite(v)) {
        throw UsageError(path + ": heights(" + std::to_string(i) + ", " + std::to_string(j) + ") is not a finite number");
      }
      map.height[j * map.nx + i] = v;
    }
  }
  map.length_x = nc.length_x;
  map.length_y = nc.length_y;
  // A length unit by its one spelling: SurfaceTopography writes micrometres as "µm" (with
  // either micro sign, U+00B5 or U+03BC, in UTF-8; or the one byte 0xB5 of Latin-1, as
  // Windows software may), which the options and messages spell "um".
  const model::Unit* unit = model::find_unit(model::Dimension::length, nc.unit == "\xB5m" ? std::string("um") : nc.unit);
  map.unit = unit ? std::string(unit->name) : nc.unit;
  map.periodic = nc.periodic;
  return map;
}

/// The separator of a CSV map, from its first row: ';' or a tab (a comma in a value is then
/// its decimal point), a comma, or blanks alone.
char csv_separator(const std::string& first_row) {
  if (first_row.find_first_of(";\t,") == std::string::npos) return ' ';
  return separator_of(first_row);
}

std::string separator_name(char sep) {
  return sep == ';' ? "';' (decimal commas read as points)" : sep == '\t' ? "tabs (decimal commas read as points)"
                    : sep == ','   ? "commas"
                                   : "blanks";
}

HeightMap read_csv(const std::string& path, std::istream& lines) {
  HeightMap map;
  int line_number = 0;
  std::optional<char> sep;
  const auto where = [&] { return path + ":" + std::to_string(line_number) + ": "; };
  for (std::string line; std::getline(lines, line);) {
    ++line_number;
    if (line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a UTF-8 byte-order mark
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (!sep) sep = csv_separator(line);
    std::vector<std::string> cells;
    if (*sep == ' ') {
      std::istringstream values(line);
      for (std::string value; values >> value;) cells.push_back(value);
    } else {
      cells = split_cells(line, *sep);
      while (!cells.empty() && cells.back().empty()) cells.pop_back();  // a separator ending the row
      if (cells.empty()) continue;  // a spreadsheet's empty row: separators alone
    }
    for (const std::string& cell : cells) {
      if (cell.empty()) throw UsageError(where() + "an empty value (two separators in a row); a height map is a full grid");
      // Between commas, a value with blanks inside is two numbers, or a number written with
      // a decimal comma in a file separated by blanks: either way, not this layout.
      if (*sep == ',' && cell.find_first_of(" \t") != std::string::npos) {
        throw UsageError(where() + "'" + cell + "' between two commas: values separated by commas and by blanks "
                         "(decimal commas? separate such values by ';' or tabs, or write decimal points)");
      }
      const std::optional<double> v = cell_number(cell, decimal_comma_with(*sep));
      if (!v) {
        throw UsageError(where() + "'" + cell + "' is not a finite number (values separated by " + separator_name(*sep) +
                         ", as in the first row)");
      }
      map.height.push_back(*v);
    }
    if (map.nx == 0) map.nx = cells.size();
    if (cells.size() != map.nx) {
      throw UsageError(where() + std::to_string(cells.size()) + " values; the first row has " + std::to_string(map.nx) +
                       " (row " + std::to_string(map.ny + 1) + " of the map; a height map is a full grid)");
    }
    ++map.ny;
    if (map.height.size() > kMaxPixels) throw UsageError(path + ": more than 4096 x 4096 pixels");
  }
  return map;
}

/// The root mean square of h(k) - h(k') over the pixel pairs (k, k') `pair` gives for
/// i < n, along a row or a column.
template <class Pair>
double rms_step(std::size_t n, const std::vector<double>& h, Pair pair) {
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto [a, b] = pair(i);
    sum += (h[a] - h[b]) * (h[a] - h[b]);
  }
  return std::sqrt(sum / static_cast<double>(n));
}

/// The step across the map's edge (its last row to its first, or last column to its first)
/// beside the largest between neighbouring rows (columns) inside it.
struct EdgeStep {
  double across = 0.0;  ///< the RMS step across the edge
  double inside = 0.0;  ///< the largest RMS step between neighbouring rows (columns) inside
};
EdgeStep edge_step(const HeightMap& map, bool along_y) {
  const std::size_t nx = map.nx, ny = map.ny;
  const std::size_t lines = along_y ? ny : nx, width = along_y ? nx : ny;
  const auto at = [&](std::size_t line, std::size_t i) { return along_y ? line * nx + i : i * nx + line; };
  EdgeStep out;
  for (std::size_t line = 0; line + 1 < lines; ++line) {
    out.inside = std::max(out.inside, rms_step(width, map.height, [&](std::size_t i) { return std::pair{at(line + 1, i), at(line, i)}; }));
  }
  out.across = rms_step(width, map.height, [&](std::size_t i) { return std::pair{at(0, i), at(lines - 1, i)}; });
  return out;
}

/// A note where the map's opposite edges do not meet: the step across an edge is more than
/// kEdgeStepFactor times the largest between neighbouring rows (columns) inside the map, so
/// the map is no whole period (a tilt not levelled, a crop off the period). A map that says it
/// is not periodic has its own note.
constexpr double kEdgeStepFactor = 2.0;

void note_edges(HeightMap& map, const std::string& path) {
  if (map.periodic == 0) return;
  const auto [lo, hi] = std::minmax_element(map.height.begin(), map.height.end());
  const double range = *hi - *lo;
  std::vector<std::string> edges;
  for (const bool along_y : {false, true}) {
    const EdgeStep e = edge_step(map, along_y);
    if (e.across > kEdgeStepFactor * e.inside && e.across > 1e-9 * range) {
      const std::string factor = e.inside > 0.0 ? model::number_text(e.across / e.inside, 3) + " times" : "above";
      edges.push_back(std::string(along_y ? "its last row to its first" : "its last column to its first") + " steps " +
                      factor + " the largest step between neighbouring " + (along_y ? "rows" : "columns"));
    }
  }
  if (edges.empty()) return;
  std::string which = edges[0];
  if (edges.size() > 1) which += ", and " + edges[1];
  map.notes.push_back(path + ": its opposite edges do not meet (" + which + "): it looks like no whole period; the engine "
                      "repeats it as one period, so crop it to a whole period (or level its tilt) for a texture's answer");
}

}  // namespace

HeightMap read_height_map(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw UsageError(path + ": no regular file (a height map: CSV, .npy or NetCDF)");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw UsageError(path + ": cannot be read (a height map: CSV, .npy or NetCDF)");
  char magic[6] = {};
  file.read(magic, 6);
  if (file.gcount() == 6 && std::memcmp(magic, "\x93NUMPY", 6) == 0) {
    file.seekg(0);
    const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    return checked(read_npy(path, bytes), path);
  }
  const bool classic = file.gcount() >= 4 && std::memcmp(magic, "CDF", 3) == 0;
  if (classic || (file.gcount() >= 4 && std::memcmp(magic, "\x89HDF", 4) == 0)) {
    // NetCDF-3 as SurfaceTopography's to_netcdf writes it, or NetCDF-4 (HDF5) as its
    // parallel writer does.
    io::NetcdfHeights nc;
    try {
      if (classic) {
        file.seekg(0);
        const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        nc = read_netcdf(path, bytes);
      } else {
        nc = io::read_netcdf4_heights(path);
      }
    } catch (const UsageError&) {
      throw;
    } catch (const std::runtime_error& e) {
      throw UsageError(e.what());
    }
    return checked(from_netcdf(nc, path), path);
  }
  file.seekg(0);
  return checked(read_csv(path, file), path);
}

}  // namespace punchsweep::input
