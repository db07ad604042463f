#include "engine/surface_evaluation.hpp"

#include <boost/program_options.hpp>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>
#include <utility>

#include "engine/curve_cache.hpp"
#include "input/cell_file.hpp"
#include "input/height_map.hpp"
#include "input/scaled_value.hpp"
#include "input/usage_error.hpp"
#include "input/value_parsing.hpp"
#include "model/numerics/number_text.hpp"
#include "model/periodic/periodic_model.hpp"
#include "model/surface/periodic_curve.hpp"
#include "model/surface/small_spot_touchdown.hpp"
#include "model/surface/surface_sensitivity.hpp"
#include "reference/cell_stepping.hpp"
#include "reference/load_curve.hpp"
#include "reference/measured_cell.hpp"
#include "reference/reference_point.hpp"
#include "reference/periodic_grid.hpp"
#include "sweep/reproducible_fft.hpp"

namespace po = boost::program_options;

namespace punchsweep::engine {

double machine_bytes() {
  static const double bytes = [] {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
    return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
  }();
  return bytes;
}

std::string seconds_text(double s) {
  std::ostringstream out;
  out.precision(s < 10.0 ? 2 : 3);
  out << s << " s";
  return out.str();
}

namespace {

/// The one line on stderr that says where a curve's build stands: the share of its load range
/// done (reference::LoadCurveProgress::fraction, from the first load up to full contact, known
/// before the first solve), the solves and seconds so far and the seconds left. Those blend
/// two guesses by the share f done: (1 - f) times the cost model's (estimated_curve_seconds,
/// --dry-run's, less the time spent) and f times the rate so far's (elapsed (1 - f) / f).
/// The rate alone says too little early, the upper range being dearer (the deeper levels'
/// touchdowns are bisected there): on a hexagonal three-level curve of 7.1 s it said 1.3 s
/// left at 2 s, the blend 4.6 s (5.1 s were left); on a scattered 3 x 3 supercell's of
/// 35 s, the blend 8.7 s at 12.8 s (22 s were left: its caps' touchdowns crowd at 62-76%).
/// Silent for a curve done within kQuiet; on a terminal the line is rewritten in place (at
/// most every kRedraw), in a log one line at each tenth of the range passed.
class CurveProgressLine {
 public:
  /// `grid`: the curve's ("N nodes a pitch", or a measured map's "nx x ny pixels").
  CurveProgressLine(std::string grid, double estimated_seconds)
      : grid_(std::move(grid)), estimated_(estimated_seconds), tty_(::isatty(::fileno(stderr)) != 0) {}
  CurveProgressLine(const CurveProgressLine&) = delete;
  CurveProgressLine& operator=(const CurveProgressLine&) = delete;
  ~CurveProgressLine() {
    if (drawn_) std::cerr << "\n" << std::flush;  // ends the rewritten line
  }

  void operator()(const reference::LoadCurveProgress& p) {
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (elapsed < kQuiet) return;
    const double f = p.fraction();
    const int tenth = static_cast<int>(10.0 * f);
    if (tty_ ? std::chrono::duration<double>(now - last_).count() < kRedraw : tenth <= tenth_) return;
    last_ = now;
    tenth_ = tenth;
    std::ostringstream line;
    line << "punchsweep surface: load curve on " << grid_ << ": " << static_cast<int>(100.0 * f)
         << "% of the load range to " << (p.X_full < p.X_full_contact ? "the loads' reach" : "full contact") << " (X = "
         << std::min(p.X_front, p.X_full) << " of " << p.X_full << " E0*), " << p.solves << " solves in " << seconds_text(elapsed);
    if (f >= 0.02) {
      // (The model's seconds are a whole curve's: a curve stopped at the loads' reach is
      // given its share of the range in log X.)
      const double by_rate = elapsed * (1.0 - f) / f, by_model = std::max(estimated_ * p.range_share() - elapsed, 0.0);
      line << ", about " << seconds_text((1.0 - f) * by_model + f * by_rate) << " left";
    }
    if (tty_) {
      std::cerr << "\r" << line.str() << "\033[K" << std::flush;
      drawn_ = true;
    } else {
      std::cerr << line.str() << "\n";
    }
  }

 private:
  static constexpr double kQuiet = 2.0;   // s
  static constexpr double kRedraw = 0.5;  // s
  std::string grid_;
  double estimated_;  ///< the cost model's seconds for the whole curve
  bool tty_;
  bool drawn_ = false;
  int tenth_ = -1;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_{};
};

/// --grid auto: the least nodes a pitch that give the
/// smallest spot the times meet a radius of kAutoSpotRadius node spacings, within
/// [kAutoMin, kAutoMaxNodes] (past it the snapshots below the curve's resolution are flagged).
constexpr int kAutoMin = 64;
constexpr double kAutoSpotRadius = 13.0;  // a spacing past the curve's first sample (12)
/// --grid auto resolves the spots at this share of the small-spot limit's reach (where it
/// answers the cell), so that the curve's resolved part starts within the reach (its
/// first load at least a step of the limit's loads, a sixteenth of a decade, below it).
constexpr double kAutoLimitHandOver = 0.5;
/// --grid auto's least nodes a pitch where the small-spot limit reads every time's load (the
/// curve is held to the grid of half of them).
constexpr int kAutoLeast = 16;
/// --grid auto's accuracy of an area fraction (the stated 1%), its error estimated as
/// kAutoAreaMoveShare of its move from the grid of half the nodes.
constexpr double kAutoAreaAccuracy = 1e-2;
constexpr double kAutoAreaMoveShare = 0.5;
/// The budget of one curve: at most kMaxNodes nodes (a 4096 x 4096 height map; the
/// boundary elements hold about kBytesPerNode a node, measured: 68 MB for 512 x 512), and
/// nodes x caps at most kMaxNodeCaps (measured: an 8 x 8 two-level supercell, 128 caps on
/// 512 x 512 nodes, 3.4e7 node-caps, took 470 s on one core; the budget is some 30 times that).
constexpr double kMaxNodes = 4096.0 * 4096.0;
/// The scales the boundary elements take (scale_problem): cell lengths and the relief over
/// the cell, in R.
constexpr double kMinCellLength = 1e-6, kMaxCellLength = 1e6;
constexpr double kMinRelief = 1e-30, kMaxRelief = 1e8;
constexpr double kBytesPerNode = 260.0;
/// From this many nodes a curve's setup is said on stderr, with its memory.
constexpr double kLargeGrid = 1048576.0;
constexpr double kMaxNodeCaps = 1073741824.0;  // 2^30
/// A curve may take at most this share of the machine's memory (the rest: the system, other
/// ranks' curves, the map).
constexpr double kMachineShare = 0.8;
/// estimated_curve_seconds' power law: seconds = scale x nodes^node_power x caps^cap_power,
/// times `mirrored` on a grid solved as its quarter and `mirrored_x` as its half. Fitted to
/// 17 whole curves built on one thread here (square, hexagonal, three levels, 2x2 and 4x4
/// scattered supercells; 1024 to 262144 nodes, 2 to 32 caps; 0.05 to 14 s), after the
/// bracketed warm starts (467c182): each within a factor 1.42 of its estimate
/// (docs/performance.md, "A curve's cost"). On more threads a curve takes less.
constexpr double kCurveSecondsScale = 5.54e-5, kCurveSecondsNodePower = 1.047, kCurveSecondsCapPower = 0.175,
                 kCurveSecondsMirrored = 0.410, kCurveSecondsMirroredX = 0.696;
/// The largest supercell: K x K lattice cells.
constexpr int kMaxSupercell = 32;
/// The most draws of an ensemble (--seeds): each its own curve.
constexpr int kMaxSeeds = 1000;
/// The least draws --target-error takes before it judges the standard errors.
constexpr int kLeastDraws = 4;
/// The most caps --part-caps takes (a part's: a square metre of 1 um caps).
constexpr std::uint64_t kMaxPartCaps = 1000000000000000ULL;

/// --scatter's text: normal:SD, uniform:HALFWIDTH (lengths, >= 0) or list:V1,V2,...
/// A scatter's text (`option`'s): normal:SD, uniform:HALFWIDTH (>= 0) or list:V1,V2,...,
/// each value read by `value` (a length for --scatter, a pure number for
/// --curvature-scatter, whose `what` says which).
template <class Value>
model::HeightScatter read_scatter(const std::string& text, const std::string& option, const std::string& what, Value value) {
  const std::string valid = "normal:SD, uniform:HALFWIDTH (" + what + " >= 0) or list:V1,V2,...";
  const std::size_t colon = text.find(':');
  const std::string kind = text.substr(0, colon), rest = colon == std::string::npos ? "" : text.substr(colon + 1);
  model::HeightScatter out;
  if (kind == "normal" || kind == "uniform") {
    out.kind = kind == "normal" ? model::HeightScatter::Kind::normal : model::HeightScatter::Kind::uniform;
    out.width = value(rest);
    if (!(std::isfinite(out.width) && out.width >= 0.0)) {
      throw input::UsageError(option + " = '" + text + "' is outside its range: " + valid);
    }
  } else if (kind == "list") {
    out.kind = model::HeightScatter::Kind::list;
    std::stringstream items(rest);
    for (std::string item; std::getline(items, item, ',');) {
      const double v = value(item);
      if (!std::isfinite(v)) throw input::UsageError(option + " = '" + text + "': " + item + " is not finite");
      out.values.push_back(v);
    }
  } else {
    throw input::UsageError(option + " = '" + text + "' is not one of: " + valid);
  }
  return out;
}

model::HeightScatter read_height_scatter(const std::string& text, const input::PhysicalScales& scales) {
  return read_scatter(text, "--scatter", "a length", [&](const std::string& v) { return input::read_length(v, scales, "--scatter"); });
}

model::HeightScatter read_curvature_scatter(const std::string& text) {
  return read_scatter(text, "--curvature-scatter", "a pure number", [&](const std::string& v) {
    return input::parse_real(v, "--curvature-scatter");
  });
}

}  // namespace

po::options_description surface_options(const input::PointMaterial& material) {
  po::options_description opts(
      "punchsweep surface: when each level of a periodic texture touches a creeping material, and\n"
      "the contact areas in time, from the elastic load curve of the texture's cell (boundary\n"
      "elements continued from first to full contact; docs/model.md, section 17).\n\n"
      "Units: lengths in R (punch size), pressures in E0* = E0/(1-nu^2), areas in R^2 and loads\n"
      "in R^2 E0* per cell, time in T_eps (creep time), or in the material file's time_unit.\n\nOptions");
  input::add_point_options(opts, material.spec);
  input::add_material_options(opts);
  input::add_tolerance_option(opts);
  opts.add_options()
      ("lattice", po::value<std::string>()->value_name("KIND")->default_value("square"),
       "square: level 1 at the squares' centres, level 2 at the edges' midpoints; hexagonal: the "
       "densest packing, level 1 at the triangles' centres (with --dh2: the upward ones, level 2 the "
       "downward ones)")
      ("dh2", po::value<std::string>()->value_name("DH2"),
       "a third level, this far below the tallest tips (R, or a length with --R); >= 0")
      ("cell", po::value<std::string>()->value_name("FILE"),
       "any rectangular periodic cell instead of a lattice: a [cell] file of Lx, Ly, s, C and one "
       "'site = x, y, drop, level[, s, C]' line per punch (docs/cli.md); --grid then counts nodes along Lx")
      ("height-map", po::value<std::string>()->value_name("FILE"),
       "a measured period of a texture: a height map (CSV rows along y, a 2-D float .npy, or the NetCDF "
       "file SurfaceTopography's to_netcdf writes, its lengths and unit read from it), one "
       "boundary-element node per pixel (an even count each way); its summits are the caps followed")
      ("pixel", po::value<std::string>()->value_name("SIZE"),
       "the height map's pixel (a length: 0.5um with --R, or in R); a NetCDF map that states its lengths gives it")
      ("height-unit", po::value<std::string>()->value_name("UNIT")->default_value("R"),
       "the unit of the map's heights: R, or a length unit with --R (um, nm)")
      ("summit-radius", po::value<std::string>()->value_name("L"),
       "a summit is higher than every pixel within this length (default 3 pixels)")
      ("prominence", po::value<std::string>()->value_name("H"),
       "a summit must rise this high above the highest saddle on any path to higher ground (a length; "
       "0 keeps every summit; default 2% of the map's height range, so that land roughness is no cap)")
      ("level-gap", po::value<std::string>()->value_name("L"),
       "summits sorted by depth start a new level where the depth jumps by more than L (default: one level)")
      ("supercell", po::value<int>()->value_name("K")->default_value(1),
       "K x K lattice cells as one periodic cell, each cap's height scattered by --scatter: an integer "
       "in [1, 32]")
      ("scatter", po::value<std::string>()->value_name("DIST"),
       "each cap's height change (a positive one lowers the cap): normal:SD, uniform:HALFWIDTH (lengths "
       "in R, or with a unit and --R; >= 0) or list:V1,V2,... (one per cap of the supercell, in R); "
       "needs --supercell")
      ("curvature-scatter", po::value<std::string>()->value_name("DIST"),
       "each cap's curvature change in the supercell, relative: its C becomes C (1 + d) (a paraboloid's tip radius "
       "over 1 + d): normal:SD, uniform:HALFWIDTH (pure numbers >= 0, the half-width below 1) or list:D1,D2,... "
       "(one per cap); drawn after --scatter's heights from the same --seed; needs --supercell")
      ("part-caps", po::value<std::string>()->value_name("N"),
       "the caps of the whole part the supercell samples: how far its tallest tip would lie above the tall caps' "
       "design height (median and 5-95%) from --scatter's distribution, beside the supercell's own; a whole number "
       "in [1, 1e15]; needs --scatter normal or uniform")
      ("seed", po::value<std::string>()->value_name("N")->default_value("1"),
       "the seed of --scatter's draws, an integer in [0, 2^64-1] (std::mt19937_64, fully specified: the same seed gives the same caps)")
      ("seeds", po::value<int>()->value_name("N")->default_value(1),
       "an ensemble: the scatter drawn with seeds --seed to --seed + N - 1 (each its own supercell and curve); "
       "each level's touch times of its first, median and last cap and each time's area fraction and shares of "
       "caps in contact as their mean, standard deviation, standard error and 5-95% band over the draws: an "
       "integer in [1, 1000]; N > 1 needs --scatter normal or uniform")
      ("target-error", po::value<std::string>()->value_name("E"),
       "with --seeds N: stop drawing once the standard error of every mean share of caps in contact and area "
       "fraction (each level's, at each time) is at most E (a share: 0.01 is one point), after at least 4 draws "
       "and at most N: a number in (0, 1)")
      ("full-curve", po::bool_switch(),
       "build the load curve to full contact; by default it stops at its first sample past the largest "
       "creep-weighted load the question reaches (X(inf) of the pressure, over the tolerances' corners), "
       "which answers the same (a level untouched by then never touches) and a cached curve that reaches "
       "further serves")
      ("check", po::bool_switch(),
       "also step the same cell in time (the time-stepping boundary elements, which assume nothing of the "
       "contact's history) and print its touch times, areas and loads beside the curve's")
      ("curve", po::value<std::string>()->value_name("KIND")->default_value("auto"),
       "where the elastic load curve comes from: tables (the periodic model's, n = 512 with the small-spot "
       "table below: the two-level square lattice only, as `point` reads them), cell (the cell's own "
       "boundary elements), or auto (tables where they answer, else cell; a --grid asks for cell)")
      ("grid", po::value<std::string>()->value_name("N")->default_value("auto"),
       "boundary-element nodes per pitch: an even integer in [4, 2048], or auto (the smallest spot the "
       "times meet spans a radius of 13 nodes; 64 to 512)")
      ("format", po::value<std::string>()->value_name("FMT")->default_value("table"),
       "output format: table, json or csv");
  return opts;
}

int read_grid(const std::string& text) {
  if (text == "auto") return 0;
  int nodes = -1;  // (not an integer: refused below with the option's range)
  try {
    nodes = input::parse_integer(text, "--grid");
  } catch (const input::UsageError&) {
  }
  if (nodes < 4 || nodes > kMaxGridNodes || nodes % 2 != 0) {
    throw input::UsageError("--grid = " + text + " is outside its range: an even integer in [4, " +
                            std::to_string(kMaxGridNodes) + "], or auto");
  }
  return nodes;
}

namespace {

/// A length in R as the user reads it: in R's unit where the run has R, else in R.
std::string measured_length(double value, const input::PhysicalScales& scales) {
  const input::PhysicalUnit unit = input::physical_unit_or_scaled("R", scales);
  return model::number_text(value * unit.per_scaled, 3) + " " + unit.units;
}

/// The note where most of a measured map's summits look like land roughness taken for
/// caps: far below the highest (more than half the map's height range) and rising little
/// above their saddles (less than a tenth of it); "" where they do not.
std::string roughness_note(const reference::MeasuredCell& cell, const input::PhysicalScales& scales) {
  const std::vector<model::Site>& sites = cell.geometry.sites;
  std::size_t rough = 0;
  double least = std::numeric_limits<double>::infinity(), most = 0.0;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    if (sites[k].drop > 0.5 * cell.height_range && cell.prominence[k] < 0.1 * cell.height_range) {
      ++rough;
      least = std::min(least, sites[k].drop);
      most = std::max(most, sites[k].drop);
    }
  }
  if (2 * rough <= sites.size()) return "";
  std::ostringstream note;
  note << rough << " of the map's " << sites.size() << " summits lie " << measured_length(least, scales) << " to "
       << measured_length(most, scales) << " below the highest (more than half its height range, "
       << measured_length(cell.height_range, scales) << ") and rise less than a tenth of that above their saddles: "
       << "land roughness taken for caps? A summit must now rise " << measured_length(cell.least_prominence, scales)
       << " (--prominence); raise it, or --summit-radius, to keep the caps alone";
  return note.str();
}

/// --height-map FILE with --pixel, --height-unit, --summit-radius, --prominence and
/// --level-gap: the measured cell, lengths in R. A NetCDF map that states its lengths and unit gives the
/// pixel and the heights' unit (the options then override it); `notes` gets what the
/// reading says of the map.
reference::MeasuredCell read_measured(const po::variables_map& vm, const input::PhysicalScales& scales,
                                      std::vector<std::string>* notes) {
  const std::string path = vm["height-map"].as<std::string>();
  const input::HeightMap map = input::read_height_map(path);
  notes->insert(notes->end(), map.notes.begin(), map.notes.end());
  const auto read_length = [&](const char* option, const std::string& text) {
    const double value = input::read_length(text, scales, std::string("--") + option);
    if (!(std::isfinite(value) && value > 0.0)) {
      throw input::UsageError(std::string("--") + option + " = " + text + " is outside its range: a length > 0");
    }
    return value;
  };
  // The file's own lengths (a NetCDF map): its pixel, square, in its unit (or in R without one).
  std::optional<std::string> stated_pixel;
  if (map.length_x > 0.0 && map.length_y > 0.0) {
    const double px = map.length_x / static_cast<double>(map.nx), py = map.length_y / static_cast<double>(map.ny);
    if (std::abs(px - py) > 1e-9 * px) {
      throw input::UsageError(path + ": pixels of " + input::json_number(px) + " x " + input::json_number(py) + " " +
                              (map.unit.empty() ? "R" : map.unit) + "; the boundary elements need square pixels");
    }
    stated_pixel = input::json_number(px) + map.unit;
    if (!map.unit.empty() && !scales.R && !vm.count("pixel")) {
      throw input::UsageError(path + ": its lengths and heights are in " + map.unit +
                              ": give --R (the punch's radius of curvature, e.g. 80um) to read them in R");
    }
  }
  if (!vm.count("pixel") && !stated_pixel) {
    throw input::UsageError("--height-map needs --pixel SIZE, the map's pixel (a length: 0.5um with --R, or in R)");
  }
  if (vm.count("pixel") && stated_pixel) {
    notes->push_back("--pixel " + vm["pixel"].as<std::string>() + " replaces the map's own pixel, " + *stated_pixel);
  }
  const double pixel = read_length("pixel", vm.count("pixel") ? vm["pixel"].as<std::string>() : *stated_pixel);
  // The heights' unit: --height-unit where given, else the file's, else R.
  const std::string unit = !vm["height-unit"].defaulted() || map.unit.empty() ? vm["height-unit"].as<std::string>() : map.unit;
  const double per_unit = unit == "R" ? 1.0 : read_length("height-unit", "1" + unit);
  if (map.periodic == 0) {
    notes->push_back(path + " says it is not periodic (x:periodic = 0): the engine repeats it as one period, so its "
                     "opposite edges meet; crop it to a whole period for a texture's answer");
  }
  if (map.nx % 2 != 0 || map.ny % 2 != 0) {
    throw input::UsageError(path + ": " + std::to_string(map.nx) + " x " + std::to_string(map.ny) +
                            " pixels; the boundary elements need an even count each way (crop a row or column)");
  }
  const double radius = vm.count("summit-radius") ? read_length("summit-radius", vm["summit-radius"].as<std::string>()) : 3.0 * pixel;
  if (radius < pixel) throw input::UsageError("--summit-radius is under one pixel: a summit needs neighbours to be above");
  const double gap = vm.count("level-gap") ? read_length("level-gap", vm["level-gap"].as<std::string>())
                                           : std::numeric_limits<double>::infinity();
  std::vector<double> z = map.height;
  for (double& v : z) v *= per_unit;
  const auto [lowest, highest] = std::minmax_element(z.begin(), z.end());
  double prominence = reference::kDefaultProminenceShare * (*highest - *lowest);
  if (vm.count("prominence")) {
    const std::string text = vm["prominence"].as<std::string>();
    prominence = input::read_length(text, scales, "--prominence");
    if (!(std::isfinite(prominence) && prominence >= 0.0)) {
      throw input::UsageError("--prominence = " + text + " is outside its range: a length >= 0");
    }
  }
  reference::MeasuredCell cell = reference::make_measured_cell(z, map.nx, map.ny, pixel, radius, gap, prominence);
  if (const std::string note = roughness_note(cell, scales); !note.empty()) notes->push_back(note);
  return cell;
}

}  // namespace

SurfaceRun read_surface(const po::variables_map& given, const input::PointMaterial& material) {
  SurfaceRun run;
  po::variables_map vm = given;
  std::optional<model::CellGeometry> cell;
  std::vector<std::string> map_notes;  // what reading a height map or a cell file says of it
  const bool measured = given.count("height-map") > 0;
  if (given.count("cell") || measured) {
    const std::string source = measured ? "--height-map" : "--cell";
    if (given.count("cell") && measured) throw input::UsageError("--cell beside --height-map: give one texture");
    for (const char* name : {"l", "dh", "dh2", "s", "C", "lattice"}) {
      if (given.count(name) && !given[name].defaulted()) {
        throw input::UsageError(std::string("--") + name + " beside " + source + ": the " +
                                (measured ? "height map" : "cell file") + " gives the cell, its sites and their shapes");
      }
    }
    const input::PhysicalScales scales = input::read_physical_scales(given, material.material.get());
    if (measured) {
      for (const char* name : {"grid", "supercell", "scatter"}) {
        if (given.count(name) && !given[name].defaulted()) {
          throw input::UsageError(std::string("--") + name + " beside --height-map: the map's pixels are the grid and its caps");
        }
      }
      run.measured = read_measured(given, scales, &map_notes);
      cell = run.measured->geometry;
      run.cell_file = given["height-map"].as<std::string>();
    } else {
      run.cell_file = given["cell"].as<std::string>();
      cell = input::read_cell_file(run.cell_file, scales, &map_notes);
    }
    // The point's reading of the material and the load reads a cell too: the texture's
    // (taken out of the inputs' echo below).
    const model::Site& first = cell->sites.front();
    const auto put = [&vm](const char* name, const std::string& text) {
      vm.erase(name);
      vm.emplace(name, po::variable_value(boost::any(text), false));
    };
    put("l", input::json_number(cell->Lx));
    put("dh", "0");
    put("s", std::to_string(first.shape.s));
    put("C", input::json_number(first.shape.C));
  }
  run.inputs = input::read_point_inputs(vm, material);
  run.inputs.notes.insert(run.inputs.notes.end(), map_notes.begin(), map_notes.end());
  if (cell) {
    std::erase_if(run.inputs.values, [](const auto& v) { return v.first->name == "l" || v.first->name == "dh" || v.first->name == "s" || v.first->name == "C"; });
  }
  run.times = input::read_times(vm, run.inputs.scales);
  run.tolerances = input::read_tolerances(vm, run.inputs);
  for (const model::Tolerance& t : run.tolerances) {
    if (t.parameter->name == "l" || t.parameter->name == "dh" || t.parameter->name == "C") {
      throw input::UsageError("--tolerance " + std::string(t.parameter->name) +
                              ": a tolerance on the texture's geometry needs a load curve per corner; surface takes "
                              "tolerances on the pressure and the creep law's parameters (pressure, T, temperature)");
    }
  }
  run.lattice = input::read_choice(vm, "lattice", {"square", "hexagonal"}) == "square" ? model::LatticeKind::square
                                                                                       : model::LatticeKind::hexagonal;
  std::vector<double> drops{run.inputs.problem.dh};
  if (vm.count("dh2")) {
    const model::Parameter* dh2 = model::texture_parameter(model::kThirdLevelDrop);
    drops.push_back(input::read_parameter(vm, *dh2, &run.inputs.scales));
    // Echoed with the inputs, after dh (the table's first line, JSON's "inputs").
    auto after = std::find_if(run.inputs.values.begin(), run.inputs.values.end(), [](const auto& v) { return v.first->name == "dh"; });
    run.inputs.values.emplace(after == run.inputs.values.end() ? after : after + 1, dh2, drops.back());
  }
  run.grid_nodes = read_grid(vm["grid"].as<std::string>());
  run.check = vm.count("check") && vm["check"].as<bool>();
  run.full_curve = vm.count("full-curve") && vm["full-curve"].as<bool>();
  // The periodic model's tables are the two-level square lattice's, on their own grid.
  const std::string curve = input::read_choice(vm, "curve", {"auto", "tables", "cell"});
  const bool paper_lattice = !cell && run.lattice == model::LatticeKind::square && drops.size() == 1 &&
                             vm["supercell"].as<int>() == 1;
  if (curve == "tables" && !paper_lattice) {
    throw input::UsageError("--curve tables: the periodic model's tables are the two-level square lattice's (without --dh2, "
                            "--cell, --height-map, --supercell or --lattice hexagonal); use --curve cell or auto");
  }
  // (The tables answer s up to Localization::kMaxPeriodicExponent; auto takes the cell beyond.)
  const std::string beyond_tables = model::Localization{.periodic = true}.exponent_error(run.inputs.problem.shape.s);
  if (curve == "tables" && !beyond_tables.empty()) throw input::UsageError("--curve tables: " + beyond_tables);
  if (curve == "tables" && run.grid_nodes != 0) {
    throw input::UsageError("--grid beside --curve tables: the tables' grid is their own (512 nodes per pitch)");
  }
  run.curve_source = curve == "cell" || !paper_lattice || run.grid_nodes != 0 || !beyond_tables.empty() ? CurveSource::cell
                     : curve == "tables"                                      ? CurveSource::tables
                                                                              : CurveSource::tables_or_cell;
  run.geometry = cell ? *cell : model::lattice_cell(run.lattice, run.inputs.problem.l, run.inputs.problem.shape, drops);
  run.supercell = vm["supercell"].as<int>();
  if (run.supercell < 1 || run.supercell > kMaxSupercell) {
    throw input::UsageError("--supercell = " + std::to_string(run.supercell) + " is outside its range: an integer in [1, " +
                            std::to_string(kMaxSupercell) + "]");
  }
  const std::uint64_t seed = run.seed = input::parse_seed(vm["seed"].as<std::string>(), "--seed");
  // --scatter's and --curvature-scatter's draws: each needs the supercell's caps, a list one
  // value per cap.
  const auto supercell_scatter = [&](const char* option, const char* what, auto read) {
    if (run.supercell == 1 && vm["supercell"].defaulted()) {
      throw input::UsageError(std::string("--") + option + " needs --supercell K (the caps whose " + what + " scatter: K x K cells)");
    }
    model::HeightScatter scatter = read(vm[option].as<std::string>());
    scatter.seed = seed;
    const std::size_t caps = static_cast<std::size_t>(run.supercell) * run.supercell * run.geometry.sites.size();
    if (scatter.kind == model::HeightScatter::Kind::list && scatter.values.size() != caps) {
      throw input::UsageError(std::string("--") + option + " list has " + std::to_string(scatter.values.size()) +
                              " values: it needs one per cap, " + std::to_string(caps) + " for " + std::to_string(run.supercell) +
                              " x " + std::to_string(run.supercell) + " cells of " + std::to_string(run.geometry.sites.size()) +
                              " caps");
    }
    return scatter;
  };
  if (vm.count("scatter")) {
    run.scatter = supercell_scatter("scatter", "heights",
                                    [&](const std::string& text) { return read_height_scatter(text, run.inputs.scales); });
  }
  if (vm.count("curvature-scatter")) {
    run.curvature = supercell_scatter("curvature-scatter", "shapes", read_curvature_scatter);
    if (run.curvature.kind == model::HeightScatter::Kind::uniform && !(run.curvature.width < 1.0)) {
      throw input::UsageError("--curvature-scatter uniform:" + input::json_number(run.curvature.width) +
                              " is outside its range: a half-width below 1 (C (1 + d) must stay > 0)");
    }
  }
  run.seeds = vm["seeds"].as<int>();
  if (run.seeds < 1 || run.seeds > kMaxSeeds) {
    throw input::UsageError("--seeds = " + std::to_string(run.seeds) + " is outside its range: an integer in [1, " +
                            std::to_string(kMaxSeeds) + "]");
  }
  if (vm.count("target-error")) {
    const std::string text = vm["target-error"].as<std::string>();
    run.target_error = input::parse_real(text, "--target-error");
    if (!(run.target_error > 0.0 && run.target_error < 1.0)) {
      throw input::UsageError("--target-error = " + text + " is outside its range: a share in (0, 1)");
    }
    if (run.seeds <= kLeastDraws) {
      throw input::UsageError("--target-error needs --seeds N above " + std::to_string(kLeastDraws) +
                              " (the most draws; it stops at the first that meets it)");
    }
  }
  if (run.seeds > 1) {
    if (!model::drawn_at_random(run.scatter) && !model::drawn_at_random(run.curvature)) {
      throw input::UsageError("--seeds " + std::to_string(run.seeds) +
                              " draws the scatter again for each seed: it needs --scatter normal:SD or uniform:HALFWIDTH "
                              "(or --curvature-scatter's, with --supercell K)");
    }
    if (seed > std::numeric_limits<std::uint64_t>::max() - static_cast<std::uint64_t>(run.seeds - 1)) {
      throw input::UsageError("--seed + --seeds - 1 passes 2^64 - 1: a lower --seed");
    }
  }
  if (vm.count("part-caps")) {
    const std::string text = vm["part-caps"].as<std::string>();
    const std::uint64_t caps = input::parse_seed(text, "--part-caps");
    if (caps < 1 || caps > kMaxPartCaps) {
      throw input::UsageError("--part-caps = " + text + " is outside its range: a whole number in [1, 1e15]");
    }
    if (!model::drawn_at_random(run.scatter)) {
      throw input::UsageError("--part-caps: the tallest of a part's caps follows from the heights' distribution: it "
                              "needs --scatter normal:SD or uniform:HALFWIDTH (with --supercell K)");
    }
    if (!(run.scatter.width > 0.0)) throw input::UsageError("--part-caps: --scatter's width is 0: every tip at its design height");
    // Each level's caps a cell and design drop, then the part's and the supercell's counts.
    const int levels = run.geometry.levels();
    std::vector<double> drops(static_cast<std::size_t>(levels), std::numeric_limits<double>::infinity()), per_cell(drops.size(), 0.0);
    for (const model::Site& site : run.geometry.sites) {
      const std::size_t L = static_cast<std::size_t>(site.level);
      drops[L] = std::min(drops[L], site.drop);
      per_cell[L] += 1.0;
    }
    const double sites = static_cast<double>(run.geometry.sites.size()), copies = static_cast<double>(run.supercell) * run.supercell;
    std::vector<double> part(per_cell.size()), ours(per_cell.size());
    for (std::size_t L = 0; L < per_cell.size(); ++L) {
      part[L] = static_cast<double>(caps) * per_cell[L] / sites;
      ours[L] = copies * per_cell[L];
    }
    run.part_caps = static_cast<double>(caps);
    const double q[3] = {0.05, 0.5, 0.95};
    for (int k = 0; k < 3; ++k) {
      run.part_rise[static_cast<std::size_t>(k)] = model::tallest_rise_quantile(run.scatter, drops, part, q[k]);
      run.supercell_rise[static_cast<std::size_t>(k)] = model::tallest_rise_quantile(run.scatter, drops, ours, q[k]);
    }
  }
  if (run.supercell > 1) {
    try {
      run.geometry = model::supercell(run.geometry, run.supercell, run.scatter, run.curvature, &run.tallest_rise);
    } catch (const std::invalid_argument& e) {
      throw input::UsageError(std::string("--curvature-scatter: ") + e.what() + " (a narrower width, or another --seed)");
    }
  }
  return run;
}

namespace {

/// --grid auto: the least positive load the times after 0 meet (t = 0 alone where no later
/// time is asked; +infinity where none is positive).
double least_asked_load(const SurfaceRun& run, const model::CreepWeightedLoad& load) {
  double X = std::numeric_limits<double>::infinity();
  const bool later = std::any_of(run.times.begin(), run.times.end(), [](double t) { return t > 0.0; });
  for (const double t : run.times) {
    if (later && !(t > 0.0)) continue;
    const double x = t > 0.0 ? load(t) : load.initial();
    if (x > 0.0) X = std::min(X, x);
  }
  return X;
}

/// SurfaceRun::small_spot_reach, found once (`limit` and its touchdowns `touched`: the given
/// geometry's, where the caller has them; else made here).
double small_spot_reach(SurfaceRun& run, const model::CreepWeightedLoad& load, const model::SmallSpotLimit* limit = nullptr,
                        const std::vector<model::SmallSpotTouchdown>* touched = nullptr) {
  if (!run.small_spot_reach) {
    run.small_spot_reach = 0.0;
    const double X = least_asked_load(run, load);
    if (!run.measured && std::isfinite(X)) {
      if (limit != nullptr && touched != nullptr) {
        run.small_spot_reach = model::small_spot_reach(*limit, *touched, X);
      } else {
        const model::SmallSpotLimit own(run.geometry);
        run.small_spot_reach = own.answers() ? model::small_spot_reach(own, own.touchdowns(), X) : 0.0;
      }
    }
  }
  return *run.small_spot_reach;
}

/// --grid auto: nodes per pitch that give the tallest sites' spot, as an isolated punch's, a
/// radius of kAutoSpotRadius spacings at the least positive load the times after 0 meet (t = 0
/// alone where no later time is asked). The glassy spot at t = 0 can be far smaller than any
/// later one (the study's TPE: 280 nodes a pitch for it, 88 from 1 s on); it does not drive the
/// grid: where the grid taken does not resolve it, that snapshot is flagged below_resolution,
/// while the touchdowns (t*) do not read it. Nor do spots the small-spot limit answers: below
/// half its reach (SurfaceRun::small_spot_reach) the grid need only resolve the spots at that
/// load, where the curve hands over to the limit's states (docs/model.md 17.6), the
/// touchdowns there being the limit's on every grid.
int auto_grid_at(const SurfaceRun& run, double X);
reference::PeriodicGrid curve_grid(const SurfaceRun& run, int nodes);
int auto_grid(SurfaceRun& run, const model::CreepWeightedLoad& load) {
  const double X = least_asked_load(run, load), reach = small_spot_reach(run, load);
  if (!(reach > 0.0) || !std::isfinite(X)) return auto_grid_at(run, X);
  // The limit reads the loads asked below the hand-over, the curve those past it: the grid
  // resolves the spots at the least load it reads (kAutoMin at least: its touchdowns are held
  // to the grid of half the nodes), or none where every time's load is the limit's, and its
  // resolved part (the curve's X_resolved) starts by the hand-over at the latest.
  const double hand_over = kAutoLimitHandOver * reach;
  double most = 0.0;
  for (const double t : run.times) most = std::max(most, t > 0.0 ? load(t) : load.initial());
  int n = most > hand_over ? auto_grid_at(run, std::max(X, hand_over)) : kAutoLeast;
  const int resolved_spot = reference::LoadCurveOptions{}.resolved_spot_nodes;
  while (n < kAutoMaxNodes &&
         (reference::spot_load(run.geometry, curve_grid(run, n), resolved_spot) > hand_over || !reference::fft_friendly(n * run.supercell))) {
    n += 4;
  }
  return n;
}

/// --grid auto's nodes a pitch for the least load X (kAutoMin where X is not positive).
int auto_grid_at(const SurfaceRun& run, double X) {
  if (!std::isfinite(X) || !(X > 0.0)) return kAutoMin;
  // The load spread over the tallest level's caps (all of them: in a scattered supercell
  // the nearly tallest touch at once, each with a small spot).
  double count = 0.0;
  for (const model::Site& site : run.geometry.sites) count += site.level == 0 ? 1.0 : 0.0;
  const model::Shape& shape = run.geometry.sites.front().shape;
  const double a = std::pow(X * run.geometry.Lx * run.geometry.Ly / count / model::load_coefficient(shape), 1.0 / (shape.s + 1));
  // (A multiple of 4: the grid of half its nodes, which the curve is held to, is even; the
  // next one FFTW transforms with its fast codelets, as the grid of half its nodes then is.)
  const double least = std::ceil(kAutoSpotRadius * run.geometry.Lx / run.supercell / a / 4.0) * 4.0;
  int n = static_cast<int>(std::clamp(least, static_cast<double>(kAutoMin), static_cast<double>(kAutoMaxNodes)));
  while (n < kAutoMaxNodes && !reference::fft_friendly(n * run.supercell)) n += 4;
  return n;
}

std::string budget_problem(const SurfaceRun& run, const reference::PeriodicGrid& grid);

/// --grid auto: the curve on the grid auto_grid picks, held to the curve on half its nodes:
/// where some level's t* (under `load`) moves between them by more than kAutoTStarAccuracy
/// of itself, or its regime changes, the nodes double (up to kAutoMaxNodes) and the finer is held
/// to the last. Each level's move on the grid taken is kept (SurfaceRun::grid_t_star_change:
/// it bounds the taken grid's error where t* converges at first order or faster); a level
/// still moving at kAutoMaxNodes is marked unresolved, with a note.
template <class CurveOn>
model::LoadCurve auto_grid_curve(SurfaceRun& run, const model::CreepWeightedLoad& load, const CurveOn& curve_on, bool progress,
                                 const MoreLoadPoints& also_held) {
  int n = auto_grid(run, load);
  model::LoadCurve coarse = curve_on(n / 2);
  model::LoadCurve fine = curve_on(n);
  const std::size_t L = static_cast<std::size_t>(fine.levels());
  std::vector<double> change(L, 0.0);
  // Each level's touch at the run's load and at every other load point asked.
  const auto touches = [&](const model::LoadCurve& curve) {
    std::vector<std::vector<model::LevelTouch>> rows{model::level_touches(curve, load)};
    if (also_held.touches) {
      std::vector<std::vector<model::LevelTouch>> more = also_held.touches(run, curve);
      rows.insert(rows.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
    }
    return rows;
  };
  for (;;) {
    const std::vector<std::vector<model::LevelTouch>> a = touches(coarse), b = touches(fine);
    double worst = 0.0;
    std::fill(change.begin(), change.end(), 0.0);
    for (std::size_t row = 0; row < a.size(); ++row) {
      for (std::size_t level = 0; level < L; ++level) {
        const model::LevelTouch &x = a[row][level], &y = b[row][level];
        const double moved = x.regime != y.regime                ? std::numeric_limits<double>::infinity()
                             : y.regime == model::Regime::delayed ? std::abs(y.t_star - x.t_star) / y.t_star
                                                                   : 0.0;
        change[level] = std::max(change[level], moved);
        worst = std::max(worst, moved);
      }
    }
    if (worst <= kAutoTStarAccuracy || 2 * n > kAutoMaxNodes) break;
    if (const std::string problem = budget_problem(run, curve_grid(run, 2 * n)); !problem.empty()) {
      run.inputs.notes.push_back("--grid auto stopped at " + std::to_string(n) + " nodes a pitch: " + problem);
      break;
    }
    if (progress) {
      std::cerr << "punchsweep surface: --grid auto: t* moves by " << worst << " of itself from " << n / 2 << " to " << n
                << " nodes a pitch (more than " << kAutoTStarAccuracy << "): the curve on " << 2 * n << "\n";
    }
    coarse = std::move(fine);
    n *= 2;
    fine = curve_on(n);
  }
  run.grid_coarser = n / 2;
  run.grid_t_star_change = change;
  if (const double X0 = load.initial(); X0 > 0.0 && X0 < fine.X_resolved &&
      std::any_of(run.times.begin(), run.times.end(), [](double t) { return !(t > 0.0); })) {
    run.inputs.notes.push_back("--grid auto sized the grid for the times after 0: the snapshot at t = 0 (the glassy spot) is below what " +
                               std::to_string(n) + " nodes a pitch resolve and is flagged below_resolution; --grid " +
                               std::to_string(auto_grid_at(run, X0)) + " resolves it");
  }
  // Each snapshot's area fraction on both grids: kAutoAreaMoveShare (half) of its move is
  // the taken grid's error where the areas converge at order 1.6 or faster (a lone cap's at second order,
  // docs/model.md 17.3; the square lattice at s = 3 as slowly as 2.9 a doubling: 1.13% off
  // on 120 nodes a pitch where it moved 2.2% from 60), where the grid of half the nodes
  // resolves the spots too; below its X_resolved that grid is not yet converging at its
  // order, and the whole move stands for the error (the square lattice at s = 3, l 0.5 R,
  // pbar 8e-5, past level 1's touchdown: 1.4% off on 104 nodes a pitch where it moved 1.15%
  // from 52, then 0.3% on 208).
  // (A reading of the small-spot limit's states reads no grid: no error of one.)
  for (const double t : run.times) {
    const double X = t > 0.0 ? load(t) : load.initial();
    const double a = coarse.at(X).area_fraction, b = fine.at(X).area_fraction;
    const double share = X >= coarse.X_resolved ? kAutoAreaMoveShare : 1.0;
    run.grid_area_error.push_back(b > 0.0 && X > fine.X_small_spot ? share * std::abs(b - a) / b : 0.0);
  }
  for (std::size_t level = 1; level < L; ++level) {
    if (change[level] <= kAutoTStarAccuracy) continue;
    std::ostringstream note;
    note.precision(3);
    note << "level " << level << ": --grid auto stopped at " << n << " nodes a pitch, where t* still ";
    if (std::isinf(change[level])) {
      note << "changes regime from " << n / 2 << " nodes";
    } else {
      note << "moves by " << change[level] << " of itself from " << n / 2 << " nodes";
    }
    note << " (the stated accuracy: " << kAutoTStarAccuracy << "): the level is marked unresolved; --grid N up to " << kMaxGridNodes
         << " refines further";
    run.inputs.notes.push_back(note.str());
    run.unresolved_levels.push_back(static_cast<int>(level));
  }
  return fine;
}

/// The grid of the curve at `nodes` a pitch: the lattice's (K cells each way), a cell file's
/// (its tips snapped to it, when the cell is made), or the measured map's pixels.
reference::PeriodicGrid curve_grid(const SurfaceRun& run, int nodes) {
  if (run.measured) return run.measured->cell.grid;
  if (run.cell_file.empty()) return reference::lattice_grid(run.geometry, run.lattice, nodes, run.supercell);
  return reference::cell_grid(run.geometry, nodes * run.supercell);
}

/// The memory of a curve's solve on `grid`, in bytes: kBytesPerNode a stored node, and 17
/// more a level (the levels' shares of each node).
double curve_bytes(const SurfaceRun& run, const reference::PeriodicGrid& grid) {
  const double levels = static_cast<double>(std::max(run.geometry.levels(), 1));
  return static_cast<double>(grid.size()) * (kBytesPerNode + 17.0 * levels);
}

/// Why `grid` is beyond what one curve may take (budget_problem's first clause), empty where
/// it is within: the nodes, the node-caps, or this machine's memory.
std::string over_budget(const SurfaceRun& run, const reference::PeriodicGrid& grid) {
  const double nodes = static_cast<double>(grid.nodes());
  const double caps = static_cast<double>(run.geometry.sites.size());
  const double bytes = curve_bytes(run, grid), machine = machine_bytes();
  std::ostringstream out;
  out.precision(3);
  if (nodes > kMaxNodes) {
    out << "the curve's grid, " << grid.nx << " x " << grid.ny << " nodes (about " << bytes / 1e9
        << " GB), is beyond the engine's budget of " << kMaxNodes << " nodes";
  } else if (nodes * caps > kMaxNodeCaps) {
    out << "the curve's grid, " << grid.nx << " x " << grid.ny << " nodes with " << run.geometry.sites.size() << " caps (" << nodes * caps
        << " node-caps, about " << bytes / 1e9 << " GB), is beyond the engine's budget of " << kMaxNodeCaps
        << " node-caps (each cap that touches apart is its own search over the whole grid: hours)";
  } else if (machine > 0.0 && bytes > kMachineShare * machine) {
    out << "the curve's grid, " << grid.nx << " x " << grid.ny << " nodes, needs about " << bytes / 1e9
        << " GB, beyond " << kMachineShare * 100.0 << "% of this machine's " << machine / 1e9 << " GB";
  }
  return out.str();
}

/// The largest nodes a pitch below `nodes` (even, at least 4) whose grid is within the
/// budget (over_budget empty); 0 where none is.
int largest_grid_within(const SurfaceRun& run, int nodes) {
  for (int n = nodes - 2; n >= 4; n -= 2) {
    if (over_budget(run, curve_grid(run, n)).empty()) return n;
  }
  return 0;
}

/// Why a curve on `grid` is beyond what the engine takes on (empty where it is not): more
/// than kMaxNodes nodes (memory: about kBytesPerNode a node), nodes x caps beyond
/// kMaxNodeCaps (each cap that touches apart costs its own search of some 20 solves of the
/// whole grid), or more than kMachineShare of this machine's memory (over_budget). Each is
/// said with the estimate and what brings it down: for a lattice or a cell file, the largest
/// --grid within the budget.
std::string budget_problem(const SurfaceRun& run, const reference::PeriodicGrid& grid) {
  const std::string over = over_budget(run, grid);
  if (over.empty()) return over;
  std::ostringstream out;
  out.precision(3);
  out << over << ": ";
  if (run.measured) {
    out << "crop or resample the map";
    return out.str();
  }
  out << "give a smaller --grid (nodes a pitch)" << (run.supercell > 1 ? " or --supercell" : "");
  // (A lattice's or cell's grid has nx = nodes a pitch x the supercell's cells.)
  if (const int fits = largest_grid_within(run, grid.nx / run.supercell); fits > 0) {
    const reference::PeriodicGrid largest = curve_grid(run, fits);
    out << "; the largest that fits: --grid " << fits << " (" << largest.nx << " x " << largest.ny << " nodes, about "
        << curve_bytes(run, largest) / 1e9 << " GB)";
  }
  return out.str();
}

/// Why the boundary elements cannot take the texture's scales (empty where they can): its
/// cell's lengths outside [kMinCellLength, kMaxCellLength] R, or its relief (the greatest
/// separation over the cell, from the highest tip) outside [kMinRelief, kMaxRelief] R, where
/// the solve's numbers leave double precision (--l 1e300, --C 1e300 or a cell 1e5 R long
/// ended in an internal error, --l 1e-300 ran without end).
std::string scale_problem(const SurfaceRun& run) {
  std::ostringstream out;
  out.precision(3);
  const double Lx = run.geometry.Lx, Ly = run.geometry.Ly;
  if (!(Lx >= kMinCellLength && Lx <= kMaxCellLength && Ly >= kMinCellLength && Ly <= kMaxCellLength)) {
    out << "the cell is " << Lx << " x " << Ly << " R: the boundary elements take cells whose lengths lie in ["
        << kMinCellLength << ", " << kMaxCellLength << "] R";
    return out.str();
  }
  const double relief = run.measured ? *std::max_element(run.measured->cell.profile.begin(), run.measured->cell.profile.end())
                                     : model::SurfaceLocator(run.geometry).top();
  if (!(relief >= kMinRelief && relief <= kMaxRelief)) {
    out << "the texture's relief over its cell (the deepest point below the highest tip) is about " << relief
        << " R: the boundary elements take reliefs in [" << kMinRelief << ", " << kMaxRelief << "] R (C, s and the pitch set it)";
  }
  return out.str();
}

/// The grid the boundary elements solve on (the curve's, or --check's), a cell file's tips
/// snapped to its nodes (with a note). A texture whose scales the solve cannot take
/// (scale_problem) or a grid beyond the budget (budget_problem) is refused before anything
/// is allocated.
reference::PeriodicGrid boundary_element_grid(SurfaceRun& run, const model::CreepWeightedLoad& load) {
  if (const std::string problem = scale_problem(run); !problem.empty()) throw input::UsageError(problem);
  if (run.grid_nodes == 0 && !run.measured) run.grid_nodes = auto_grid(run, load);
  reference::PeriodicGrid grid = curve_grid(run, run.grid_nodes);
  if (const std::string problem = budget_problem(run, grid); !problem.empty()) throw input::UsageError(problem);
  if (run.measured || run.cell_file.empty()) return grid;
  // A cell file's tips go to their nearest nodes: the move is reported.
  double moved = 0.0;
  run.geometry = reference::snap_tips(run.geometry, grid, &moved);
  // The snapped tips keep the symmetry the grid was chosen for, or less.
  const reference::Symmetry snapped = reference::symmetry_of(run.geometry);
  if ((grid.mirrored() && snapped != reference::Symmetry::mirror) || (grid.mirrored_x() && snapped == reference::Symmetry::none)) {
    grid.symmetry = snapped;
  }
  if (moved > 1e-9 * std::min(grid.hx(), grid.hy())) {
    std::ostringstream note;
    note.precision(3);
    note << "the tips were moved to the nearest nodes of the " << grid.nx << " x " << grid.ny << " grid, by at most "
         << moved << " R (" << moved / std::min(grid.hx(), grid.hy()) << " node spacings)";
    run.inputs.notes.push_back(note.str());
  }
  return grid;
}

/// The cell the boundary elements solve on `grid` (boundary_element_grid's): the measured
/// map's, or made from the geometry. `progress`: a large one is said on stderr first.
reference::Cell boundary_element_cell(const SurfaceRun& run, const reference::PeriodicGrid& grid, bool progress) {
  if (progress && static_cast<double>(grid.nodes()) >= kLargeGrid) {
    std::cerr << "punchsweep surface: the cell on " << grid.nx << " x " << grid.ny << " nodes with " << run.geometry.sites.size()
              << " caps (about " << curve_bytes(run, grid) / 1e9
              << " GB); its curve takes minutes or more, with progress below\n";
  }
  if (run.measured) return run.measured->cell;
  return reference::make_cell(run.geometry, grid);
}

/// The curve held to its own time stepping (--check), on the same cell: a level whose
/// regime differs, or whose t* differs by more than the stepping's resolution and 1e-3 of
/// itself, is not resolved; a valid snapshot whose area fraction differs by more than 1% and
/// half a node per cap is flagged check_disagrees. Either gets a note with the numbers.
void hold_to_check(SurfaceRun& run, double t_resolution) {
  const reference::CellReference& stepped = *run.stepped;
  for (std::size_t level = 1; level < run.history.levels.size(); ++level) {
    model::LevelTouch& mine = run.history.levels[level];
    const double theirs = stepped.level_t_star[level];
    const bool same_regime = mine.regime == stepped.level_regime[level];
    const bool close = same_regime && (mine.regime != model::Regime::delayed ||
                                       std::abs(mine.t_star - theirs) <= t_resolution + 1e-3 * theirs);
    if (close) continue;
    mine.resolved = false;
    std::ostringstream note;
    note.precision(6);
    note << "level " << level << ": the curve says " << model::regime_name(mine.regime) << " (t* = " << mine.t_star
         << ") and its time stepping " << model::regime_name(stepped.level_regime[level]) << " (t* = " << theirs
         << ") beyond their accuracy: the level is marked unresolved; a finer --grid decides";
    run.inputs.notes.push_back(note.str());
  }
  const double half_nodes = 0.5 * static_cast<double>(run.geometry.sites.size()) /
                            (static_cast<double>(run.curve.nx) * static_cast<double>(run.curve.ny));
  int flagged = 0;
  double worst = 0.0;
  for (std::size_t k = 0; k < run.history.snapshots.size(); ++k) {
    model::SurfaceSnapshot& s = run.history.snapshots[k];
    const double theirs = stepped.series[k].area_fraction;
    const double miss = std::abs(s.state.area_fraction - theirs);
    if (s.validity != model::SurfaceValidity::valid || miss <= 0.01 * theirs + half_nodes) continue;
    s.validity = model::SurfaceValidity::check_disagrees;
    ++flagged;
    worst = std::max(worst, miss / std::max(theirs, 1e-300));
  }
  if (flagged > 0) {
    std::ostringstream note;
    note.precision(3);
    note << flagged << " snapshot" << (flagged == 1 ? "" : "s") << "' area fraction differ" << (flagged == 1 ? "s" : "")
         << " from the time stepping's by up to " << 100.0 * worst
         << "% (the curve's stated accuracy: 1% and half a node per cap): flagged check_disagrees";
    run.inputs.notes.push_back(note.str());
  }
}

/// `run`'s cell stepped in time at its load (--check), the steps scaled to the law as
/// `reference` scales them: run.stepped, check_t_star_resolution and check_seconds.
void step_in_time(SurfaceRun& run, const reference::Cell& cell) {
  reference::ReferenceOptions scaled;
  reference::scale_steps_to_law(*run.inputs.creep, &scaled);
  reference::CellReferenceOptions check;
  check.times = run.times;
  check.steps = scaled.steps;
  check.t_star_resolution = scaled.t_star_resolution;
  run.check_t_star_resolution = check.t_star_resolution;
  sweep::use_reproducible_fft_plans();
  const auto check_start = std::chrono::steady_clock::now();
  run.stepped = reference::evaluate_cell_reference(run.geometry, cell, run.inputs.problem.pbar0, *run.inputs.creep,
                                                   run.inputs.problem.loading, check);
  run.check_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - check_start).count();
}

/// Whether the periodic model's tables give this run's curve: the two-level square lattice
/// under --curve auto or tables (CurveSource, set as the inputs are read), where they reach
/// its dh (model::periodic_curve_reaches). The one place the curve's source is decided, for
/// the evaluation, its cost and its parts.
bool tables_answer(const SurfaceRun& run) {
  return run.curve_source != CurveSource::cell &&
         model::periodic_curve_reaches(model::periodic_solution(run.inputs.problem.shape.s), run.inputs.problem);
}
/// The load's inputs of `run`: its pressure, law and values, and load shape.
model::SurfaceLoad surface_load_of(const SurfaceRun& run) {
  return {run.inputs.problem.pbar0, run.inputs.law, run.inputs.law_values, run.inputs.problem.loading};
}

/// How far `run`'s curve is read (SurfaceRun::X_reach): the largest X(inf) of its load,
/// its tolerances' corners and `also_held`'s points (t* asks whether X(t) ever reaches X*;
/// every snapshot lies at or below X(inf)); +infinity under --full-curve.
double curve_reach(const SurfaceRun& run, const MoreLoadPoints& also_held) {
  if (run.full_curve) return std::numeric_limits<double>::infinity();
  double X = 0.0;
  try {
    X = model::largest_final_load(surface_load_of(run), run.tolerances);
  } catch (const std::invalid_argument& e) {
    throw input::UsageError(std::string("--tolerance: ") + e.what());
  }
  return also_held.X_reach ? std::max(X, also_held.X_reach(run)) : X;
}
}  // namespace

/// The curve as far as the times reach, and the history on it.
void evaluate(SurfaceRun& run, bool progress, const MoreLoadPoints& also_held) {
  const model::CreepWeightedLoad load(*run.inputs.creep, run.inputs.problem.pbar0, run.inputs.problem.loading);
  const model::SurfaceLoad surface_load = surface_load_of(run);
  run.X_reach = curve_reach(run, also_held);
  const auto start = std::chrono::steady_clock::now();
  std::optional<model::LoadCurve> tabulated;
  if (tables_answer(run)) {
    // The two-level square lattice's curve off the periodic model's tables.
    tabulated = model::periodic_load_curve(model::periodic_solution(run.inputs.problem.shape.s), run.inputs.problem);
  } else if (run.curve_source != CurveSource::cell) {
    if (run.curve_source == CurveSource::tables) {
      const model::PeriodicSolution& solution = model::periodic_solution(run.inputs.problem.shape.s);
      const model::PeriodicScales scales(run.inputs.problem);
      std::ostringstream why;
      why << "--curve tables: dh = " << run.inputs.problem.dh << " R is outside the tables' range: dh <= "
          << solution.delta_top() * scales.h_unit << " R (their top), or dh >= " << solution.delta_hidden() * scales.h_unit
          << " R (level 1 hidden under the tall punches); use --curve cell";
      throw input::UsageError(why.str());
    }
    run.inputs.notes.push_back("dh lies between the periodic tables' top and where level 1 hides: the curve is the cell's "
                               "own boundary elements'");
  }
  std::optional<reference::Cell> cell;
  if (tabulated) {
    run.curve_source = CurveSource::tables;
    run.curve = std::move(*tabulated);
    run.X_reach = std::numeric_limits<double>::infinity();  // the tables' curve is whole
  } else {
    run.curve_source = CurveSource::cell;
    reference::LoadCurveOptions options;
    // As far as the loads asked reach (its first sample past X_reach): below it the curve is
    // the full curve's, bit for bit, so a cached curve that reaches further serves (cut
    // there), and a level untouched by then never touches under these loads. FFTW's plans
    // are its estimate's, so that a curve and every answer read off it have the same bits
    // in every process.
    options.X_reach = run.X_reach;
    sweep::use_reproducible_fft_plans();
    std::optional<CurveProgressLine> line;  // the curve being built's, where progress is shown
    if (progress) {
      options.progress = [&](const reference::LoadCurveProgress& p) {
        if (!line) {
          const reference::PeriodicGrid grid = curve_grid(run, run.grid_nodes);
          line.emplace(run.measured ? std::to_string(grid.nx) + " x " + std::to_string(grid.ny) + " pixels"
                                    : std::to_string(run.grid_nodes) + " nodes a pitch",
                       estimated_curve_seconds(grid, static_cast<double>(run.geometry.sites.size())));
        }
        (*line)(p);
      };
    }
    // The curve on `nodes` a pitch (0: the measured map's pixels): the given geometry's
    // tips snapped to that grid, its note the last grid's alone.
    const model::CellGeometry given = run.geometry;
    const std::vector<std::string> notes = run.inputs.notes;
    // The small-spot limit's touchdowns of the given geometry (docs/model.md 17.6): they do
    // not depend on the grid, so found once for every grid's curve.
    std::optional<model::SmallSpotLimit> limit;
    std::vector<model::SmallSpotTouchdown> limit_touchdowns;
    if (!run.measured) {
      limit.emplace(given);
      limit_touchdowns = limit->touchdowns();
      if (run.grid_nodes == 0) small_spot_reach(run, load, &*limit, &limit_touchdowns);
    }
    bool cached = true;
    const auto curve_on = [&](int nodes) {
      run.geometry = given;
      run.inputs.notes = notes;
      run.grid_nodes = nodes;
      const reference::PeriodicGrid grid = boundary_element_grid(run, load);
      // The cell is made only where the curve is built (a cached one is read without it).
      cell.reset();
      const auto made = [&]() -> const reference::Cell& {
        cell = boundary_element_cell(run, grid, progress);
        return *cell;
      };
      CurveOrigin origin = CurveOrigin::built;
      model::LoadCurve curve = load_curve_for(run.geometry, grid, options, run.measured ? &run.measured->cell : nullptr,
                                              made, &origin);
      // A first touch the grid cannot resolve (the tallest spots span too few nodes), taken
      // from the small-spot limit where it holds (docs/model.md 17.6): the given tips, not
      // the grid's snapped ones.
      const std::vector<double> own = curve.level_touchdown;
      if (limit && model::answer_small_spots(curve, given, limit_touchdowns) > 0) {
        for (std::size_t level = 1; level < curve.level_small_spot.size(); ++level) {
          if (curve.level_small_spot[level] == 0) continue;
          std::ostringstream note;
          note.precision(6);
          note << "level " << level << ": X* = " << curve.level_touchdown[level]
               << " E0* from the small-spot limit (the caps in contact as isolated punches in the cell's periodic field, "
               << "their spots within " << model::kSmallSpotMaxRatio << " of the nearest distance: about 1e-5 of X*); the curve on "
               << grid.nx << " x " << grid.ny << " nodes gave " << own[level];
          run.inputs.notes.push_back(note.str());
        }
        // A scattered cell's tall caps below its tallest, each its own touchdown.
        std::size_t tall = 0;
        for (std::size_t k = 0; k < curve.site_small_spot.size(); ++k) tall += curve.site_small_spot[k] != 0 && given.sites[k].level == 0;
        if (tall > 0) {
          run.inputs.notes.push_back("level 0: " + std::to_string(tall) +
                                     " caps below the tallest touch at loads from the small-spot limit (each in the periodic field of the "
                                     "caps in contact before it; cap_list's touchdown_from)");
        }
      }
      // Below the curve's resolution the spots' areas and loads from the limit too, where it
      // holds up to there (docs/model.md 17.6): the curve the same whatever load reads it (a
      // map's points and `surface` alike).
      const double unresolved = curve.X_resolved;
      if (limit && model::resolve_small_spots(curve, *limit, limit_touchdowns)) {
        std::ostringstream note;
        note.precision(6);
        note << "areas and loads below X = " << unresolved << " E0* (where the spots span too few of the " << grid.nx << " x " << grid.ny
             << " nodes) from the small-spot limit, from X = " << curve.X_first() << " E0*";
        run.inputs.notes.push_back(note.str());
      }
      line.reset();  // the next curve (--grid auto's finer one) says its own line
      cached = cached && origin == CurveOrigin::cache;
      return curve;
    };
    if (run.grid_nodes != 0 || run.measured) {
      run.curve = curve_on(run.grid_nodes);
    } else {
      run.curve = auto_grid_curve(run, load, curve_on, progress, also_held);
    }
    run.curve_cached = cached;
  }
  run.curve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.history = model::surface_history(run.curve, load, run.times);
  for (const int level : run.unresolved_levels) run.history.levels[static_cast<std::size_t>(level)].resolved = false;
  // --grid auto: a valid snapshot whose area the grid leaves more than 1% uncertain is
  // flagged below_resolution (a finer --grid answers it).
  int uncertain = 0;
  for (std::size_t k = 0; k < run.grid_area_error.size() && k < run.history.snapshots.size(); ++k) {
    model::SurfaceSnapshot& snapshot = run.history.snapshots[k];
    if (snapshot.validity != model::SurfaceValidity::valid || run.grid_area_error[k] <= kAutoAreaAccuracy) continue;
    snapshot.validity = model::SurfaceValidity::below_resolution;
    ++uncertain;
  }
  if (uncertain > 0) {
    std::ostringstream note;
    note << uncertain << " snapshot(s) flagged below_resolution: their area fraction moves by more than "
         << 100.0 * kAutoAreaAccuracy / kAutoAreaMoveShare << "% from the grid of half the nodes (" << 100.0 * kAutoAreaAccuracy
         << "% where that grid does not resolve the spots: an error beyond " << 100.0 * kAutoAreaAccuracy
         << "% on the grid taken); a finer --grid answers";
    run.inputs.notes.push_back(note.str());
  }
  // Each level's sensitivity of t* to the load's inputs, and its range over the tolerances.
  run.derivatives.resize(static_cast<std::size_t>(run.curve.levels()));
  run.ranges.resize(static_cast<std::size_t>(run.curve.levels()));
  std::vector<model::TStarRange> ranges;
  if (!run.tolerances.empty()) {
    try {
      ranges = model::level_t_star_ranges(run.curve, surface_load, run.tolerances);
    } catch (const std::invalid_argument& e) {
      throw input::UsageError(std::string("--tolerance: ") + e.what());
    }
  }
  for (int level = 1; level < run.curve.levels(); ++level) {  // the tallest touch at once
    const std::size_t at = static_cast<std::size_t>(level);
    run.derivatives[at] = model::level_t_star_derivatives(run.curve, level, surface_load, run.history.levels[at].t_star);
    if (!ranges.empty()) run.ranges[at] = ranges[at];
    // A level on a knife edge says so, as `point` does (t* then asks more of the curve than
    // its grid's accuracy).
    if (const std::string note = model::knife_edge_note(run.derivatives[at]); !note.empty()) {
      run.inputs.notes.push_back("level " + std::to_string(level) + ": " + note);
    }
  }
  if (run.check) {
    if (!cell) {  // (the curve's was read from the cache, or off the tables)
      sweep::use_reproducible_fft_plans();
      const reference::PeriodicGrid grid = boundary_element_grid(run, load);
      cell = boundary_element_cell(run, grid, false);
    }
    step_in_time(run, *cell);
    hold_to_check(run, run.check_t_star_resolution);
  }
}

namespace {

/// use(run) on the texture of `keywords`, read by the command's own options and checks,
/// while the material it reads (which the run's law points into) lives.
template <class Use>
auto with_keywords(const input::Keywords& keywords, Use&& use) {
  const input::PointMaterial material = input::find_point_material(keywords);
  SurfaceRun run = read_surface(input::parse_keywords(keywords, surface_options(material), "surface"), material);
  return use(run);
}

/// The grids (nodes a pitch) the cell's curve is built on, refused as boundary_element_cell
/// refuses (the scales, the budget) before anything is allocated: the one given (0 for a
/// measured map's pixels), or --grid auto's pick and its half (at least).
std::vector<int> cell_grids(SurfaceRun& run) {
  if (const std::string problem = scale_problem(run); !problem.empty()) throw input::UsageError(problem);
  std::vector<int> grids{run.grid_nodes};
  if (run.grid_nodes == 0 && !run.measured) {
    const int n = auto_grid(run, model::CreepWeightedLoad(*run.inputs.creep, run.inputs.problem.pbar0, run.inputs.problem.loading));
    grids = {n / 2, n};
  }
  for (const int nodes : grids) {
    if (const std::string problem = budget_problem(run, curve_grid(run, nodes)); !problem.empty()) throw input::UsageError(problem);
  }
  return grids;
}

}  // namespace

CurveCost curve_cost(SurfaceRun& run, const MoreLoadPoints& also_held) {
  CurveCost cost;
  cost.caps = run.geometry.sites.size();
  cost.levels = run.geometry.levels();
  if (tables_answer(run)) {
    cost.source = "periodic tables";
    return cost;
  }
  cost.source = "cell";
  const std::vector<int> grids = cell_grids(run);
  cost.auto_grid = run.grid_nodes == 0 && !run.measured;
  const model::CreepWeightedLoad load(*run.inputs.creep, run.inputs.problem.pbar0, run.inputs.problem.loading);
  const model::CellGeometry given = run.geometry;
  reference::LoadCurveOptions options;
  options.X_reach = cost.X_reach = curve_reach(run, also_held);
  for (const int nodes : grids) {
    run.geometry = given;
    run.grid_nodes = nodes;
    const reference::PeriodicGrid grid = boundary_element_grid(run, load);
    CurveCost::Grid g;
    g.nodes_per_pitch = nodes;
    g.nx = grid.nx;
    g.ny = grid.ny;
    g.bytes = curve_bytes(run, grid);
    const CachedCurve held = cached_curve(run.geometry, grid, options, run.measured ? &run.measured->cell : nullptr);
    g.cached = held.holds == CachedCurve::Holds::whole;
    if (held.holds == CachedCurve::Holds::beginning) g.continued_from = held.X_last;
    g.built_seconds = estimated_curve_seconds(grid, static_cast<double>(cost.caps));
    g.seconds = g.cached ? 0.0 : g.built_seconds;
    cost.grids.push_back(g);
  }
  return cost;
}

SurfaceRun evaluate_surface(const input::Keywords& keywords, const MoreLoadPoints& also_held) {
  return with_keywords(keywords, [&](SurfaceRun& run) {
    evaluate(run, false, also_held);
    return std::move(run);
  });
}

namespace {

/// One draw's values for its ensemble.
SurfaceEnsemble::Member ensemble_member(const SurfaceRun& run, std::uint64_t seed) {
  SurfaceEnsemble::Member m;
  m.seed = seed;
  const std::size_t L = run.history.levels.size();
  std::vector<std::vector<double>> caps(L);
  for (std::size_t k = 0; k < run.geometry.sites.size(); ++k) {
    caps[static_cast<std::size_t>(run.geometry.sites[k].level)].push_back(run.history.sites[k].t_star);
  }
  for (std::vector<double>& times : caps) {
    std::sort(times.begin(), times.end());
    m.first.push_back(times.front());
    m.median.push_back(model::percentile(times, 0.5));
    m.last.push_back(times.back());
  }
  const auto series = [&](auto value) {
    std::vector<double> out;
    for (const model::SurfaceSnapshot& s : run.history.snapshots) out.push_back(value(s));
    return out;
  };
  m.series.push_back(series([](const model::SurfaceSnapshot& s) { return s.state.area_fraction; }));
  m.series.push_back(series([](const model::SurfaceSnapshot& s) { return s.state.sites_touched; }));
  for (std::size_t level = 0; level < L; ++level) {
    m.series.push_back(series([level](const model::SurfaceSnapshot& s) { return s.state.level_sites_touched[level]; }));
  }
  for (std::size_t level = 0; level < L; ++level) m.resolved.push_back(run.history.levels[level].resolved ? 1 : 0);
  m.valid = series([](const model::SurfaceSnapshot& s) { return s.validity == model::SurfaceValidity::valid ? 1.0 : 0.0; });
  return m;
}

/// Each series' statistics over `members`' draws, per time.
std::vector<std::vector<model::SampleStatistics>> series_statistics(const std::vector<SurfaceEnsemble::Member>& members) {
  std::vector<std::vector<model::SampleStatistics>> out;
  for (std::size_t q = 0; q < members.front().series.size(); ++q) {
    std::vector<model::SampleStatistics>& at = out.emplace_back();
    for (std::size_t t = 0; t < members.front().series[q].size(); ++t) {
      std::vector<double> values;
      for (const SurfaceEnsemble::Member& m : members) values.push_back(m.series[q][t]);
      at.push_back(model::sample_statistics(std::move(values)));
    }
  }
  return out;
}

/// The largest standard error among `series`' means (--target-error's measure).
double largest_error(const std::vector<std::vector<model::SampleStatistics>>& series) {
  double worst = 0.0;
  for (const std::vector<model::SampleStatistics>& at : series) {
    for (const model::SampleStatistics& s : at) worst = std::max(worst, s.se);
  }
  return worst;
}

}  // namespace

SurfaceEnsemble evaluate_ensemble(SurfaceRun& run, const po::variables_map& given, const input::PointMaterial& material,
                                  bool progress) {
  SurfaceEnsemble out;
  out.target_error = run.target_error;
  const std::uint64_t first = run.seed;
  for (int k = 0; k < run.seeds; ++k) {
    if (run.target_error > 0.0 && k >= kLeastDraws && largest_error(series_statistics(out.members)) <= run.target_error) break;
    const std::uint64_t seed = first + static_cast<std::uint64_t>(k);
    if (progress) std::cerr << "punchsweep surface: draw " << k + 1 << " of " << run.seeds << " (seed " << seed << ")\n";
    if (k == 0) {
      evaluate(run, progress);
      out.members.push_back(ensemble_member(run, seed));
      continue;
    }
    po::variables_map vm = given;
    static_cast<std::map<std::string, po::variable_value>&>(vm)["seed"] = po::variable_value(boost::any(std::to_string(seed)), false);
    SurfaceRun draw = read_surface(vm, material);
    evaluate(draw, progress);
    out.members.push_back(ensemble_member(draw, seed));
  }
  out.series = series_statistics(out.members);
  if (run.target_error > 0.0) {
    out.reached_error = largest_error(out.series);
    if (out.reached_error > run.target_error) {
      std::ostringstream note;
      note << "--target-error " << run.target_error << ": after " << out.members.size()
           << " draws (--seeds, the most) the largest standard error of a mean share or area fraction is "
           << out.reached_error << "; more --seeds reach it";
      run.inputs.notes.push_back(note.str());
    }
  }
  const std::size_t L = run.history.levels.size();
  const auto over_draws = [&](auto value) {
    std::vector<double> values;
    for (const SurfaceEnsemble::Member& m : out.members) values.push_back(value(m));
    return model::sample_statistics(std::move(values));
  };
  for (std::size_t level = 0; level < L; ++level) {
    out.levels.push_back({over_draws([level](const SurfaceEnsemble::Member& m) { return m.first[level]; }),
                          over_draws([level](const SurfaceEnsemble::Member& m) { return m.median[level]; }),
                          over_draws([level](const SurfaceEnsemble::Member& m) { return m.last[level]; })});
  }
  out.series_names = {"area_fraction", "touched"};
  for (std::size_t level = 0; level < L; ++level) out.series_names.push_back("touched_" + std::to_string(level));
  return out;
}

std::pair<SurfaceRun, std::optional<SurfaceEnsemble>> evaluate_surface_ensemble(const input::Keywords& keywords) {
  const input::PointMaterial material = input::find_point_material(keywords);
  const po::variables_map vm = input::parse_keywords(keywords, surface_options(material), "surface");
  SurfaceRun run = read_surface(vm, material);
  if (run.seeds == 1) {
    evaluate(run, false);
    return {std::move(run), std::nullopt};
  }
  SurfaceEnsemble ensemble = evaluate_ensemble(run, vm, material, false);
  return {std::move(run), std::move(ensemble)};
}

TextureParts texture_parts(const input::Keywords& keywords, const MoreLoadPoints& also_held) {
  return with_keywords(keywords, [&](SurfaceRun& run) {
    TextureParts out;
    if (tables_answer(run)) {
      model::ContactProblem periodic = run.inputs.problem;
      periodic.localization = model::Localization{.periodic = true};
      run.curve_source = CurveSource::tables;
      out.parts = std::make_unique<model::LocalizationParts>(periodic);
    } else {
      evaluate(run, false, also_held);
      out.parts = std::make_unique<model::CurveParts>(std::move(run.curve));
    }
    out.run = std::move(run);
    return out;
  });
}

reference::Cell surface_cell(const input::Keywords& keywords) {
  return with_keywords(keywords, [](SurfaceRun& run) {
    const model::CreepWeightedLoad load(*run.inputs.creep, run.inputs.problem.pbar0, run.inputs.problem.loading);
    const reference::PeriodicGrid grid = boundary_element_grid(run, load);
    return boundary_element_cell(run, grid, false);
  });
}

TextureGeometry texture_geometry(const input::Keywords& keywords) {
  return with_keywords(keywords, [](SurfaceRun& run) {
    if (run.measured) {
      throw input::UsageError("--height-map: a measured map's cell is its heights, not caps at drops that could be "
                              "moved; its design finds the pressure (--find pressure)");
    }
    if (run.grid_nodes == 0) throw std::invalid_argument("texture_geometry: the grid must be fixed, not auto");
    const model::CreepWeightedLoad load(*run.inputs.creep, run.inputs.problem.pbar0, run.inputs.problem.loading);
    reference::PeriodicGrid grid = boundary_element_grid(run, load);
    return TextureGeometry{std::move(run.geometry), std::move(grid), run.supercell, run.cell_file};
  });
}

SurfaceRun step_surface(const input::Keywords& keywords, const reference::Cell& cell) {
  return with_keywords(keywords, [&](SurfaceRun& run) {
    const model::CreepWeightedLoad load(*run.inputs.creep, run.inputs.problem.pbar0, run.inputs.problem.loading);
    boundary_element_grid(run, load);  // (the geometry as the cell's: a cell file's tips snapped)
    step_in_time(run, cell);
    return std::move(run);
  });
}

double estimated_curve_seconds(const reference::PeriodicGrid& grid, double caps) {
  // Fitted (log-linear least squares) to curves built on one core here: see
  // docs/performance.md for the runs and each one's ratio to this estimate.
  return kCurveSecondsScale * std::pow(static_cast<double>(grid.nodes()), kCurveSecondsNodePower) *
         std::pow(caps, kCurveSecondsCapPower) *
         (grid.mirrored() ? kCurveSecondsMirrored : grid.mirrored_x() ? kCurveSecondsMirroredX : 1.0);
}

SurfaceCheck check_surface(const input::Keywords& keywords) {
  return with_keywords(keywords, [](SurfaceRun& run) {
    SurfaceCheck out{0.0, run.times.size()};
    // The tables need no cell; where they may not reach the lattice's dh (auto), the cell's
    // refusals come when it is built.
    if (run.curve_source != CurveSource::cell) return out;
    for (const int nodes : cell_grids(run)) {
      out.seconds += estimated_curve_seconds(curve_grid(run, nodes), static_cast<double>(run.geometry.sites.size()));
    }
    return out;
  });
}

CurveCost curve_cost(const input::Keywords& keywords, const MoreLoadPoints& also_held) {
  return with_keywords(keywords, [&](SurfaceRun& run) { return curve_cost(run, also_held); });
}

}  // namespace punchsweep::engine
