#include "engine/texture_map.hpp"

#include <boost/program_options.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <unistd.h>
#include <utility>

#include "engine/surface_evaluation.hpp"
#include "run/text_lines.hpp"
#include "input/axis_parser.hpp"
#include "input/scaled_value.hpp"
#include "input/usage_error.hpp"
#include "input/value_parsing.hpp"
#include "io/crc32.hpp"
#include "io/netcdf_file.hpp"
#include "io/output_file.hpp"
#include "model/contact/regime.hpp"
#include "model/laws/creep_laws.hpp"
#include "model/point/parameters.hpp"
#include "model/point/point_axes.hpp"
#include "model/point/sensitivity.hpp"
#include "model/surface/surface_sensitivity.hpp"
#include "model/surface/surface_history.hpp"
#include "model/surface/surface_advisory.hpp"
#include "sweep/mpi_session.hpp"

namespace po = boost::program_options;

namespace punchsweep::engine {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::int8_t kNotComputed = -1;

/// The texture's lengths that may be axes, each one load curve per value, in the map's order.
constexpr std::string_view kGeometryKeys[] = {model::kPitch, model::kHeightDifference, model::kThirdLevelDrop,
                                              model::kScatterWidth, model::kScatterSeed};
/// The map's own keywords (not the texture's).
constexpr const char* kOutput = "output";
constexpr const char* kOverwrite = "overwrite";
constexpr const char* kResume = "resume";
constexpr const char* kQuiet = "quiet";
/// The map's sample of load points checked by time stepping, and its seed.
constexpr const char* kCheckSample = "check-sample";
constexpr const char* kCheckSeed = "check-seed";
/// The target values a tile of the map holds (load points x snapshot times), and its default.
constexpr const char* kChunk = "chunk";
/// What the map stores: regime (each level's touch) or full (and what the times read).
constexpr const char* kQuantities = "quantities";
constexpr std::size_t kDefaultChunk = 4096;


/// The options `surface` has that a map does not take, and why.
struct Refused {
  const char* key;
  const char* why;
};
constexpr Refused kRefused[] = {
    {"check", "the time stepping checks a sample of the map's load points: --check-sample K"},
    {"format", "the map is a netCDF-4 file (--output)"},
    {"seeds", "a map draws one supercell per value of its seed axis ([texture] seed = 1:8) and keeps each"},
    {"part-caps", "a map keeps each drawn supercell; surface --part-caps N says how far a part's tallest tip lies"},
    {"target-error", "a map draws one supercell per value of its seed axis, as many as it lists"},
};

/// A map's limits (refused up front): geometries, each a load curve.
constexpr std::size_t kMaxGeometries = 10000;
/// A geometry's load points: a tile (a row of the first load axis at the least, the whole
/// geometry at the most) travels whole between ranks and into the journal (with three
/// levels and ten times, about 500 bytes a load point), and --grid auto holds each level's
/// touch at every load point on two grids.
constexpr double kMaxLoadPoints = 1e6;

const std::string* find(const input::Keywords& keywords, const std::string& name) {
  for (const auto& [key, value] : keywords) {
    if (key == name) return &value;
  }
  return nullptr;
}

/// An axis of `text` measured as `parameter` (its scale, units, range), named `name`.
SurfaceMapAxis read_axis(const std::string& name, const std::string& text, const model::Parameter& parameter,
                         const input::PhysicalScales& scales, bool units_required = false) {
  map::Axis axis;
  try {
    const std::optional<input::Scale> scale = input::scale_of(parameter.scale, scales);
    axis = scale ? input::read_scaled_axis(text, parameter.integer, *scale, units_required)
                 : input::parse_axis(text, parameter.integer);
  } catch (const std::invalid_argument& e) {
    throw input::UsageError("--" + name + " = '" + text + "': " + e.what());
  }
  for (const double v : axis.values) {
    if (!parameter.admits(v)) throw input::UsageError("--" + name + " = '" + text + "': " + parameter.error(v));
  }
  return {name, axis.values, std::string(parameter.scale), std::string(parameter.long_name)};
}

/// The map's reading of its keywords: the texture's own, the axes, the load's axes.
struct MapInputs {
  input::Keywords texture;  ///< every keyword but the axes' and the map's own
  std::vector<SurfaceMapAxis> geometry;
  std::string scatter_kind;  ///< "normal" / "uniform" where the scatter's width is an axis
  /// The load's axes: pbar, then the point's other coordinates given (the creep law's
  /// parameters, ramp_time), in model::PointAxes' order; and the coordinate each sets.
  std::vector<SurfaceMapAxis> load;
  std::vector<model::PointAxis> load_coordinates;
  /// A box of tolerances about every load point (--tolerance, its text): on the pressure and
  /// the law's parameters, each with its coordinate.
  std::string tolerance_text;
  std::vector<model::StatedTolerance> tolerance;
  std::vector<model::PointAxis> tolerance_coordinates;
  /// --check-sample K and --check-seed S: K load points of the map checked by time stepping.
  std::uint64_t check_sample = 0;
  std::uint64_t check_seed = 1;
  /// --chunk N: the target values of a tile (load points x snapshot times).
  std::size_t chunk = kDefaultChunk;
  /// --quantities regime|full.
  bool full = true;
  /// The material (or law) the keywords name: its law spec is what the load points build.
  std::shared_ptr<const input::PointMaterial> material;
  const model::CreepLawSpec* spec = nullptr;  ///< material->spec
};

/// The coordinate of a load point that option `key` gives (--pbar or --pressure, a creep
/// law's parameter, --ramp: model::PointAxes without the texture's l, s, dh), if any.
std::optional<model::PointAxis> load_coordinate(const model::PointAxes& axes, const std::string& key) {
  const std::string name = key == "pressure" ? std::string(model::kPressure)
                           : key == "ramp"   ? std::string(model::ramp_time_parameter().name)
                                             : key;
  const std::size_t j = axes.find(name);
  if (j == axes.size() || axes[j].coordinate <= model::Coordinate::height_difference) return std::nullopt;
  return axes[j];
}

MapInputs read_map_inputs(const input::Keywords& keywords) {
  MapInputs in;
  in.material = std::make_shared<const input::PointMaterial>(input::find_point_material(keywords));
  const input::PointMaterial& material = *in.material;
  in.spec = &material.spec;
  std::optional<model::Physical> R;
  if (const std::string* text = find(keywords, "R")) {
    try {
      R = input::read_length_scale(*text);
    } catch (const std::invalid_argument& e) {
      throw input::UsageError(std::string("--R = '") + *text + "': " + e.what());
    }
  }
  const input::PhysicalScales scales = input::scales_of(material.material.get(), R);
  const model::PointAxes point_axes(in.spec->parameters, true);
  for (const auto& [key, value] : keywords) {
    if (is_map_run_keyword(key)) continue;
    if (key == "tolerance") {
      in.tolerance_text = value;
      continue;
    }
    if (key == kCheckSample || key == kCheckSeed) {
      const std::uint64_t n = input::parse_seed(value, std::string("--") + key);
      if (key == kCheckSample && n == 0) throw input::UsageError("--check-sample = 0: valid: at least 1 load point");
      (key == kCheckSample ? in.check_sample : in.check_seed) = n;
      continue;
    }
    if (key == kQuantities) {
      if (value != "regime" && value != "full") {
        throw input::UsageError("--quantities = '" + value + "': valid: regime (each level's touch) or full (and what the "
                                "snapshot times read: caps and areas in contact, each level's load)");
      }
      in.full = value == "full";
      continue;
    }
    if (key == kChunk) {
      const std::string valid = ": valid: an integer >= 1 (load points x snapshot times a tile)";
      int n = 0;
      try {
        n = input::parse_integer(value, "--chunk");
      } catch (const input::UsageError&) {
        throw input::UsageError("--chunk = '" + value + "' is not an integer" + valid);
      }
      if (n < 1) throw input::UsageError("--chunk = " + value + valid);
      in.chunk = static_cast<std::size_t>(n);
      continue;
    }
    for (const Refused& r : kRefused) {
      if (key == r.key) throw input::UsageError("--" + key + " is not a map's: " + r.why);
    }
    const bool geometry = key == model::kPitch || key == model::kHeightDifference || key == model::kThirdLevelDrop ||
                          key == model::kScatterSeed;
    if (geometry) {
      const model::Parameter* p = model::problem_parameter(key);
      in.geometry.push_back(read_axis(key, value, p ? *p : *model::texture_parameter(key), scales));
    } else if (key == "scatter" && (value.rfind("normal:", 0) == 0 || value.rfind("uniform:", 0) == 0)) {
      const std::size_t colon = value.find(':');
      in.scatter_kind = value.substr(0, colon);
      SurfaceMapAxis axis = read_axis("scatter", value.substr(colon + 1), *model::texture_parameter(model::kScatterWidth), scales);
      axis.name = model::kScatterWidth;
      in.geometry.push_back(std::move(axis));
    } else if (const std::optional<model::PointAxis> coordinate = load_coordinate(point_axes, key)) {
      for (const model::PointAxis& c : in.load_coordinates) {
        if (c.parameter == coordinate->parameter) {
          throw input::UsageError("--" + key + ": the " + std::string(c.parameter->long_name) +
                                  " is given twice (--pbar and --pressure are one axis); give it once");
        }
      }
      SurfaceMapAxis axis = read_axis(key, value, *coordinate->parameter, scales, key == "pressure");
      axis.name = std::string(coordinate->parameter->name);
      in.load.push_back(std::move(axis));
      in.load_coordinates.push_back(*coordinate);
    } else {
      in.texture.emplace_back(key, value);
    }
  }
  const auto given = [&](model::Coordinate c) {
    return std::any_of(in.load_coordinates.begin(), in.load_coordinates.end(),
                       [&](const model::PointAxis& a) { return a.coordinate == c; });
  };
  if (!given(model::Coordinate::pressure)) {
    throw input::UsageError("--pbar (or --pressure with a material) is required: the load's axis");
  }
  if (given(model::Coordinate::ramp_time) && find(in.texture, "load-table") != nullptr) {
    throw input::UsageError("--ramp and --load-table both given; valid: one of them");
  }
  if (!in.tolerance_text.empty()) {
    // On the load's inputs only: a corner of the geometry would be a load curve of its own.
    std::string names = "pbar or pressure";
    for (const std::size_t j : point_axes.law()) names += ", " + std::string(point_axes[j].parameter->name);
    const auto known = [&](std::string_view name) -> const model::Parameter* {
      const std::size_t j = point_axes.find(name);
      if (j == point_axes.size()) return nullptr;
      const model::Coordinate c = point_axes[j].coordinate;
      return c == model::Coordinate::pressure || c == model::Coordinate::law ? point_axes[j].parameter : nullptr;
    };
    in.tolerance = input::parse_tolerances(
        in.tolerance_text, "--tolerance", known, scales, names,
        "is no load input of a surface map (a tolerance on the texture's geometry needs a load curve per corner)");
    if (in.tolerance.size() > model::kMaxTolerances) {
      throw input::UsageError("--tolerance: at most " + std::to_string(model::kMaxTolerances) + " tolerances");
    }
    for (const model::StatedTolerance& t : in.tolerance) in.tolerance_coordinates.push_back(point_axes[point_axes.find(t.parameter->name)]);
  }
  // The geometry's axes in one order, whatever the keywords' (l, dh, dh2, scatter_width).
  const auto place = [](const SurfaceMapAxis& a) {
    const auto* at = std::find(std::begin(kGeometryKeys), std::end(kGeometryKeys), a.name);
    return at - std::begin(kGeometryKeys);
  };
  std::stable_sort(in.geometry.begin(), in.geometry.end(), [&](const auto& a, const auto& b) { return place(a) < place(b); });
  // The load's: pbar first, then in the point's order.
  const auto rank = [&](std::size_t k) {
    const model::PointAxis& a = in.load_coordinates[k];
    return a.coordinate == model::Coordinate::pressure ? 0 : 1 + point_axes.find(a.parameter->name);
  };
  std::vector<std::size_t> order(in.load.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rank(a) < rank(b); });
  std::vector<SurfaceMapAxis> load;
  std::vector<model::PointAxis> coordinates;
  for (const std::size_t k : order) {
    load.push_back(in.load[k]);
    coordinates.push_back(in.load_coordinates[k]);
  }
  in.load = std::move(load);
  in.load_coordinates = std::move(coordinates);
  return in;
}

/// The point's keyword text of a value in its scaled unit.
std::string text_of(double value) { return input::json_number(value); }

/// The digits of row-major index k over `sizes`.
std::vector<std::size_t> digits_of(std::size_t k, const std::vector<std::size_t>& sizes) {
  std::vector<std::size_t> out(sizes.size());
  for (std::size_t d = sizes.size(); d-- > 0;) {
    out[d] = k % sizes[d];
    k /= sizes[d];
  }
  return out;
}

std::vector<std::size_t> sizes_of(const std::vector<SurfaceMapAxis>& axes) {
  std::vector<std::size_t> out;
  for (const SurfaceMapAxis& a : axes) out.push_back(a.values.size());
  return out;
}

std::string json_keywords(const input::Keywords& keywords) {
  std::string out = "{";
  for (std::size_t k = 0; k < keywords.size(); ++k) {
    out += (k ? ", " : "") + input::json_string(keywords[k].first) + ": " + input::json_string(keywords[k].second);
  }
  return out + "}";
}

}  // namespace

/// Whether `key` is one of the run's own keywords (where and how to write), not the map's.
bool is_map_run_keyword(const std::string& key) {
  return key == kOutput || key == kOverwrite || key == kResume || key == kQuiet;
}

std::size_t SurfaceMap::geometries() const {
  std::size_t n = 1;
  for (const SurfaceMapAxis& a : geometry) n *= a.values.size();
  return n;
}

std::size_t SurfaceMap::load_points() const {
  std::size_t n = 1;
  for (const SurfaceMapAxis& a : load) n *= a.values.size();
  return n;
}

std::size_t SurfaceMap::points_per_row() const {
  std::size_t n = 1;
  for (std::size_t a = 1; a < load.size(); ++a) n *= load[a].values.size();
  return n;
}

std::size_t SurfaceMap::tiles_per_geometry() const {
  const std::size_t rows = load.empty() ? 1 : load.front().values.size();
  return (rows + tile_rows - 1) / tile_rows;
}

SurfaceMap::Tile SurfaceMap::tile(std::size_t u) const {
  const std::size_t per = tiles_per_geometry(), rows = load.empty() ? 1 : load.front().values.size();
  if (u >= geometries() * per) throw std::invalid_argument("tile " + std::to_string(u) + " outside the map's " + std::to_string(geometries() * per));
  const std::size_t row = (u % per) * tile_rows;
  return {u / per, row * points_per_row(), std::min(tile_rows, rows - row) * points_per_row()};
}

std::size_t SurfaceMap::per_points(std::size_t q, std::size_t P) const {
  const std::size_t L = static_cast<std::size_t>(levels), T = times.size();
  switch (map::kTextureQuantities[q].extent) {
    case map::TextureExtent::load_level: return P * L;
    case map::TextureExtent::geometry_level: return L;
    case map::TextureExtent::load_time: return P * T;
    case map::TextureExtent::load_time_level: return P * T * L;
    case map::TextureExtent::geometry: return 1;
  }
  return 0;
}

namespace {

/// Each stored quantity and its values a geometry, in map::kTextureQuantities' order: the
/// order a geometry's values travel (between ranks, into the journal) and are written.
/// Over `points` load points of a geometry (a tile's), or all of them.
template <class Visit>
void for_each_stored(const SurfaceMap& map, std::size_t points, Visit&& visit) {
  for (std::size_t q = 0; q < map::kTextureQuantityCount; ++q) {
    if (map.stores(q)) visit(q, map.per_points(q, points));
  }
}
template <class Visit>
void for_each_stored(const SurfaceMap& map, Visit&& visit) {
  for_each_stored(map, map.load_points(), std::forward<Visit>(visit));
}

/// Whether a quantity of `extent` runs over the load's axes (then a tile holds its rows).
constexpr bool over_load(map::TextureExtent extent) {
  return extent != map::TextureExtent::geometry && extent != map::TextureExtent::geometry_level;
}

/// A block's head: levels, caps, E0* in Pa, the curve's seconds and source (0 built, 1
/// from the cache, 2 off the tables, 3 held from the rank's tile before), the number of
/// times, then the times.
enum Head : std::size_t { kLevels, kCaps, kE0, kSeconds, kSource, kTimes, kHead };

/// Sizes every stored array of `map` for its geometries: NaN, flags not computed.
void size_arrays(SurfaceMap& map) {
  const std::size_t G = map.geometries();
  for (SurfaceMap::Values& values : map.values) values.clear();
  for_each_stored(map, [&](std::size_t q, std::size_t n) {
    const bool flag = map::kTextureQuantities[q].flags != map::TextureFlags::none;
    map[q].assign(G * n, flag ? static_cast<double>(kNotComputed) : kNaN);
  });
}

// The quantities a geometry computes, by name (a name not declared fails to compile).
constexpr std::size_t kTStar = map::texture_quantity("t_star"), kRegime = map::texture_quantity("regime"),
                      kTStarLow = map::texture_quantity("t_star_low"), kTStarHigh = map::texture_quantity("t_star_high"),
                      kRegimeLow = map::texture_quantity("regime_low"), kRegimeHigh = map::texture_quantity("regime_high"),
                      kXStar = map::texture_quantity("X_star"), kResolved = map::texture_quantity("resolved"),
                      kTouched = map::texture_quantity("touched"), kAreaFraction = map::texture_quantity("area_fraction"),
                      kValid = map::texture_quantity("valid"), kGrid = map::texture_quantity("grid"),
                      kFromTables = map::texture_quantity("from_tables"),
                      kContactRadius = map::texture_quantity("contact_radius"), kAdvised = map::texture_quantity("advised"),
                      kCheckRegime = map::texture_quantity("check_regime"), kCheckTStar = map::texture_quantity("check_t_star"),
                      kCheckResolution = map::texture_quantity("check_t_star_resolution"),
                      kCheckAreaFraction = map::texture_quantity("check_area_fraction"),
                      kLevelTouched = map::texture_quantity("level_touched"), kLevelArea = map::texture_quantity("level_area"),
                      kLevelLoad = map::texture_quantity("level_load");

}  // namespace

struct TextureMapPlan::Inputs : MapInputs {};

/// A geometry's run as a tile reads it, and what opening it cost.
struct TextureMapPlan::Opened {
  std::size_t geometry;
  SurfaceRun run;
  double seconds;
};

TextureMapPlan::TextureMapPlan(const input::Keywords& keywords)
    : in_(std::make_unique<const Inputs>(Inputs{read_map_inputs(keywords)})) {
  const MapInputs& in = *in_;
  SurfaceMap& map = header_;
  map.geometry = in.geometry;
  map.load = in.load;
  map.texture = json_keywords(in.texture);
  map.scatter_kind = in.scatter_kind;
  map.tolerance = in.tolerance_text;
  map.full = in.full;
  map.time_unit = in.material->time_unit();
  if (const std::string* m = find(keywords, "material")) map.material = *m;
  if (const std::string* R = find(keywords, "R")) {
    const model::Physical length = input::read_length_scale(*R);  // (read_map_inputs has checked it)
    map.R = input::format_axis_value(length.number) + " " + std::string(length.unit->name);
    map.R_m = length.si();
  }
  const std::size_t G = map.geometries(), P = map.load_points();
  if (in.check_sample > 0) {
    const std::uint64_t points = static_cast<std::uint64_t>(G) * P;
    if (in.check_sample > points) {
      throw input::UsageError("--check-sample = " + std::to_string(in.check_sample) + ": valid: 1 to the map's " +
                              std::to_string(points) + " load points (" + std::to_string(G) + " geometries x " +
                              std::to_string(P) + ")");
    }
    map.check_sample = in.check_sample;
    map.check_seed = in.check_seed;
    check_.emplace(points, in.check_sample, in.check_seed);
  }
  // Up front, what the map asks: a load curve per geometry (seconds to minutes each), and
  // every point's values held on rank 0 until the file is written.
  if (G > kMaxGeometries) {
    throw input::UsageError("the map has " + std::to_string(G) + " geometries, each its own load curve (seconds to minutes): at most " +
                            std::to_string(kMaxGeometries) + " in one map; split the geometry axes over several maps");
  }
  if (static_cast<double>(P) > kMaxLoadPoints) {
    throw input::UsageError("the map has " + std::to_string(P) + " load points a geometry, beyond " + input::json_number(kMaxLoadPoints) +
                            " (a tile of them travels whole between ranks and into the journal): split the load's axes over "
                            "several maps");
  }
  // Every geometry's texture read as `surface` reads it, before any curve is built: a
  // missing or bad option, a scale or a grid beyond the engine is refused here (exit 2,
  // nothing written), not by the rank that meets it in the middle of the run.
  seconds_.assign(G, 0.0);
  std::size_t times = 0;
  for (std::size_t g = 0; g < G; ++g) {
    try {
      const SurfaceCheck check = check_surface(keywords_of(g));
      seconds_[g] = check.seconds;
      times = check.times;
    } catch (const input::UsageError& e) {
      throw input::UsageError("geometry " + std::to_string(g + 1) + " (" + describe(g) + "): " + e.what());
    }
  }
  // Tiles of whole rows of the first load axis (the pressure), as many as hold about
  // `chunk` values of a quantity over load points and times, one row at the least.
  times_ = times;
  const std::size_t row_values = map.points_per_row() * (map.full ? std::max<std::size_t>(times, 1) : 1);
  map.tile_rows = std::clamp<std::size_t>(in.chunk / row_values, 1, map.load.front().values.size());
}

TextureMapPlan::~TextureMapPlan() = default;

SurfaceMap::LengthUnit SurfaceMap::length_unit() const {
  const std::size_t space = R.find(' ');
  if (space == std::string::npos) return {};
  return {std::stod(R.substr(0, space)), R.substr(space + 1)};
}

std::string TextureMapPlan::describe(std::size_t g) const {
  std::ostringstream line;
  const std::vector<std::size_t> at = digits_of(g, sizes_of(header_.geometry));
  if (header_.geometry.empty()) return "the texture as given: no geometry axis";
  const auto [per_R, unit] = header_.length_unit();
  for (std::size_t d = 0; d < header_.geometry.size(); ++d) {
    const SurfaceMapAxis& axis = header_.geometry[d];
    const bool length = axis.scale == "R";
    line << (d ? ", " : "") << axis.name << " = " << axis.values[at[d]] * (length ? per_R : 1.0) << (length ? " " + unit : "");
  }
  return line.str();
}

std::vector<std::size_t> TextureMapPlan::dealing_order(int ranks) const {
  std::vector<std::size_t> geometries(seconds_.size());
  for (std::size_t g = 0; g < geometries.size(); ++g) geometries[g] = g;
  std::stable_sort(geometries.begin(), geometries.end(), [&](std::size_t a, std::size_t b) { return seconds_[a] > seconds_[b]; });
  // In waves of `ranks` geometries: their first tiles (each a curve to build), then the
  // rest of their tiles a geometry after another (each read off a curve built by then, or
  // being built: from the table cache, where the build holds its lock).
  const std::size_t per = header_.tiles_per_geometry(), wave = static_cast<std::size_t>(std::max(ranks, 1));
  std::vector<std::size_t> order;
  order.reserve(geometries.size() * per);
  for (std::size_t begin = 0; begin < geometries.size(); begin += wave) {
    const std::size_t end = std::min(begin + wave, geometries.size());
    for (std::size_t k = begin; k < end; ++k) order.push_back(geometries[k] * per);
    for (std::size_t k = begin; k < end; ++k) {
      for (std::size_t t = 1; t < per; ++t) order.push_back(geometries[k] * per + t);
    }
  }
  return order;
}

input::Keywords TextureMapPlan::keywords_of(std::size_t g) const {
  const MapInputs& in = *in_;
  const SurfaceMap& map = header_;
  const double least_pbar = *std::min_element(in.load[0].values.begin(), in.load[0].values.end());
  // The geometry's keywords: the texture's, its lengths, and the least pressure (the grid
  // --grid auto picks is the one the smallest spot asks) at the law's first values.
  input::Keywords keywords = in.texture;
  const std::vector<std::size_t> at = digits_of(g, sizes_of(map.geometry));
  for (std::size_t d = 0; d < map.geometry.size(); ++d) {
    const double v = map.geometry[d].values[at[d]];
    if (map.geometry[d].name == model::kScatterWidth) {
      keywords.emplace_back("scatter", in.scatter_kind + ":" + text_of(v));
    } else {
      keywords.emplace_back(map.geometry[d].name, text_of(v));
    }
  }
  keywords.emplace_back("pbar", text_of(least_pbar));
  for (std::size_t a = 1; a < in.load.size(); ++a) {  // the law's (the curve is elastic: no ramp)
    if (in.load_coordinates[a].coordinate == model::Coordinate::law) {
      keywords.emplace_back(in.load[a].name, text_of(in.load[a].values.front()));
    }
  }
  return keywords;
}

namespace {

/// Load point p of a map of `run`'s texture: its point with the load axes' values put in,
/// its law and load.
struct LoadPoint {
  model::PointValues point;
  std::unique_ptr<model::CreepLaw> creep;
  std::optional<model::CreepWeightedLoad> load;
};
LoadPoint load_point(const MapInputs& in, const SurfaceMap& map, const SurfaceRun& run, std::size_t p) {
  LoadPoint out{{run.inputs.problem, run.inputs.law_values}, nullptr, std::nullopt};
  const std::vector<std::size_t> digits = digits_of(p, sizes_of(map.load));
  for (std::size_t a = 0; a < map.load.size(); ++a) {
    model::set_coordinate(in.load_coordinates[a], map.load[a].values[digits[a]], &out.point);
  }
  out.creep = model::make_creep_law(*in.spec, out.point.law);
  out.load.emplace(*out.creep, out.point.problem.pbar0, out.point.problem.loading);
  return out;
}

}  // namespace

MoreLoadPoints TextureMapPlan::load_points() const {
  const MapInputs& in = *in_;
  const SurfaceMap& map = header_;
  const std::size_t P = map.load_points();
  MoreLoadPoints out;
  // The curve reaches the largest X(inf) of them all: the same for every geometry (a load
  // point's law and load are the load axes' and the texture's keywords), so found once.
  out.X_reach = [&in, &map, P, this](const SurfaceRun& run) {
    if (!reach_) {
      double X = 0.0;
      for (std::size_t p = 0; p < P; ++p) X = std::max(X, load_point(in, map, run, p).load->final());
      reach_ = X;
    }
    return *reach_;
  };
  // --grid auto holds every load point's t* (not only the least pressure's, which sizes
  // the grid): a level whose touch load the grid moves by a little moves t* most where the
  // creep-weighted load reaches it slowly.
  out.touches = [&in, &map, P](const SurfaceRun& run, const model::LoadCurve& curve) {
    std::vector<std::vector<model::LevelTouch>> rows;
    rows.reserve(P);
    for (std::size_t p = 0; p < P; ++p) rows.push_back(model::level_touches(curve, *load_point(in, map, run, p).load));
    return rows;
  };
  return out;
}

const TextureMapPlan::Opened& TextureMapPlan::open(std::size_t g, bool* held) const {
  *held = last_ && last_->geometry == g;
  if (*held) return *last_;
  last_.reset();  // (its curve and cell freed before the next is built)
  const auto start = std::chrono::steady_clock::now();
  SurfaceRun run = evaluate_surface(keywords_of(g), load_points());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  last_ = std::make_unique<Opened>(Opened{g, std::move(run), seconds});
  return *last_;
}

std::vector<double> TextureMapPlan::evaluate(std::size_t u) const {
  const MapInputs& in = *in_;
  const SurfaceMap& map = header_;
  const SurfaceMap::Tile tile = map.tile(u);
  const std::size_t g = tile.geometry;
  const std::vector<std::size_t> load_sizes = sizes_of(map.load);
  const std::size_t P = map.load_points();
  const input::Keywords keywords = keywords_of(g);

  // The geometry's run: this process's own where its last tile was of the same geometry,
  // else its curve built, read from the table cache (where another rank built it: the same
  // bits) or off the periodic tables.
  bool held = false;
  const Opened& opened = open(g, &held);
  const SurfaceRun& run = opened.run;
  const std::size_t L = static_cast<std::size_t>(run.curve.levels());
  // The tile's block: a map of this one geometry and the tile's rows of the first load axis.
  SurfaceMap block = map;
  for (SurfaceMapAxis& axis : block.geometry) axis.values.resize(1);
  {
    std::vector<double>& rows = block.load.front().values;
    const std::size_t first = tile.first / map.points_per_row(), count = tile.count / map.points_per_row();
    rows = std::vector<double>(rows.begin() + static_cast<std::ptrdiff_t>(first), rows.begin() + static_cast<std::ptrdiff_t>(first + count));
  }
  block.levels = run.curve.levels();
  block.caps = run.geometry.sites.size();
  block.times = run.times;
  size_arrays(block);
  block[kGrid][0] = run.curve.nx;
  block[kFromTables][0] = run.curve_source == CurveSource::tables ? 1 : 0;
  // Each level's touchdown load and whether the curve resolves it: the geometry's alone,
  // as the run read them.
  for (std::size_t level = 0; level < L; ++level) {
    block[kXStar][level] = run.history.levels[level].X_star;
    block[kResolved][level] = run.history.levels[level].resolved ? 1 : 0;
  }
  // Each load point of the tile off the curve: the map's p, the block's p - tile.first.
  const std::size_t T = block.times.size();
  for (std::size_t p = 0; p < tile.count; ++p) {
    const LoadPoint at_p = load_point(in, map, run, tile.first + p);
    const model::PointValues& point = at_p.point;
    const model::CreepWeightedLoad& load = *at_p.load;
    const std::vector<model::LevelTouch> touches = model::level_touches(run.curve, load);
    for (std::size_t level = 0; level < L; ++level) {
      block[kTStar][p * L + level] = touches[level].t_star;
      block[kRegime][p * L + level] = static_cast<std::int8_t>(touches[level].regime);
    }
    if (!in.tolerance.empty()) {
      // The box about this point (each tolerance about its own value here), each level's
      // t* at its corners (model::level_t_star_ranges, as surface --tolerance).
      std::vector<model::Tolerance> box;
      for (std::size_t k = 0; k < in.tolerance.size(); ++k) {
        const model::PointAxis& c = in.tolerance_coordinates[k];
        box.push_back(in.tolerance[k].at(c.coordinate == model::Coordinate::pressure ? point.problem.pbar0
                                                                                     : point.law[c.law_index]));
      }
      const model::SurfaceLoad surface_load{point.problem.pbar0, in.spec, point.law, point.problem.loading};
      std::vector<model::TStarRange> ranges;
      try {
        ranges = model::level_t_star_ranges(run.curve, surface_load, box);
      } catch (const std::invalid_argument&) {
        // A corner outside a parameter's range (T < 1): NaN, not computed, as a sweep's map.
      }
      for (std::size_t level = 0; level < ranges.size(); ++level) {
        const model::TStarRange& r = ranges[level];
        if (r.not_computed > 0) continue;
        block[kTStarLow][p * L + level] = r.low;
        block[kTStarHigh][p * L + level] = r.high;
        block[kRegimeLow][p * L + level] = static_cast<std::int8_t>(r.regime_low);
        block[kRegimeHigh][p * L + level] = static_cast<std::int8_t>(r.regime_high);
      }
    }
    const double X0 = load.initial();
    // Each level's contact radius and advisories by the last time (surface's, per level):
    // in every map, as every answer carries them.
    if (T > 0) {
      const double t_last = block.times[T - 1];
      const model::SurfaceAdvisories advice = model::advise_surface(run.geometry, run.curve.at(t_last > 0.0 ? load(t_last) : X0));
      for (std::size_t level = 0; level < L; ++level) {
        block[kContactRadius][p * L + level] = advice.level[level].a_max;
        block[kAdvised][p * L + level] = advice.level[level].raised.empty() ? 0.0 : 1.0;
      }
    }
    // What the snapshot times read (a map of full quantities).
    if (!map.full) continue;
    for (std::size_t k = 0; k < T; ++k) {
      const double t = block.times[k];
      const model::CurveState state = run.curve.at(t > 0.0 ? load(t) : X0);
      const model::SurfaceValidity validity = model::reading_validity(run.curve, X0, state);
      block[kValid][p * T + k] = static_cast<std::int8_t>(validity);
      block[kTouched][p * T + k] = state.sites_touched;
      block[kAreaFraction][p * T + k] = state.range == model::CurveRange::above_top ? kNaN : state.area_fraction;
      for (std::size_t level = 0; level < L; ++level) {
        block[kLevelTouched][(p * T + k) * L + level] = state.level_sites_touched[level];
        block[kLevelArea][(p * T + k) * L + level] = state.level_area[level];
      }
    }
    // Each level's load, by the load's history (surface's: model::surface_history).
    const model::SurfaceHistory history = model::surface_history(run.curve, load, block.times);
    for (std::size_t k = 0; k < T; ++k) {
      for (std::size_t level = 0; level < L; ++level) {
        block[kLevelLoad][(p * T + k) * L + level] = history.snapshots[k].level_load[level];
      }
    }
  }
  // The sampled load points of this geometry, each stepped in time on the same cell (as
  // surface --check: the same grid as the curve's).
  std::optional<reference::Cell> check_cell;
  for (std::size_t p = 0; p < tile.count && check_; ++p) {
    if (!check_->contains(static_cast<std::uint64_t>(g) * P + tile.first + p)) continue;
    input::Keywords at_p;
    for (const auto& [key, value] : keywords) {
      const bool load_key = key == "pbar" || std::any_of(in.load.begin(), in.load.end(), [&](const SurfaceMapAxis& a) { return a.name == key; });
      if (!load_key && key != "grid") at_p.emplace_back(key, value);
    }
    const std::vector<std::size_t> digits = digits_of(tile.first + p, load_sizes);
    for (std::size_t a = 0; a < map.load.size(); ++a) {
      const std::string& name = map.load[a].name;
      at_p.emplace_back(name == model::ramp_time_parameter().name ? "ramp" : name, text_of(map.load[a].values[digits[a]]));
    }
    if (run.curve_source == CurveSource::tables) {
      if (const std::string* grid = find(keywords, "grid")) at_p.emplace_back("grid", *grid);
    } else if (find(keywords, "height-map") == nullptr) {
      at_p.emplace_back("grid", std::to_string(run.grid_nodes));  // the curve's own
    }
    at_p.emplace_back("check", "true");
    // On the curve's cell, made once (the sampled points of a geometry share its grid): the
    // curve is not read again. Off the tables the cell's grid is each point's own (auto).
    SurfaceRun checked;
    if (run.curve_source == CurveSource::tables) {
      checked = evaluate_surface(at_p);
    } else {
      if (!check_cell) check_cell = surface_cell(at_p);
      checked = step_surface(at_p, *check_cell);
    }
    const reference::CellReference& stepped = *checked.stepped;
    for (std::size_t level = 0; level < L; ++level) {
      block[kCheckRegime][p * L + level] = static_cast<std::int8_t>(stepped.level_regime[level]);
      block[kCheckTStar][p * L + level] = stepped.level_t_star[level];
      block[kCheckResolution][p * L + level] = checked.check_t_star_resolution;
    }
    for (std::size_t k = 0; k < T && k < stepped.series.size(); ++k) block[kCheckAreaFraction][p * T + k] = stepped.series[k].area_fraction;
  }
  // As it travels: the head, then every array's values as doubles (codes are small integers).
  std::vector<double> values(kHead);
  values[kLevels] = static_cast<double>(L);
  values[kCaps] = static_cast<double>(block.caps);
  values[kE0] = run.inputs.scales.E0_star ? run.inputs.scales.E0_star->si() : 0.0;
  values[kSeconds] = held ? 0.0 : opened.seconds;
  values[kSource] = held ? 3.0 : run.curve_source == CurveSource::tables ? 2.0 : run.curve_cached ? 1.0 : 0.0;
  values[kTimes] = static_cast<double>(T);
  values.insert(values.end(), block.times.begin(), block.times.end());
  for_each_stored(block, [&](std::size_t q, std::size_t) { values.insert(values.end(), block[q].begin(), block[q].end()); });
  return values;
}

double estimated_reading_seconds(std::size_t points, int levels, std::size_t times, bool full) {
  if (!full) return static_cast<double>(points) * (5e-6 + 1e-6 * levels);
  return static_cast<double>(points) * levels * (19e-6 + 16e-6 * static_cast<double>(times));
}

GeometryCost geometry_cost(std::span<const double> block) {
  if (block.size() < kHead) throw std::invalid_argument("a geometry's block shorter than its head");
  const char* source = block[kSource] == 3.0   ? "held from the rank's tile before"
                       : block[kSource] == 2.0 ? "from the periodic tables"
                       : block[kSource] == 1.0 ? "from the cache"
                                               : "built";
  return {block[kSeconds], source, block[kSource] == 3.0};
}

namespace {
/// The keywords that name a file the map reads.
constexpr std::array<const char*, 3> kInputFileKeys{"material", "cell", "height-map"};
}  // namespace

std::vector<std::string> texture_input_files(const input::Keywords& keywords) {
  std::vector<std::string> files;
  for (const char* key : kInputFileKeys) {
    if (const std::string* path = find(keywords, key)) files.push_back(*path);
  }
  return files;
}

namespace {

/// Why the map may not be written to `path` (io::output_file_problem's rule for it and for
/// its .partial, neither of them one of the map's input files, and an existing file without
/// `overwrite`), or empty. An input is refused before the existing file, so that the
/// refusal never invites --overwrite onto an input.
std::string map_output_problem(const std::string& path, bool overwrite, const input::Keywords& keywords) {
  const std::vector<std::string> inputs = texture_input_files(keywords);
  for (const std::string& file : {path, path + ".partial"}) {
    if (std::string problem = io::output_file_problem(file, inputs); !problem.empty()) return problem;
  }
  if (!overwrite && std::filesystem::exists(path)) return path + " exists: give --overwrite to replace it";
  return {};
}
}  // namespace

struct TextureMapWriter::File {
  io::NetcdfFile netcdf;
  explicit File(const std::string& path) : netcdf(path) {}
};

TextureMapWriter::TextureMapWriter(std::string path, SurfaceMap header, bool overwrite, const input::Keywords& keywords)
    : path_(std::move(path)), header_(std::move(header)), written_(header_.tiles(), false) {
  if (const std::string problem = map_output_problem(path_, overwrite, keywords); !problem.empty()) {
    throw input::UsageError(problem);
  }
}

TextureMapWriter::~TextureMapWriter() {
  if (file_) {
    file_.reset();
    std::remove((path_ + ".partial").c_str());
  }
}

void TextureMapWriter::create(std::span<const double> block) {
  SurfaceMap& map = header_;
  map.levels = static_cast<int>(block[kLevels]);
  map.caps = static_cast<std::size_t>(block[kCaps]);
  map.E0_star_Pa = block[kE0];
  map.times.assign(block.begin() + kHead, block.begin() + static_cast<std::ptrdiff_t>(kHead + static_cast<std::size_t>(block[kTimes])));
  file_ = std::make_unique<File>(path_ + ".partial");
  io::NetcdfFile& file = file_->netcdf;
  file.attribute("Conventions", "CF-1.8");
  file.attribute("title", "punchsweep surface map: each level's touch time over a texture's geometry and load");
  file.attribute("texture", map.texture);
  file.attribute("material", map.material);
  // The physical scales as a regime map states them (R, R_m, E0_star_Pa), so that one
  // reader (Python's open_map, the scripts, the explorer) gives every map in kPa and um.
  if (!map.R.empty()) {
    file.attribute("R", map.R);
    file.attribute("R_m", map.R_m);
  }
  if (map.E0_star_Pa > 0.0) file.attribute("E0_star_Pa", map.E0_star_Pa);
  if (!map.scatter_kind.empty()) file.attribute("scatter_kind", map.scatter_kind);
  if (!map.identity.empty()) file.attribute("identity", map.identity);
  if (map.layout_version > 0) file.attribute("layout_version", static_cast<double>(map.layout_version));
  if (map.check_sample > 0) {
    file.attribute("check_sample", static_cast<double>(map.check_sample));
    file.attribute("check_seed", static_cast<double>(map.check_seed));
  }
  file.attribute("time_unit", map.time_unit);
  const auto units = [&](const std::string& scale) -> io::Attributes {
    if (scale == "T_eps" && map.time_unit != "T_eps") return {{"units", map.time_unit}};
    if (scale == "degC") return {{"units", "degC"}};
    if (scale == "1") return {{"units", "1"}};
    return {{"units", "1"}, {"scaled_by", scale}};
  };
  const auto with = [](io::Attributes a, const io::Attributes& more) {
    a.insert(a.end(), more.begin(), more.end());
    return a;
  };
  std::vector<std::string> geometry_dims, load_dims;
  for (const SurfaceMapAxis& a : map.geometry) {
    file.coordinate(a.name, a.values, with(units(a.scale), {{"long_name", a.long_name}}));
    geometry_dims.push_back(a.name);
  }
  for (const SurfaceMapAxis& a : map.load) {
    file.coordinate(a.name, a.values, with(units(a.scale), {{"long_name", a.long_name}}));
    load_dims.push_back(a.name);
  }
  std::vector<double> levels;
  for (int level = 0; level < map.levels; ++level) levels.push_back(level);
  file.coordinate("level", levels, {{"units", "1"}, {"long_name", "level: 0 the tallest caps"}});
  file.coordinate("t", map.times, with(units("T_eps"), {{"long_name", "time since the load was applied"}}));
  // The flag sets' codes and meanings (the model's enums, in code order).
  struct FlagSet {
    std::vector<std::int8_t> codes;
    std::string meanings;  ///< empty: flag_values only
  };
  const auto flag_set = [](map::TextureFlags flags) {
    FlagSet set;
    const auto add = [&set](std::int8_t code, std::string_view name) {
      set.codes.push_back(code);
      if (!name.empty()) set.meanings += std::string(set.meanings.empty() ? "" : " ") + std::string(name);
    };
    switch (flags) {
      case map::TextureFlags::regime_or_not_computed:
        add(kNotComputed, "not_computed");
        [[fallthrough]];
      case map::TextureFlags::regime:
        for (const model::Regime r : {model::Regime::immediate, model::Regime::delayed, model::Regime::never}) {
          add(static_cast<std::int8_t>(r), model::regime_name(r));
        }
        break;
      case map::TextureFlags::surface_validity:
        for (const model::SurfaceValidity v : {model::SurfaceValidity::valid, model::SurfaceValidity::below_resolution,
                                               model::SurfaceValidity::above_top, model::SurfaceValidity::unloading}) {
          add(static_cast<std::int8_t>(v), model::surface_validity_name(v));
        }
        break;
      case map::TextureFlags::yes_no:
        add(0, "");
        add(1, "");
        break;
      case map::TextureFlags::none:
        break;
    }
    return set;
  };
  if (!map.tolerance.empty()) file.attribute("tolerance", map.tolerance);
  const std::string box = " over the box of tolerances (" + map.tolerance + ") about the point";
  for (std::size_t q = 0; q < map::kTextureQuantityCount; ++q) {
    if (!map.stores(q)) continue;
    const map::TextureQuantitySpec& spec = map::kTextureQuantities[q];
    std::vector<std::string> over = geometry_dims;
    using map::TextureExtent;
    if (spec.extent != TextureExtent::geometry && spec.extent != TextureExtent::geometry_level) {
      over.insert(over.end(), load_dims.begin(), load_dims.end());
    }
    if (spec.extent == TextureExtent::load_time || spec.extent == TextureExtent::load_time_level) over.emplace_back("t");
    if (spec.extent != TextureExtent::geometry && spec.extent != TextureExtent::load_time) over.emplace_back("level");
    const std::string long_name = std::string(spec.long_name) + (spec.stored == map::TextureStored::tolerance ? box : "");
    // One tile a slab (and a chunk): a geometry's tile_rows of the first load axis; the
    // map arrives, and is written, a tile at a time.
    const std::size_t rows = over_load(spec.extent) ? map.tile_rows : 0;
    if (spec.flags == map::TextureFlags::none) {
      file.declare(std::string(spec.name), over, geometry_dims.size(), false, kNaN,
                   with(units(std::string(spec.scale)), {{"long_name", long_name}}), {}, rows);
      continue;
    }
    const FlagSet set = flag_set(spec.flags);
    io::Attributes attributes{{"long_name", long_name}};
    if (!set.meanings.empty()) attributes.emplace_back("flag_meanings", set.meanings);
    file.declare(std::string(spec.name), over, geometry_dims.size(), true, kNotComputed, attributes, set.codes, rows);
  }
  if (map.E0_star_Pa > 0.0) {
    std::vector<double> pressure;
    for (const double p : map.load.front().values) pressure.push_back(p * map.E0_star_Pa);
    file.variable("pressure", {"pbar"}, pressure, {{"units", "Pa"}, {"long_name", "nominal pressure"}});
  }
}

void TextureMapWriter::write(std::size_t u, std::span<const double> block) {
  const auto refuse = [u](const std::string& why) {
    return std::invalid_argument("tile " + std::to_string(u) + "'s block " + why);
  };
  if (u >= written_.size()) throw refuse("lies outside the map's " + std::to_string(written_.size()) + " tiles");
  if (block.size() < kHead || block.size() < kHead + static_cast<std::size_t>(block[kTimes])) throw refuse("is shorter than its head");
  const std::size_t T = static_cast<std::size_t>(block[kTimes]);
  if (!file_) create(block);
  const SurfaceMap& map = header_;
  const int levels = static_cast<int>(block[kLevels]);
  if (levels != map.levels) {
    throw input::UsageError("the geometries have different numbers of levels (" + std::to_string(map.levels) + " and " +
                            std::to_string(levels) + "): a map's geometries share their levels");
  }
  if (!std::equal(map.times.begin(), map.times.end(), block.begin() + kHead, block.begin() + static_cast<std::ptrdiff_t>(kHead + T)) ||
      T != map.times.size()) {
    throw refuse("has other snapshot times than the map's");
  }
  const SurfaceMap::Tile tile = map.tile(u);
  std::size_t expected = kHead + T;
  for_each_stored(map, tile.count, [&expected](std::size_t, std::size_t n) { expected += n; });
  if (block.size() != expected) {
    throw refuse("holds " + std::to_string(block.size()) + " values where the map's tile has " + std::to_string(expected));
  }
  const std::vector<std::size_t> at = digits_of(tile.geometry, sizes_of(map.geometry));
  // The tile's rows of the first load axis, in the quantities over the load.
  const io::NetcdfFile::Rows rows{tile.first / map.points_per_row(), tile.count / map.points_per_row()};
  std::size_t k = kHead + T;
  for_each_stored(map, tile.count, [&](std::size_t q, std::size_t n) {
    file_->netcdf.write_slab(std::string(map::kTextureQuantities[q].name), at, block.subspan(k, n),
                             over_load(map::kTextureQuantities[q].extent) ? rows : io::NetcdfFile::Rows{});
    k += n;
  });
  written_[u] = true;
}

void TextureMapWriter::finish() {
  const auto missing = std::find(written_.begin(), written_.end(), false);
  if (missing != written_.end()) {
    throw std::logic_error("the map is finished without tile " + std::to_string(missing - written_.begin()));
  }
  file_->netcdf.close();
  file_.reset();
  std::filesystem::rename(path_ + ".partial", path_);
}

void write_texture_map(const input::Keywords& keywords, const std::string& path, bool overwrite, bool progress) {
  const TextureMapPlan plan(keywords);
  SurfaceMap header = plan.header();
  header.identity = run::join(texture_map_identity(keywords), "\n");
  TextureMapWriter writer(path, std::move(header), overwrite, keywords);
  const std::size_t G = plan.geometries();
  for (const std::size_t u : plan.dealing_order(1)) {
    const std::vector<double> block = plan.evaluate(u);
    writer.write(u, block);
    const GeometryCost cost = geometry_cost(block);
    if (progress && !cost.held) {
      const std::size_t g = plan.header().tile(u).geometry;
      std::cerr << "punchsweep surface-map: geometry " << g + 1 << " of " << G << " (" << plan.describe(g) << "): curve "
                << cost.source << " in " << cost.seconds << " s\n";
    }
  }
  writer.finish();
}

/// The map's own options (where and how to write, the time-stepping sample) and surface's.
po::options_description texture_map_options(const input::PointMaterial& material) {
  po::options_description own("The map's own options");
  own.add_options()
      ("output", po::value<std::string>()->value_name("FILE"), "the map to write (netCDF-4): required")
      ("overwrite", po::bool_switch(), "replace FILE where it exists")
      ("resume", po::bool_switch(), "finish the map an interrupted run left (its journal FILE.partial.journal), "
                                   "computing only the geometries it lacks")
      ("quiet", po::bool_switch(), "no progress lines")
      ("check-sample", po::value<std::string>()->value_name("K"),
       "step the same cell in time (surface --check) at K load points of the map drawn at random, into "
       "check_regime, check_t_star, check_area_fraction")
      ("check-seed", po::value<std::string>()->value_name("S")->default_value("1"), "the seed of --check-sample's draw")
      ("quantities", po::value<std::string>()->value_name("WHAT"),
       "regime: each level's touch and advisories alone (t_star, regime, X_star, resolved, contact_radius, advised; "
       "reads in a fraction of the time); full (the default): also what each snapshot time reads (caps and areas in "
       "contact, each level's load)")
      ("chunk", po::value<std::string>()->value_name("N"),
       "the target values of a tile, the unit of work, of the journal and of an HDF5 chunk: load points x snapshot "
       "times, in whole rows of the pressure axis (at least one); 4096 by default");
  po::options_description opts;
  opts.add(own).add(surface_options(material));
  return opts;
}

std::vector<std::string> texture_map_identity(const input::Keywords& keywords) {
  // A file's content, not its path (as a regime map's material): the same file moved, or
  // copied into a job's run folder, is the same map.
  const auto file_text = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream content;
    content << in.rdbuf();
    if (!in) return path;  // (unreadable: the plan refuses it by name)
    const std::string bytes = content.str();
    char hex[9];
    std::snprintf(hex, sizeof hex, "%08x", io::crc32(bytes.data(), bytes.size()));
    return std::filesystem::path(path).filename().string() + " (file crc32 " + hex + ")";
  };
  std::vector<std::string> lines;
  for (const auto& [key, value] : keywords) {
    const bool file = std::find(kInputFileKeys.begin(), kInputFileKeys.end(), key) != kInputFileKeys.end();
    lines.push_back(key + " = " + (file ? file_text(value) : value));
  }
  std::sort(lines.begin(), lines.end());
  lines.insert(lines.begin(), "layout_version = " + std::to_string(map::kTextureLayoutVersion));
  return lines;
}

void check_texture_keywords(const input::Keywords& keywords, const std::vector<std::string>& origins) {
  const po::options_description opts = texture_map_options(input::find_point_material(keywords));
  for (std::size_t k = 0; k < keywords.size(); ++k) {
    const std::string& key = keywords[k].first;
    if (is_map_run_keyword(key) || opts.find_nothrow(key, false) == nullptr || key == "help") {
      std::string known;
      for (const auto& option : opts.options()) {
        const std::string& name = option->long_name();
        if (!is_map_run_keyword(name) && name != "help") known += (known.empty() ? "" : ", ") + name;
      }
      const std::string& origin = k < origins.size() ? origins[k] : key;
      throw input::UsageError("unknown key " + origin + " (a texture's map takes surface's options, '_' for '-': " + known + ")");
    }
  }
}

std::string surface_map_file(const input::Keywords& keywords) {
  const std::string* output = find(keywords, kOutput);
  if (!output) throw input::UsageError("surface_map: output is required");
  const std::string* overwrite_text = find(keywords, kOverwrite);
  const bool overwrite = overwrite_text && *overwrite_text == "true";
  // The output is checked before any curve is built, and again as it is written.
  if (const std::string problem = map_output_problem(*output, overwrite, keywords); !problem.empty()) {
    throw input::UsageError(problem);
  }
  input::Keywords texture;
  for (const auto& [key, value] : keywords) {
    if (!is_map_run_keyword(key)) texture.emplace_back(key, value);
  }
  write_texture_map(texture, *output, overwrite, false);
  return *output;
}

}  // namespace punchsweep::engine
