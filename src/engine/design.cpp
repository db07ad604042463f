#include "engine/design.hpp"

#include <boost/program_options.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "engine/surface_evaluation.hpp"
#include "input/scaled_value.hpp"
#include "input/usage_error.hpp"
#include "model/laws/time_shift.hpp"
#include "model/load/creep_weighted_load.hpp"
#include "model/numerics/number_text.hpp"
#include "model/numerics/root_finding.hpp"
#include "model/point/point_evaluation.hpp"
#include "model/point/sensitivity.hpp"
#include "model/problem/cell_geometry.hpp"
#include "model/problem/parameter.hpp"
#include "model/surface/surface_advisory.hpp"
#include "model/surface/small_spot_touchdown.hpp"
#include "reference/level_closure.hpp"
#include "reference/periodic_grid.hpp"
#include "sweep/reproducible_fft.hpp"

namespace po = boost::program_options;

namespace punchsweep::engine {

/// Lengths in R's physical unit where --R is given, else in R.
Unit length_unit(const input::PointInputs& in) {
  if (const auto u = input::physical_unit("R", in.scales)) return {u->per_scaled, u->units};
  return {1.0, "R"};
}

/// Pressures in Pa, kPa or MPa (whichever `typical`, in E0*, reads in as 1 to 1000) where the
/// material gives a modulus, else in E0*.
Unit pressure_unit(const input::PointInputs& in, double typical) {
  if (const auto u = input::physical_unit("E0/(1-nu^2)", in.scales)) {
    const double pa = typical * u->per_scaled;
    if (pa >= 1e6) return {u->per_scaled / 1e6, "MPa"};
    if (pa >= 1e3) return {u->per_scaled / 1e3, "kPa"};
    return {u->per_scaled, "Pa"};
  }
  return {1.0, "E0*"};
}

std::string pressure_text(double pbar, const input::PointInputs& in) {
  const Unit u = pressure_unit(in, pbar);
  return model::number_text(pbar * u.per, 4) + " " + u.unit;
}

OwnTolerance own_tolerance(const DesignTolerance& box, std::string_view quantity) {
  if (quantity == model::kPitch) return {box.l, !box.l_absolute};
  if (quantity == model::kPressure) return {box.pressure, !box.pressure_absolute};
  return {box.dh, false};
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
/// The hottest temperature a design takes, in degC: no polymer's shift was ever measured
/// near it (a material's own T_max, where it states one, is the tighter bound).
constexpr double kMaxTemperature = 1e4;


/// The design command's own options, and every other one (the point's) as keywords.
struct DesignArgs {
  std::vector<std::string> requirement_texts;
  std::optional<std::string> temperature, tolerance;
  std::string format = "table";
  bool help = false;
  /// What the window is of: dh (given l); l (given dh; --l is then the range searched); or
  /// pbar, the nominal pressure (given dh and l; --pressure or --pbar is the range searched).
  std::string find = "dh";
  std::optional<std::string> dh;
  std::string pressure_option, pressure_range;  ///< --find pressure: "--pressure", "1kPa..100kPa"
  /// A texture of `surface` (docs/design.md, "Any texture"): --lattice, --dh2 (a third
  /// level's drop, fixed unless --find dh2), --grid (nodes per pitch, or auto) and --level
  /// (whose touch the requirements state, with --find l or pressure).
  std::optional<std::string> lattice, dh2, grid, level;
  /// A scattered supercell (surface's --supercell, --scatter, --seed): with --find pressure.
  std::optional<std::string> supercell, scatter, seed;
  bool scattered() const { return supercell || scatter || seed; }
  /// A cell file or a measured height map (surface's --cell, --height-map and the map's
  /// --pixel, --height-unit, --summit-radius, --prominence, --level-gap), as given: with --find pressure.
  input::Keywords texture_file;
  bool from_file() const { return !texture_file.empty(); }
  /// Read off the texture's load curve (every cap's touchdown), not solved per load.
  bool off_curve() const { return scattered() || from_file(); }
  /// Whether the design reads that curve (--find pressure); a drop or pitch window of these
  /// textures closes the level on their cell (one contact solve a trial), as a lattice's.
  bool by_curve() const { return off_curve() && find == model::kPressure; }
  input::Keywords point;
  /// Whether the design is of a texture's cell (any texture option given, or --find dh2),
  /// solved by its boundary elements, rather than of the paper's lattice by the model.
  bool texture() const { return lattice || dh2 || grid || level || find == "dh2" || off_curve(); }
};

DesignArgs split_keywords(const input::Keywords& keywords) {
  DesignArgs a;
  // Every option once, as the other commands take them (--require repeats, one per
  // requirement); --pbar and --pressure are one option, the pressure.
  std::vector<std::string> seen;
  for (const auto& [name, value] : keywords) {
    if (name == "require") continue;
    for (const std::string& earlier : seen) {
      if (earlier == name) {
        throw input::UsageError("option '--" + name + "' cannot be specified more than once (see punchsweep design --help)");
      }
      if ((earlier == "pbar" && name == "pressure") || (earlier == "pressure" && name == "pbar")) {
        throw input::UsageError("--" + name + " beside --" + earlier + ": the pressure is given twice (--pbar and "
                                "--pressure are one option); give it once");
      }
    }
    seen.push_back(name);
  }
  for (const auto& [name, value] : keywords) {
    if (name == "require") {
      a.requirement_texts.push_back(value);
    } else if (name == "temperature") {
      a.temperature = value;
    } else if (name == "tolerance") {
      a.tolerance = value;
    } else if (name == "format") {
      a.format = value;
    } else if (name == "help") {
      a.help = true;
    } else if (name == "find") {
      a.find = value == "pressure" ? std::string(model::kPressure) : value;
    } else if (name == "dh") {
      a.dh = value;
    } else if (name == "lattice") {
      a.lattice = value;
    } else if (name == "dh2") {
      a.dh2 = value;
    } else if (name == "grid") {
      a.grid = value;
    } else if (name == "level") {
      a.level = value;
    } else if (name == "supercell") {
      a.supercell = value;
    } else if (name == "scatter") {
      a.scatter = value;
    } else if (name == "seed") {
      a.seed = value;
    } else if (name == "curvature-scatter") {
      throw input::UsageError("--curvature-scatter: a design's caps keep one shape a level (surface and maps take "
                              "scattered curvatures)");
    } else if (name == "seeds") {
      throw input::UsageError("--seeds: a design answers one drawn supercell (--seed); an ensemble's spread is "
                              "surface --seeds N's, at the edges the design gives");
    } else if (name == "cell" || name == "height-map" || name == "pixel" || name == "height-unit" ||
               name == "summit-radius" || name == "prominence" || name == "level-gap") {
      a.texture_file.emplace_back(name, value);
    } else if (name == "pbar" || name == "pressure") {
      a.pressure_option = "--" + name;
      a.pressure_range = value;
    } else {
      a.point.emplace_back(name, value);
    }
  }
  if (a.format != "table" && a.format != "json") {
    throw input::UsageError("--format = " + a.format + " is not one of: table, json");
  }
  if (a.find != "dh" && a.find != "dh2" && a.find != "l" && a.find != model::kPressure) {
    throw input::UsageError("--find = " + a.find + " is not one of: dh, dh2, l, pressure");
  }
  if (a.find == "dh2" && a.dh2) {
    throw input::UsageError("--dh2: the design finds dh2 (--find dh2); state what it must do with --require");
  }
  if (a.find == "dh2" && !a.dh && !a.from_file()) {
    throw input::UsageError("--find dh2 needs --dh, the drop of level 1 (the third level's is what the design finds)");
  }
  if (a.level && a.find != "l" && a.find != model::kPressure && !(a.from_file() && a.find == "dh")) {
    throw input::UsageError("--level: with --find " + a.find + " the requirements are on the level whose drop is found; "
                            "--level names the level they are on with --find l or pressure");
  }
  if (a.from_file()) {
    const std::string& file = a.texture_file.front().first;
    const bool measured = std::any_of(a.texture_file.begin(), a.texture_file.end(),
                                      [](const auto& kv) { return kv.first == "height-map"; });
    if (measured && a.find != model::kPressure) {
      throw input::UsageError("--height-map: a measured map's design finds the pressure (--find pressure, from one load "
                              "curve of its caps); its drops and pitch are the part's");
    }
    if (a.find == "l") {
      throw input::UsageError("--" + file + ": a cell file's design finds a level's drop (--find dh, with --level L) or "
                              "the pressure (--find pressure); its sites are the file's, so it has no pitch to search");
    }
    for (const auto& [name, given] : std::vector<std::pair<const char*, bool>>{
             {"dh", a.dh.has_value()}, {"dh2", a.dh2.has_value()}, {"lattice", a.lattice.has_value()}}) {
      if (given) {
        throw input::UsageError(std::string("--") + name + " beside --" + a.texture_file.front().first +
                                ": the file gives the cell, its sites and their drops");
      }
    }
  }
  if (a.level && a.from_file()) {
    bool digits = !a.level->empty() && a.level->size() < 4;
    for (const char c : *a.level) digits = digits && std::isdigit(static_cast<unsigned char>(c));
    if (!digits || std::stoi(*a.level) < 1) {
      throw input::UsageError("--level = " + *a.level + " is outside its range: a level of the texture from 1");
    }
  } else if (a.level && *a.level != "1" && *a.level != "2") {
    throw input::UsageError("--level = " + *a.level + " is outside its range: 1, or 2 with --dh2");
  }
  if (a.level && *a.level == "2" && !a.dh2 && !a.from_file()) {
    throw input::UsageError("--level 2 needs --dh2, the drop of level 2");
  }
  if (a.lattice && *a.lattice != "square" && *a.lattice != "hexagonal") {
    throw input::UsageError("--lattice = " + *a.lattice + " is not one of: square, hexagonal");
  }
  const bool by_pressure = a.find == model::kPressure;
  const std::string find_name = by_pressure ? "pressure" : a.find;
  if (a.find == "dh" && a.dh) {
    throw input::UsageError("--dh: the design finds dh; state what it must do with --require (or --find l, the "
                            "pitch for a given dh, or --find pressure)");
  }
  if ((a.find == "l" || a.find == model::kPressure) && !a.dh && !a.from_file()) {
    throw input::UsageError("--find " + find_name + " needs --dh, the height difference the " +
                            (by_pressure ? "pressure" : "pitch") + " is for");
  }
  if (!by_pressure && !a.pressure_option.empty()) {
    throw input::UsageError(a.pressure_option + ": each --require names its pressure ('touch within 1s at 30kPa'; "
                            "or --find pressure, the window of the pressure, searched over " + a.pressure_option +
                            " A..B)");
  }
  if (by_pressure && a.pressure_option.empty()) {
    throw input::UsageError("--find pressure needs --pressure A..B (or --pbar A..B), the pressures to search, as "
                            "1kPa..100kPa");
  }
  return a;
}


std::string trimmed(const std::string& s) { return std::string(model::trim(s, " \t")); }

/// One of the requirement's forms (kRequirementForms), its time and pressure read in the
/// point's scales; without a pressure (NaN) where the design finds it (`find_pressure`).
/// `pressure_written` gets the pressure as the requirement writes it.
Requirement read_requirement(const std::string& text, const input::PhysicalScales& scales, bool find_pressure,
                             std::string* pressure_written) {
  const auto bad = [&](const std::string& why) {
    return input::UsageError("--require '" + text + "': " + why + " (" + kRequirementForms + ")");
  };
  // The words in any case and spacing; the time and pressure as typed (units are
  // case-sensitive: 30kPa, 5MPa, 2ms).
  const std::string flat = std::regex_replace(trimmed(text), std::regex("\\s+"), " ");
  const auto form = [&](const char* pattern, std::smatch& m) {
    return std::regex_match(flat, m, std::regex(pattern, std::regex::icase));
  };
  std::smatch m;
  Requirement r;
  r.text = trimmed(text);
  std::string time_text, pressure_text;
  // Each form's pressure, " at PRESSURE", is its last group, optional here and checked below.
  // A share of caps: "90% of level 1 within 1min", "at most 5% of caps within 1s".
  static const char* kShare = "([0-9]{1,6}(?:\\.[0-9]{0,12})?) ?% of (?:level ([0-9]{1,3})(?:'s caps)?|(?:all |the |every )?caps)"
                              "(?: (?:within|by) (.+?)| ever)?(?: at (.+))?";
  std::smatch share;
  const bool at_most = std::regex_match(flat, share, std::regex(std::string("at most ") + kShare, std::regex::icase));
  if (at_most || std::regex_match(flat, share, std::regex(kShare, std::regex::icase))) {
    r.kind = at_most ? Requirement::Kind::no_touch_by : Requirement::Kind::touch_by;
    r.share = std::stod(share[1]) / 100.0;
    if (!(r.share >= 0.0 && r.share <= 1.0)) throw bad("the share " + std::string(share[1]) + "% is outside 0% to 100%");
    r.share_level = share[2].matched ? std::stoi(share[2]) : -1;
    if (share[2].matched && r.share_level == 0) throw bad("level 0 (the tallest caps) touches at once; a share of level 1 or 2, or of caps");
    r.time = kInf;
    time_text = share[3];
    m = share;
  } else if (form("touch (?:within|by) (.+?)(?: at (.+))?", m)) {
    time_text = m[1];
  } else if (form("touch (?:at once|immediately)(?: at (.+))?", m)) {
  } else if (form("touch(?: ever| eventually)?(?: at (.+))?", m)) {
    r.time = kInf;
  } else if (form("(?:never|no touch)(?: at (.+))?", m)) {
    r.kind = Requirement::Kind::no_touch_by;
    r.time = kInf;
  } else if (form("(?:no touch|not) (?:within|by) (.+?)(?: at (.+))?", m)) {
    r.kind = Requirement::Kind::no_touch_by;
    time_text = m[1];
  } else {
    throw bad("not a requirement");
  }
  pressure_text = m[m.size() - 1];
  *pressure_written = trimmed(pressure_text);
  if (find_pressure && !pressure_text.empty()) {
    throw bad("the design finds the pressure (--find pressure): state the requirement without 'at " + pressure_text + "'");
  }
  if (!find_pressure && pressure_text.empty()) throw bad("no pressure: say at which, as 'at 30kPa'");
  r.pbar = kNaN;
  try {
    if (!time_text.empty()) {
      r.time = input::read_scaled(time_text, *input::scale_of("T_eps", scales));
      if (!(std::isfinite(r.time) && r.time >= 0.0)) throw std::invalid_argument("the time is not finite and >= 0");
    }
    if (!find_pressure) {
      r.pbar = input::read_scaled(pressure_text, *input::scale_of("E0/(1-nu^2)", scales));
      if (!(std::isfinite(r.pbar) && r.pbar > 0.0)) throw std::invalid_argument("the pressure is not finite and > 0");
    }
  } catch (const std::invalid_argument& e) {
    throw bad(e.what());
  }
  return r;
}

/// The temperature unit `text` ends with ("K", or "C" for C, degC and \u00b0C; "" for none),
/// taken off it.
std::string take_temperature_unit(std::string& text) {
  text = trimmed(text);
  for (const char* u : {"\xC2\xB0" "C", "degC", "C", "K"}) {
    const std::string s(u);
    if (text.size() > s.size() && text.compare(text.size() - s.size(), s.size(), s) == 0) {
      text = trimmed(text.substr(0, text.size() - s.size()));
      return s == "K" ? "K" : "C";
    }
  }
  return "";
}

/// A temperature "20", "20C", "20degC", "293.15K" in degC; `unit_after` where it has none.
double read_temperature(std::string text, const std::string& unit_after, const std::string& option) {
  std::string unit = take_temperature_unit(text);
  if (unit.empty()) unit = unit_after;
  double v = 0.0;
  try {
    std::size_t used = 0;
    v = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw input::UsageError(option + ": '" + text + "' is not a temperature (valid: a number with C, degC, "
                            "\xC2\xB0" "C or K, as 20C, or a range 20..40C)");
  }
  if (!std::isfinite(v)) throw input::UsageError(option + ": the temperature is not finite");
  const double celsius = unit == "K" ? v - model::kZeroCelsius : v;
  if (!(celsius > -model::kZeroCelsius && celsius <= kMaxTemperature)) {
    throw input::UsageError(option + ": " + model::number_text(celsius, 10) + " degC is outside its range: a temperature " +
                            "above absolute zero (-273.15 C) and at most " + model::number_text(kMaxTemperature, 10) +
                            " C (a material's shift holds only where it was measured)");
  }
  return celsius;
}

/// --temperature: one temperature or a range A..B (degC unless a unit says K; the end's unit
/// holds for the start too), widened by `widen` K on each side, sampled at
/// kTemperatureSamples temperatures.
std::vector<double> read_temperatures(const std::string& text, double widen) {
  const std::string option = "--temperature " + text;
  const std::size_t dots = text.find("..");
  std::vector<double> out;
  if (dots == std::string::npos) {
    const double t = read_temperature(text, "C", option);
    if (widen > 0.0) return read_temperatures(model::number_text(t, 17) + ".." + model::number_text(t, 17), widen);
    return {t};
  }
  const std::string hi_text = text.substr(dots + 2);
  std::string bare = hi_text;
  std::string unit = take_temperature_unit(bare);
  if (unit.empty()) unit = "C";
  const double lo = read_temperature(text.substr(0, dots), unit, option) - widen;
  const double hi = read_temperature(hi_text, unit, option) + widen;
  if (!(hi > lo)) throw input::UsageError(option + ": the range's end is not above its start");
  for (int k = 0; k < kTemperatureSamples; ++k) out.push_back(lo + (hi - lo) * k / (kTemperatureSamples - 1));
  return out;
}

/// --tolerance as the design reads it: the point's tolerance syntax (input::parse_tolerances)
/// on dh (a length: dh is what is found), the pressure (% or a pressure), l and C (% or a
/// value) and temperature (K: the range widened); a relative one below 100%.
DesignTolerance read_tolerance(const std::string& text, const input::PointInputs& base) {
  const auto known = [](std::string_view name) -> const model::Parameter* {
    for (const std::string_view n : {model::kHeightDifference, model::kPressure, model::kPitch, model::kShapeConstant}) {
      if (name == n) return model::problem_parameter(n);
    }
    return name == model::temperature_parameter().name ? &model::temperature_parameter() : nullptr;
  };
  const auto refuse = [&](const model::StatedTolerance& t) -> std::string {
    const std::string_view name = t.parameter->name;
    if (name == model::kHeightDifference && t.relative) return "dh is what the design finds: give its tolerance as a length";
    if (name == model::temperature_parameter().name && t.relative) return "a temperature's tolerance is a difference in K";
    const double relative = name == model::kShapeConstant && !t.relative ? t.width / base.problem.shape.C : t.width;
    if ((t.relative || name == model::kShapeConstant) && !(relative < 1.0)) {
      return "a relative tolerance of 100% or more leaves nothing of the value";
    }
    return {};
  };
  DesignTolerance box;
  for (const model::StatedTolerance& t :
       input::parse_tolerances(text, "--tolerance", known, base.scales,
                               "dh (a length, 0.5um), pressure (10% or 2kPa), l and C (5% or a value), temperature (2K)",
                               "is no tolerance the design takes", refuse)) {
    const std::string_view name = t.parameter->name;
    if (name == model::kHeightDifference) box.dh = t.width;
    if (name == model::kPressure) std::tie(box.pressure, box.pressure_absolute) = std::pair{t.width, !t.relative};
    if (name == model::kPitch) std::tie(box.l, box.l_absolute) = std::pair{t.width, !t.relative};
    if (name == model::kShapeConstant) box.C = t.relative ? t.width : t.width / base.problem.shape.C;
    if (name == model::temperature_parameter().name) box.temperature = t.width;
  }
  return box;
}

/// `base` without `name`.
input::Keywords without(input::Keywords base, const std::string& name) {
  base.erase(std::remove_if(base.begin(), base.end(), [&](const auto& kv) { return kv.first == name; }), base.end());
  return base;
}

/// `base` with `name` set to `value` (replacing it where given).
input::Keywords with(input::Keywords base, const std::string& name, const std::string& value) {
  base = without(std::move(base), name);
  base.emplace_back(name, value);
  return base;
}

/// Pressures, pitches and shape factors of the box's corners about (pbar, l, C).

std::vector<double> sides(double value, double tolerance, bool absolute) {
  if (tolerance == 0.0) return {value};
  return absolute ? std::vector<double>{value - tolerance, value + tolerance}
                  : std::vector<double>{value * (1 - tolerance), value * (1 + tolerance)};
}


/// The load at which requirement `r` turns on a curve of every cap (a scattered supercell's):
/// the touchdowns of the caps it counts (`level`'s, or every cap's for -1; a hidden cap's is
/// +infinity), sorted; touch_by (at least the share touched) holds from the m-th least, m =
/// ceil(share n) (1 for the level's first cap); no_touch_by (at most the share) until the
/// (m+1)-th least, m = floor(share n) (0 for none). 0 where m = 0 for touch_by, +infinity
/// where no cap past m touches within the curve.
double share_load(const model::LoadCurve& curve, int level, const Requirement& r) {
  std::vector<double> touchdowns;
  for (std::size_t k = 0; k < curve.sites(); ++k) {
    if (level < 0 || curve.site_level[k] == level) touchdowns.push_back(curve.site_touchdown[k]);
  }
  std::sort(touchdowns.begin(), touchdowns.end());
  const double n = static_cast<double>(touchdowns.size());
  if (r.kind == Requirement::Kind::touch_by) {
    const std::size_t m = r.is_share() ? static_cast<std::size_t>(std::ceil(r.share * n - 1e-9)) : 1;
    return m == 0 ? 0.0 : m > touchdowns.size() ? kInf : touchdowns[m - 1];
  }
  const std::size_t m = r.is_share() ? static_cast<std::size_t>(std::floor(r.share * n + 1e-9)) : 0;
  return m >= touchdowns.size() ? kInf : touchdowns[m];
}

/// The most closures (each a grid's fields) a texture's design keeps at once.
constexpr std::size_t kKeptClosures = 4;

/// A texture's search for a pitch or pressure stops within this of the value's log.
constexpr double kTextureSearchTolerance = 1e-9;

/// --dh2 TEXT: the third level's drop, read as `surface` reads it (a length with --R, or in
/// R; >= 0).
double read_drop(const std::string& name, const std::string& text, const input::PhysicalScales& scales) {
  po::options_description o;
  o.add_options()(name.c_str(), po::value<std::string>());
  const po::variables_map vm = input::parse_keywords({{name, text}}, o, "design");
  return input::read_parameter(vm, *model::texture_parameter(model::kThirdLevelDrop), &scales);
}

/// A texture's cell at a pitch and shape (l and C vary over --find l and the tolerance box),
/// with the grid its closures solve on.
using TextureCellMaker = std::function<engine::TextureGeometry(double l, const model::Shape& shape)>;

/// The least drop of each level from 1 of `geometry` (a level's caps may differ: a
/// supercell's scatter, a cell file's sites), in R.
std::vector<double> least_drops(const model::CellGeometry& geometry) {
  std::vector<double> drops(static_cast<std::size_t>(std::max(geometry.levels() - 1, 0)), kInf);
  for (const model::Site& site : geometry.sites) {
    if (site.level > 0) drops[static_cast<std::size_t>(site.level - 1)] = std::min(drops[static_cast<std::size_t>(site.level - 1)], site.drop);
  }
  return drops;
}

/// The drop the searched level of a texture closes by a time (docs/design.md, "Any
/// texture"): its closure at the creep-weighted load of that time (reference::LevelClosure,
/// exact where the model's dh_touching_at is for the paper's lattice: until the level
/// touches, its drop changes nothing), one closure per corner's pitch and shape factor, on
/// the maker's grid. A level whose caps scatter moves as one: the drop is the level's design
/// drop, which lies `shift` above its tallest cap's (the scatter's draws and the supercell's
/// tallest tip set it; 0 on a lattice and for a cell file, whose level's drop is its tallest
/// cap's). A requirement on a share of the level's caps closes the cap that decides it (the
/// m-th to touch, as share_load counts them) by the closure's bisection over the drop. Each
/// load is solved once (temperatures and corners that meet the same load share it).
class TextureGap {
 public:
  /// `design_drop`: the searched level's drop as the maker's cells are made with it.
  TextureGap(TextureCellMaker make, int level, double design_drop)
      : make_(std::move(make)), level_(level), design_drop_(design_drop) {}

  /// The drop closed by time t (0: at once; +infinity: ever) under the problem's pressure
  /// and load on `creep`, at its pitch and shape, for requirement `r` (its level's first cap,
  /// or its share of the level's caps: then -infinity where no drop from 0 brings that
  /// share down by then, +infinity where a share of none asks nothing); +infinity where the
  /// law creeps without end. For a share of another level's caps (reversed(r)): the least
  /// drop at which that share has touched by then (it touches the sooner the deeper the
  /// searched level lies), +infinity where not even at its deepest, -infinity where a share
  /// of none asks nothing.
  double operator()(const model::ContactProblem& problem, const model::CreepLaw& creep, double t, const Requirement& r) {
    const model::CreepWeightedLoad load(creep, problem.pbar0, problem.loading);
    const double X = load.by(t);
    if (std::isinf(X)) return kInf;
    // A closure holds its grid's fields (tens of MB at 256 nodes a pitch): --find l asks a
    // new pitch at every trial, so only the last few are kept (a box has at most 4 corners
    // of l and C).
    Closure& closure = made(problem);
    // The cap that decides: touch_by holds once the ceil(S n)-th has touched, no_touch_by
    // until the (floor(S n) + 1)-th has (share_load's counts; the first cap for both without
    // a share), of the level's caps or of every cap of the cell.
    const bool every = r.is_share() && r.share_level < 0, other = reversed(r);
    const int level = every ? reference::LevelClosure::kEveryLevel : other ? r.share_level : level_;
    const std::size_t counted = every ? closure.made->geometry.sites.size() : closure.caps_of[static_cast<std::size_t>(level)];
    const double n = static_cast<double>(counted);
    const std::size_t cap = !r.is_share() ? 1
                            : r.kind == Requirement::Kind::touch_by
                                ? static_cast<std::size_t>(std::ceil(r.share * n - 1e-9))
                                : static_cast<std::size_t>(std::floor(r.share * n + 1e-9)) + 1;
    if (cap == 0) return other ? -kInf : kInf;        // at least none: any drop
    if (cap > counted) return other ? kInf : -kInf;   // at most all: no drop
    const std::array<double, 5> key{problem.l, problem.shape.C, X, static_cast<double>(cap), static_cast<double>(level)};
    if (const auto found = known_.find(key); found != known_.end()) return found->second;
    // Where the spots in contact are small at X, the small-spot limit answers, as it answers
    // `surface`'s touchdowns there (docs/model.md 17.6): one answer for both. The first cap
    // of the level from one state; a share of caps by bisection over the drop, each trial the
    // limit's touchdowns.
    std::optional<model::SmallSpotCount> limit;
    if (cap == 1 && level == level_) {
      if (const std::optional<double> drop = closure.limit->level_closure(X)) limit = model::SmallSpotCount{*drop, true};
    } else {
      limit = closure.limit->counting(X, cap, every ? model::SmallSpotLimit::kEveryLevel : level);
    }
    if (limit) {
      ++small_spot_;
      if (!limit->steady) unsteady_.insert(r.text);
      return known_[key] = limit->drop + closure.shift;
    }
    const reference::LevelClosed closed = solver(closure).counting(X, cap, level);
    if (!closed.steady) unsteady_.insert(r.text);
    if (other) {
      solves_ += closed.solves;
      // (Not even with the level at its deepest, "at least" the share holds at no drop; even
      // with it at the top, "at most" holds at none.)
      if (closed.drop == (r.kind == Requirement::Kind::touch_by ? kInf : -kInf)) unreachable_.insert(r.text);
      return known_[key] = closed.drop + closure.shift;  // (+-infinity stays)
    }
    if (every && closed.every_drop) {
      // So many caps touch even with the level at its deepest that "at most" the share holds
      // at no drop, and "at least" at every one (its bound the deepest, as a level's).
      (r.kind == Requirement::Kind::no_touch_by ? unreachable_ : reached_).insert(r.text);
      if (r.kind == Requirement::Kind::no_touch_by) return known_[key] = kInf;
    } else {
      every_drop_ = every_drop_ || closed.every_drop;
    }
    solves_ += closed.solves;
    return known_[key] = closure.shift == 0.0 ? closed.drop : closed.drop + closure.shift;
  }
  /// The advisories of the cell at load X (E0*) with the searched level at its design drop
  /// `drop` (R), at the problem's pitch and shape: its caps' contact radii from one contact
  /// solve of the cell (LevelClosure::state), the level's drop clipped to where it is a cap
  /// of its own.
  model::SurfaceAdvisories advice(const model::ContactProblem& problem, double X, double drop) {
    Closure& closure = made(problem);
    reference::LevelClosure& solve = solver(closure);
    const double at = std::clamp(drop - closure.shift, 0.0, solve.deepest());
    return model::advise_surface(closure.made->geometry, solve.state(X, at));
  }

  /// Whether some load pressed the level's tips at any drop it can have (its bound is then
  /// the deepest at which it is still a punch of its own).
  bool every_drop() const { return every_drop_; }
  int solves() const { return solves_; }
  int small_spot() const { return small_spot_; }
  /// Whether requirement `text`'s count of every cap rose somewhere as the level sank (its
  /// edge is then one crossing of the count, not the window's whole bound).
  bool unsteady(const std::string& text) const { return unsteady_.contains(text); }
  /// Whether requirement `text` ("at most" a share of every cap) is past reach at every drop:
  /// at its deepest the level leaves more caps touching than it allows.
  bool unreachable(const std::string& text) const { return unreachable_.contains(text); }
  /// Whether requirement `text` (at least a share of every cap) holds with the level at its
  /// deepest: the other levels' caps reach the share.
  bool reached(const std::string& text) const { return reached_.contains(text); }
  int level() const { return level_; }
  /// Whether `r` asks for a share of another level's caps than the searched one's: its drop
  /// (operator()) is then the least at which the share touches, a lower edge of the drop.
  bool reversed(const Requirement& r) const { return r.is_share() && r.share_level > 0 && r.share_level != level_; }

 private:
  struct Closure {
    std::unique_ptr<const engine::TextureGeometry> made;
    std::unique_ptr<const model::SmallSpotLimit> limit;  ///< of made's geometry
    std::unique_ptr<reference::LevelClosure> solve;      ///< built where the limit does not answer
    double shift = 0.0;
    std::vector<std::size_t> caps_of;  ///< of each level
  };
  /// The closure's contact solves, made at the first that the limit does not answer.
  reference::LevelClosure& solver(Closure& closure) {
    if (!closure.solve) closure.solve = std::make_unique<reference::LevelClosure>(closure.made->geometry, level_, closure.made->grid);
    return *closure.solve;
  }
  /// The closure of the problem's pitch and shape, its cell made where it is new.
  Closure& made(const model::ContactProblem& problem) {
    if (closures_.size() >= kKeptClosures && !closures_.contains({problem.l, problem.shape.C})) closures_.clear();
    Closure& closure = closures_[{problem.l, problem.shape.C}];
    if (!closure.made) {
      closure.made = std::make_unique<const engine::TextureGeometry>(make_(problem.l, problem.shape));
      closure.limit = std::make_unique<const model::SmallSpotLimit>(closure.made->geometry, level_);
      closure.shift = design_drop_ - least_drops(closure.made->geometry)[static_cast<std::size_t>(level_ - 1)];
      closure.caps_of.assign(static_cast<std::size_t>(closure.made->geometry.levels()), 0);
      for (const model::Site& site : closure.made->geometry.sites) ++closure.caps_of[static_cast<std::size_t>(site.level)];
    }
    return closure;
  }

  TextureCellMaker make_;
  int level_;
  double design_drop_;
  std::map<std::array<double, 5>, double> known_;
  std::set<std::string> unsteady_, unreachable_, reached_;
  std::map<std::pair<double, double>, Closure> closures_;
  bool every_drop_ = false;
  int solves_ = 0;
  int small_spot_ = 0;
};

DesignResult design_pass(const DesignArgs& a, int nodes) {
  if (a.requirement_texts.empty()) throw input::UsageError("give at least one --require (" + std::string(kRequirementForms) + ")");
  const input::PointMaterial material = input::find_point_material(a.point);
  const po::options_description opts = input::point_options(material);
  // The options of `surface` the design does not take (--curve, --check) are refused by
  // name, not as "unknown option".
  const po::options_description texture_options = engine::surface_options(material);
  for (const auto& [name, value] : a.point) {
    if (opts.find_nothrow(name, false) == nullptr && texture_options.find_nothrow(name, false) != nullptr) {
      throw input::UsageError("--" + name + " is a texture option of `punchsweep surface` that design does not take: the "
                              "design solves a lattice's cell by its boundary elements (--grid) and reads a scattered "
                              "supercell's, a cell file's or a height map's load curve");
    }
  }
  const bool has_temperature =
      std::any_of(material.spec.parameters.begin(), material.spec.parameters.end(),
                  [](const model::Parameter& p) { return p.name == model::temperature_parameter().name; });
  if (a.temperature && !has_temperature) {
    throw input::UsageError("--temperature: " + std::string(material.material
                                ? "this material file has no [shift], so its law takes no temperature"
                                : "a material's temperature: give --material FILE, a material file with a [shift]"));
  }
  // Each point the design reads goes through the point command's options and checks.
  const auto point_at = [&](const input::Keywords& keywords, const std::string& what) {
    try {
      const po::variables_map vm = input::parse_keywords(keywords, opts, "design");
      input::PointInputs in = input::read_point_inputs(vm, material);
      in.problem.localization = input::read_localization(vm);
      return in;
    } catch (const input::UsageError& e) {
      throw input::UsageError(what.empty() ? std::string(e.what()) : what + ": " + e.what());
    }
  };
  const bool by_l = a.find == model::kPitch, by_pressure = a.find == model::kPressure;
  const std::string find_name = by_pressure ? "pressure" : a.find;
  // --find l or pressure: the quantity is searched over a range, at each corner of the rest.
  const bool searched = by_l || by_pressure;
  DesignResult out;
  out.quantity = a.find;
  // The range searched: --l 100um..400um, or --pressure 1kPa..100kPa (--pbar in E0*).
  std::string range_option = "--l", range_text;
  if (by_pressure) {
    std::tie(range_option, range_text) = std::pair{a.pressure_option, a.pressure_range};
  } else {
    for (const auto& [name, value] : a.point) {
      if (name == "l") range_text = value;
    }
  }
  const std::string range_key = range_option.substr(2);
  std::string range_lo_text = range_text, range_hi_text;
  if (searched) {
    const std::size_t dots = range_text.find("..");
    if (dots == std::string::npos) {
      throw input::UsageError(range_option + " " + (range_text.empty() ? std::string("(missing)") : range_text) +
                              ": with --find " + (by_l ? "l, the range of pitches to search, as 100um..400um"
                                                       : "pressure, the range of pressures to search, as 1kPa..100kPa"));
    }
    range_lo_text = trimmed(range_text.substr(0, dots));
    range_hi_text = trimmed(range_text.substr(dots + 2));
  }
  input::Keywords base_keywords = with(a.point, "dh", searched || a.find == "dh2" ? a.dh.value_or("0") : "0");
  // A cell file or height map gives the geometry: the point's reading (the material, the
  // scales, the pressure) takes a pitch and exponent that stand for nothing (not shown, not
  // passed on); one given beside the file is refused by surface's reading.
  std::vector<std::string> placeholders;
  if (a.from_file()) {
    for (const char* name : {"l", "s"}) {
      if (std::none_of(a.point.begin(), a.point.end(), [&](const auto& kv) { return kv.first == name; })) {
        base_keywords = with(base_keywords, name, name == std::string("l") ? "1" : "2");
        placeholders.emplace_back(name);
      }
    }
  }
  if (by_l) base_keywords = with(base_keywords, "l", range_lo_text);
  // The scales first (a requirement's units need them): at a nominal pressure.
  std::optional<double> first_T;
  if (a.temperature) first_T = read_temperature(a.temperature->substr(0, a.temperature->find("..")), "C",
                                                "--temperature " + *a.temperature);
  input::Keywords probe = with(base_keywords, "pbar", "1e-6");
  if (first_T) probe = with(probe, "temperature", input::json_number(*first_T));
  const input::PointInputs scales_of_point = point_at(probe, "");
  std::vector<Requirement> requirements;
  for (const std::string& text : a.requirement_texts) {
    std::string pressure;
    requirements.push_back(read_requirement(text, scales_of_point.scales, by_pressure, &pressure));
    // A bare number is in the scale (docs/cli.md, "Units"), but beside a material that
    // gives a modulus a pressure is meant in Pa as often as not: say how it was read.
    if (!pressure.empty() && !input::has_unit(pressure) && scales_of_point.scales.E0_star) {
      out.notes.push_back("'" + requirements.back().text + "': its pressure " + pressure +
                          " has no unit, so it is in E0* = E0/(1-nu^2) of the material (docs/cli.md, Units): " +
                          pressure_text(requirements.back().pbar, scales_of_point) + "; give a unit (" + pressure +
                          "kPa) for a pressure in Pa");
    }
  }
  if (a.tolerance) out.tolerance = read_tolerance(*a.tolerance, scales_of_point);
  const DesignTolerance& box = out.tolerance;
  if (a.temperature) out.temperatures = read_temperatures(*a.temperature, box.temperature);
  else if (box.temperature > 0.0) throw input::UsageError("--tolerance temperature: give --temperature too");
  // The search's ends, each read as the point reads that option (its unit, its range).
  const auto range_end = [&](const std::string& text) {
    input::Keywords k = with(probe, range_key, text);
    if (range_key == "pressure") k = without(k, "pbar");  // the probe's; one of the two
    const input::PointInputs in = point_at(k, range_option + " " + range_text);
    return by_l ? in.problem.l : in.problem.pbar0;
  };
  if (searched) {
    out.search_lo = range_end(range_lo_text);
    out.search_hi = range_end(range_hi_text);
    if (!(out.search_hi > out.search_lo)) {
      throw input::UsageError(range_option + " " + range_text + ": the range's end is not above its start");
    }
  }
  out.inputs = point_at(with(probe, "pbar", input::json_number(by_pressure ? out.search_lo : requirements.front().pbar)), "");
  // A scattered supercell's, a cell file's or a height map's options as `surface` takes
  // them, at the nominal pressure `pbar`.
  const auto texture_keywords = [&](double pbar) {
    input::Keywords k = with(base_keywords, "pbar", input::json_number(pbar));
    k = without(k, "pressure");
    if (a.from_file()) k = without(k, "dh");  // (the file's drops)
    for (const std::string& name : placeholders) k = without(k, name);
    for (const auto& [name, value] : std::vector<std::pair<std::string, std::optional<std::string>>>{
             {"lattice", a.lattice}, {"dh2", a.dh2}, {"supercell", a.supercell}, {"scatter", a.scatter},
             {"seed", a.seed}, {"grid", a.grid}}) {
      if (value) k = with(k, name, *value);
    }
    for (const auto& [name, value] : a.texture_file) k = with(k, name, value);
    return k;
  };
  // A texture: the lattice, each level's drop (the searched level's found, the others fixed)
  // and the level the requirements are on.
  std::optional<TextureGap> texture;
  double dh2 = kNaN;
  if (a.texture()) {
    // The closures' contact solves on FFTW plans chosen without timing them, as `surface`'s
    // curves: the same edges, to the bit, in every run (timed plans round differently).
    sweep::use_reproducible_fft_plans();
    DesignTexture& t = out.texture.emplace();
    t.lattice = a.lattice.value_or("square");
    if (a.dh2) dh2 = read_drop("dh2", *a.dh2, out.inputs.scales);
    t.level = a.find == "dh2" ? 2 : a.level ? std::stoi(*a.level) : 1;
    t.levels = a.dh2 || a.find == "dh2" ? 3 : 2;
    t.nodes = nodes;
    std::vector<double> drops{a.find == "dh" ? 0.0 : out.inputs.problem.dh};  // (the searched level's is set by the closure)
    if (t.levels == 3) drops.push_back(a.find == "dh2" ? 0.0 : dh2);
    t.drops = drops;
    if (!a.off_curve()) {
      const model::LatticeKind lattice = t.lattice == "square" ? model::LatticeKind::square : model::LatticeKind::hexagonal;
      const auto lattice_cell = [lattice, drops, nodes](double l, const model::Shape& shape) {
        model::CellGeometry g = model::lattice_cell(lattice, l, shape, drops);
        reference::PeriodicGrid grid = reference::lattice_grid(g, lattice, nodes);
        return engine::TextureGeometry{std::move(g), std::move(grid), 1, ""};
      };
      texture.emplace(lattice_cell, t.level, drops[static_cast<std::size_t>(t.level - 1)]);
    } else if (!by_pressure) {
      // A scattered supercell's or a cell file's drop or pitch: its cell made as `surface`
      // makes it, on `nodes` a pitch, each level's caps closed as one.
      const input::Keywords k = with(texture_keywords(out.inputs.problem.pbar0), "grid", std::to_string(nodes));
      engine::TextureGeometry probe_cell = engine::texture_geometry(k);
      t.caps = static_cast<int>(probe_cell.geometry.sites.size());
      t.supercell = probe_cell.supercell;
      t.scatter = a.scatter.value_or("");
      t.seed = a.scatter ? a.seed.value_or("1") : "";
      if (a.from_file()) {
        t.file = probe_cell.cell_file;
        t.lattice = "cell";
        t.levels = probe_cell.geometry.levels();
        t.drops = least_drops(probe_cell.geometry);
        t.level = a.find == "dh2" ? 2 : a.level ? std::stoi(*a.level) : 1;
        if (t.level > t.levels - 1) {
          throw input::UsageError("--level " + std::to_string(t.level) + ": the texture has levels 0 to " + std::to_string(t.levels - 1));
        }
        if (box.l > 0.0 || box.C > 0.0) {
          throw input::UsageError("--tolerance: a cell file's sites and shapes are the file's; its design takes "
                                  "tolerances on the drop, the pressure and the temperature");
        }
        const double file_drop = t.drops[static_cast<std::size_t>(t.level - 1)];
        t.drops[static_cast<std::size_t>(t.level - 1)] = 0.0;  // (found)
        texture.emplace([cell = std::move(probe_cell)](double, const model::Shape&) { return cell; }, t.level, file_drop);
      } else {
        // The searched level is made deep enough that another level holds the supercell's
        // tallest tip (the drops are counted from it): its caps' offsets below the level's
        // design drop are then the same at any design drop (the closure moves the level).
        const std::string searched = t.level == 1 ? "dh" : "dh2";
        double design = a.find == "dh" || a.find == "dh2" ? *std::max_element(drops.begin(), drops.end())
                                                          : drops[static_cast<std::size_t>(t.level - 1)];
        const auto cell_at = [&](double drop) { return engine::texture_geometry(with(k, searched, input::json_number(drop))); };
        for (int tries = 0;; ++tries) {
          const engine::TextureGeometry g = cell_at(design);
          bool other_tallest = false;
          double deepest_drop = 0.0;
          for (const model::Site& site : g.geometry.sites) {
            other_tallest = other_tallest || (site.level != t.level && site.drop == 0.0);
            deepest_drop = std::max(deepest_drop, site.drop);
          }
          if (other_tallest) break;
          if (tries == 3) throw std::runtime_error("design: no drop of level " + std::to_string(t.level) + " leaves the tallest tip to another level");
          design += deepest_drop;  // the drops' whole range: past it the level's tallest cap lies below another's
        }
        const input::Keywords made_with = with(k, searched, input::json_number(design));
        texture.emplace(
            [made_with](double l, const model::Shape& shape) {
              return engine::texture_geometry(with(with(made_with, "l", input::json_number(l)), "C", input::json_number(shape.C)));
            },
            t.level, design);
      }
    }
  }
  // (A lattice's levels are known up front, a file's once it is read: a share of a level it
  // lacks is refused before any curve is built where it can be.)
  const auto check_share_levels = [&] {
    for (const Requirement& r : requirements) {
      if (r.is_share() && out.texture && r.share_level > out.texture->levels - 1) {
        throw input::UsageError("--require '" + r.text + "': the texture has levels 0 to " +
                                std::to_string(out.texture->levels - 1));
      }
    }
  };
  if (!a.from_file()) check_share_levels();
  for (const Requirement& r : requirements) {
    if (r.is_share() && !a.off_curve()) {
      throw input::UsageError("--require '" + r.text + "': a share of caps is a requirement where heights scatter "
                              "(--supercell K --scatter DIST, a cell file or a height map, with --find pressure); on a "
                              "lattice each level's caps touch together");
    }
  }
  // A scattered supercell, a cell file or a height map under --find pressure: the load curve
  // of its every cap (surface's, to full contact, cached), read for each requirement's share
  // of caps.
  std::optional<engine::SurfaceRun> off_curve;
  if (a.off_curve() && by_pressure) {
    if (box.dh > 0.0 || box.l > 0.0 || box.C > 0.0) {
      throw input::UsageError("--tolerance: the design of a scattered supercell, a cell file or a height map takes "
                              "tolerances on the pressure and the temperature (each corner of dh, l or C would be a load "
                              "curve of its own)");
    }
    input::Keywords k = texture_keywords(out.search_lo);
    if (!out.temperatures.empty()) k = with(k, "temperature", input::json_number(out.temperatures.front()));
    // --grid auto sizes the grid for the spot at the least requirement's time (t = 0 only
    // where a requirement is at once).
    double least = kInf;
    for (const Requirement& r : requirements) least = std::min(least, r.time);
    k = with(k, "times", input::json_number(std::isfinite(least) ? least : 0.0));
    off_curve = engine::evaluate_surface(k, engine::MoreLoadPoints::any_load());  // read across the window
    DesignTexture& t = *out.texture;
    t.supercell = off_curve->supercell;
    t.scatter = a.scatter.value_or("");
    t.seed = a.scatter ? a.seed.value_or("1") : "";
    t.caps = static_cast<int>(off_curve->geometry.sites.size());
    t.nodes = off_curve->grid_nodes;
    t.coarser = off_curve->grid_coarser;
    t.grid_move = 0.0;
    for (const double move : off_curve->grid_t_star_change) t.grid_move = std::max(t.grid_move, move);
    if (a.from_file()) {
      t.file = off_curve->cell_file;
      t.lattice = off_curve->measured ? "height map" : "cell";
      t.levels = off_curve->curve.levels();
      // Each level's drop: the least of its caps' (they may differ within a level).
      t.drops.assign(static_cast<std::size_t>(std::max(t.levels - 1, 0)), kInf);
      for (const model::Site& site : off_curve->geometry.sites) {
        if (site.level > 0) t.drops[static_cast<std::size_t>(site.level - 1)] = std::min(t.drops[static_cast<std::size_t>(site.level - 1)], site.drop);
      }
    }
    if (t.level > t.levels - 1) {
      throw input::UsageError("--level " + std::to_string(t.level) + ": the texture has levels 0 to " + std::to_string(t.levels - 1));
    }
  }
  if (a.from_file()) check_share_levels();
  const double l0 = out.inputs.problem.l, C0 = out.inputs.problem.shape.C;
  // The drop of the level the requirements are on, where it is given (with --find l or pressure).
  const double dh0 = a.from_file() ? out.texture->drops[static_cast<std::size_t>(out.texture->level - 1)]
                    : out.texture && out.texture->level == 2 ? dh2
                                                             : out.inputs.problem.dh;
  if (searched && box.dh > dh0) {
    throw input::UsageError(std::string("--tolerance dh: larger than --") + (dh0 == dh2 ? "dh2" : "dh") + " itself");
  }
  // The quantity's own tolerance, which moves its edges inward.
  const OwnTolerance own = own_tolerance(box, a.find);
  const std::vector<double> temperatures = out.temperatures.empty() ? std::vector<double>{kNaN} : out.temperatures;
  out.lower = searched ? out.search_lo : 0.0;
  out.upper = searched ? out.search_hi : kInf;
  // A corner's point (its pressure, temperature and, with a tolerance on C, shape factor),
  // read through the point command's options and checks.
  const auto corner_point = [&](double pbar, double T, double C, const std::string& what) {
    input::Keywords k = with(base_keywords, "pbar", input::json_number(pbar));
    if (!std::isnan(T)) k = with(k, "temperature", input::json_number(T));
    if (box.C > 0.0) k = with(k, "C", input::json_number(C));
    return point_at(k, what);
  };
  for (const Requirement& r : requirements) {
    RequirementBound b;
    b.requirement = r;
    const bool touch = r.kind == Requirement::Kind::touch_by;
    // A share of another level's caps than the searched one's (in a drop or pitch window):
    // they touch the sooner the deeper the searched level lies, so its drop is the least at
    // which they have (TextureGap), a lower edge where the level's own is an upper one.
    const bool reversed = texture && texture->reversed(r);
    // dh: touching by t is dh <= the gap closed by t, an upper edge; l and the pressure: the
    // gap grows with each (more load on each tall punch), so touching is l (or p) >= the one
    // that closes dh.
    b.upper = searched ? !touch : touch != reversed;
    b.edge = b.upper ? kInf : -kInf;
    const double lo = out.search_lo, hi = out.search_hi;
    // A bound less the quantity's own tolerance: dh's shifts it; for a searched quantity,
    // touching is at or above the value found (a lower edge), no touch below it (the range's
    // end where the gap never reaches dh in it; none where it does at the start), then its
    // tolerance moves it inward.
    const auto edge_of = [&](const DesignBound& d) {
      if (!searched) return b.upper ? d.value - own.width : d.value + own.width;
      const double e = touch ? d.value : d.value <= lo ? -kInf : std::min(d.value, hi);
      if (!std::isfinite(e)) return e;
      if (b.upper) return own.relative ? e / (1.0 + own.width) : e - own.width;
      return own.relative ? e / (1.0 - own.width) : e + own.width;
    };
    const auto take = [&](DesignBound d) {
      d.edge = edge_of(d);
      // (The first corner binds where every one holds everywhere or nowhere: +-infinity.)
      if (b.bounds.empty() || (b.upper ? d.edge < b.edge : d.edge > b.edge)) {
        b.edge = d.edge;
        b.binding = d;
      }
      b.bounds.push_back(d);
    };
    const std::string what = "--require '" + r.text + "' (a corner of the box)";
    bool endless = false;  // the load grows without end by the requirement's time at some corner
    for (const double T : temperatures) {
      for (const double p : by_pressure ? std::vector<double>{lo} : sides(r.pbar, box.pressure, box.pressure_absolute)) {
        // Each corner's point read once (its creep law made once); only its pitch or pressure
        // varies below.
        std::vector<input::PointInputs> at_C;
        const std::vector<double> Cs = sides(C0, box.C, false);
        for (const double C : Cs) {
          at_C.push_back(corner_point(p, T, C, what));
          // (A law that creeps without end closes any gap at last: no "never" holds.)
          endless = endless || std::isinf(model::CreepWeightedLoad(*at_C.back().creep, 1.0, at_C.back().problem.loading).by(r.time));
        }
        for (const double l : by_l ? std::vector<double>{l0} : sides(l0, box.l, box.l_absolute)) {
          for (std::size_t c = 0; c < Cs.size(); ++c) {
            input::PointInputs& in = at_C[c];
            in.problem.l = l;
            // The gap the first level closes by the requirement's time at `x`, the searched
            // quantity's value (the corner's pitch where none is searched).
            const auto gap_at = [&](double x) {
              (by_pressure ? in.problem.pbar0 : in.problem.l) = x;
              const double g = texture ? (*texture)(in.problem, *in.creep, r.time, r)
                                       : model::dh_touching_at(in.problem, *in.creep, r.time);
              if (std::isnan(g)) {
                throw std::runtime_error("the gap closed at " + std::string(by_pressure ? "pbar = " : "l = ") +
                                         model::number_text(x, 17) + ", " + in.describe() + " is not a number");
              }
              return g;
            };
            if (!searched) {
              const double gap = gap_at(l);
              take(DesignBound{T, p, l, Cs[c], dh0, gap});
              continue;
            }
            if (off_curve) {
              // The load at which the requirement's share of caps turns, over the load the
              // unit pressure gives by its time: the pressure is that ratio (X is linear in
              // the pressure's amplitude).
              const double g = model::CreepWeightedLoad(*in.creep, 1.0, in.problem.loading).by(r.time);
              const double X = share_load(off_curve->curve, r.share_level == 0 ? out.texture->level : r.share_level, r);
              double value = std::isinf(g) ? 0.0 : g > 0.0 ? X / g : X == 0.0 ? 0.0 : kInf;
              value = value <= lo ? lo : value > hi ? kInf : value;
              take(DesignBound{T, p, lo, Cs[c], dh0, value});
              continue;
            }
            // --find l (pressure): at each dh of the box, the pitch (pressure) whose gap by the
            // requirement's time is that dh, by bisection in its log over the range (the gap
            // grows with it; checked). Reversed, the least drop at which another level's share
            // touches falls as the pitch grows: its negative is the gap, and -dh the drop.
            const auto closing = [&](double x) {
              const double g = gap_at(x);
              return reversed ? -g : g;
            };
            const double g_lo = closing(lo), g_hi = closing(hi);
            if (!(g_hi >= g_lo)) {
              out.notes.push_back("'" + r.text + "': the gap closed by its time shrinks from " + a.find + " = " +
                                  model::number_text(lo, 4) + " to " + model::number_text(hi, 4) +
                                  " here; the window assumes it grows with " + a.find);
            }
            for (const double drop : sides(dh0, box.dh, true)) {
              const double dh = reversed ? -drop : drop;
              double value;
              if (g_lo >= dh) {
                value = lo;  // touches by then over the whole range
              } else if (!(g_hi >= dh)) {
                value = kInf;  // not within the range
              } else if (texture) {
                // Each gap is a contact solve of the cell: Brent's method in the log, to
                // 1e-9 of the value (the grid's own error is some 1e-4), in 8-12 solves
                // where bisection to 1e-15 took 50.
                // (A share no drop from 0 brings down, -infinity, is below any dh.)
                const auto f = [&](double y) {
                  const double gap = closing(std::exp(y));
                  return gap == -kInf ? -1.0 - std::abs(dh) : gap - dh;
                };
                value = std::exp(model::brent(f, std::log(lo), std::log(hi), g_lo - dh, g_hi - dh, kTextureSearchTolerance).x);
              } else {
                double a_ = std::log(lo), b_ = std::log(hi);
                for (int it = 0; it < 60 && b_ - a_ > 1e-15 * std::abs(b_); ++it) {
                  const double mid = 0.5 * (a_ + b_);
                  (gap_at(std::exp(mid)) >= dh ? b_ : a_) = mid;
                }
                value = std::exp(b_);  // the least of the range whose gap reaches dh (to 1e-15)
              }
              take(DesignBound{T, p, by_l ? lo : l, Cs[c], drop, value});
            }
          }
        }
      }
    }
    if (b.upper) {
      out.upper = std::min(out.upper, b.edge);
    } else {
      out.lower = std::max(out.lower, b.edge);
    }
    // Where the engine's monotonicity does not hold, say so: t* falls with temperature and
    // pressure, so the binding point should lie at the range's cold (touch) or warm end and
    // at the low (touch) or high pressure.
    // (A tie is no exception: h_inf is the same at every temperature.)
    const auto tighter = [&](const DesignBound& x, const DesignBound& than) {
      const double close = 1e-12 * std::max(std::abs(than.value), 1e-300);
      return b.upper ? x.value < than.value - close : x.value > than.value + close;
    };
    const auto same_corner = [](const DesignBound& x, const DesignBound& y) {
      return x.pbar == y.pbar && x.l == y.l && x.C == y.C && x.dh == y.dh;
    };
    if (temperatures.size() > 1) {
      b.every_temperature = std::all_of(b.bounds.begin(), b.bounds.end(), [&](const DesignBound& x) {
        return !same_corner(x, b.binding) || (!tighter(b.binding, x) && !tighter(x, b.binding));
      });
      const double want = touch ? temperatures.front() : temperatures.back();
      bool beaten = false;
      for (const DesignBound& x : b.bounds) {
        if (x.temperature == want && same_corner(x, b.binding)) {
          beaten = tighter(b.binding, x);
        }
      }
      if (beaten) {
        out.notes.push_back("'" + r.text + "' binds at " + model::number_text(b.binding.temperature, 4) +
                            " degC, not at the range's " + (touch ? "cold" : "warm") +
                            " end: t* does not fall with temperature there; checked at " +
                            std::to_string(temperatures.size()) + " temperatures, the edge between them may be tighter");
      }
    }
    if (box.pressure > 0.0 && !by_pressure) {
      const std::vector<double> ps = sides(r.pbar, box.pressure, box.pressure_absolute);
      DesignBound expected = b.binding;  // the binding corner at the pressure monotonicity picks
      expected.pbar = touch ? ps.front() : ps.back();
      bool beaten = false;
      for (const DesignBound& x : b.bounds) {
        if (x.temperature == expected.temperature && same_corner(x, expected)) beaten = tighter(b.binding, x);
      }
      if (beaten) {
        out.notes.push_back("'" + r.text + "' binds at the " + (touch ? "higher" : "lower") +
                            " pressure of its tolerance: t* does not fall with pressure there");
      }
    }
    // Where the requirement's time falls as the creep settles, the load hardly grows by then:
    // a level touching there does so on a knife edge (model::knife_edge_note's measure, x/t*
    // d t*/dx along the pressure: -X/(t dX/dt), X = pbar g(t)). The edge is still where the
    // level touches by that time; the time the window promises hangs on a small change.
    if (!by_pressure && !r.is_share() && r.time > 0.0 && std::isfinite(r.time) && std::isfinite(b.edge)) {
      const input::PointInputs in = corner_point(b.binding.pbar, b.binding.temperature, b.binding.C, what);
      const model::CreepWeightedLoad load(*in.creep, 1.0, in.problem.loading);
      const double elasticity = -load.response(r.time) / (r.time * load.response_rate(r.time));
      if (std::abs(elasticity) > model::kKnifeEdgeElasticity) {
        out.notes.push_back("'" + r.text + "': by then the creep has nearly settled, so at the edge t* is on a knife edge: " +
                            "x/t* d t*/dx = " + model::number_text(elasticity, 3) +
                            " for the pressure (a 1% change of the pressure, or of the drop's touchdown load, moves t* " +
                            "by far more than 1%); the window is where the level touches by then, with no margin in time");
      }
    }
    if (!touch && endless) {
      out.notes.push_back("'" + r.text + "' cannot hold: this law creeps without end, so the second level touches "
                          "at last whatever " + (searched ? find_name : a.find));
    } else if (searched && std::isinf(b.edge)) {
      const auto value = [&](double x) {
        if (by_pressure) return pressure_text(x, out.inputs);
        const Unit L = length_unit(out.inputs);
        return model::number_text(x * L.per, 4) + " " + L.unit;
      };
      out.notes.push_back("'" + r.text + "' holds at no " + (by_l ? "pitch" : "pressure") + " from " +
                          value(out.search_lo) + " to " + value(out.search_hi) + " at every corner: widen " +
                          range_option + " or change dh");
    }
    // (A pitch window's search meets drops past reach at pitches outside its window: that
    // is the window's edge, not a note.)
    if (texture && !searched && texture->unreachable(r.text)) {
      out.notes.push_back("'" + r.text + "': at some corner " +
                          (!reversed ? "more caps than it allows touch"
                           : touch   ? "fewer of level " + std::to_string(r.share_level) + "'s caps than it asks touch even"
                                     : "more of level " + std::to_string(r.share_level) + "'s caps than it allows touch even") +
                          " with level " + std::to_string(out.texture->level) + (reversed && !touch ? "'s tallest cap at the top" : " at its deepest") +
                          (reversed ? "" : " (the other levels' caps alone reach the share)") +
                          ": no drop of the level meets it there");
    }
    if (texture && !searched && texture->reached(r.text)) {
      out.notes.push_back("'" + r.text + "': at some corner the caps it asks for touch with level " +
                          std::to_string(out.texture->level) + " at its deepest (the other levels' caps reach the " +
                          "share): its bound there is the deepest drop at which the level is still a cap of its own");
    }
    if (texture && texture->unsteady(r.text)) {
      const std::string level = std::to_string(out.texture->level);
      out.notes.push_back("'" + r.text + "': " +
                          (reversed ? "the count of level " + std::to_string(r.share_level) + "'s caps in contact fell somewhere "
                                      "as level " + level + " sank (it carries less, but the others' caps take the load "
                                      "unevenly)"
                                    : "the count of every cap in contact rose somewhere as level " + level +
                                          " sank (its own caps touch later, the others sooner)") +
                          ": the edge is where the count crosses the share, and drops beyond it may meet the requirement "
                          "too; `surface` at a few drops says where");
    }
    // Point's advisories at the edge: the binding corner with the searched quantity at its
    // edge, in the long term (X(inf) of that corner's pressure and law).
    const bool edge_inside = std::isfinite(b.edge) && (searched ? b.edge >= lo && b.edge <= hi : b.edge > 0.0);
    if (edge_inside && !b.bounds.empty()) {
      const DesignBound& at = b.binding;
      input::PointInputs in = corner_point(by_pressure ? b.edge : at.pbar, at.temperature, at.C, what);
      in.problem.l = by_l ? b.edge : at.l;
      const double drop = searched ? at.dh : b.edge;  // the searched level's
      const double X_inf = model::CreepWeightedLoad(*in.creep, in.problem.pbar0, in.problem.loading).by(kInf);
      if (std::isfinite(X_inf)) {
        if (!out.texture) {
          in.problem.dh = drop;
          b.advice = model::advise(in.problem, model::summarize_point(in.problem, *in.creep), std::nullopt);
        } else {
          const model::SurfaceAdvisories advice =
              off_curve ? model::advise_surface(off_curve->geometry, off_curve->curve.at(X_inf))
                        : texture->advice(in.problem, X_inf, drop);
          b.advice = advice.all;
          b.advice_level = static_cast<int>(advice.widest());
        }
      }
    }
    out.bounds.push_back(std::move(b));
  }
  if (texture) {
    out.texture->every_drop = texture->every_drop();
    out.texture->solves = texture->solves();
    out.texture->small_spot = texture->small_spot();
    if (texture->every_drop()) {
      out.notes.push_back("at some corner the other levels' surfaces press level " + std::to_string(out.texture->level) +
                          "'s tips at any drop it can have: its bound there is the deepest drop at which it is still a cap "
                          "of its own, below which the taller caps hide it");
    }
  }
  return out;
}

/// The grid a texture's design starts from, the finest --grid auto takes, and the
/// accuracy it holds every edge to (its relative move from the grid of half the nodes).
constexpr int kAutoGridStart = 64;
constexpr int kAutoGridMax = 256;
constexpr double kAutoGridAccuracy = 1e-3;

/// The largest relative move of a requirement's edge between two passes (0 where both are
/// the same infinity).
double edge_move(const DesignResult& coarse, const DesignResult& fine) {
  double move = 0.0;
  for (std::size_t k = 0; k < fine.bounds.size() && k < coarse.bounds.size(); ++k) {
    const double a = coarse.bounds[k].edge, b = fine.bounds[k].edge;
    if (a == b) continue;
    move = std::max(move, std::isfinite(a) && std::isfinite(b) ? std::abs(b - a) / std::max(std::abs(b), 1e-300) : kInf);
  }
  return move;
}

/// The design: the paper's lattice by the model; a texture on --grid N, or (--grid auto)
/// on grids of doubling nodes from kAutoGridStart until no edge moves by more than
/// kAutoGridAccuracy of itself, up to kAutoGridMax (a note says where it still moves); on
/// kAutoGridStart alone where the small-spot limit closed every edge (no grid read).
DesignResult design(const DesignArgs& a) {
  if (!a.texture() || a.by_curve()) return design_pass(a, 0);  // (a curve holds its own grid)
  if (const int nodes = engine::read_grid(a.grid.value_or("auto")); nodes != 0) return design_pass(a, nodes);
  DesignResult coarse = design_pass(a, kAutoGridStart);
  // Every closure in the small-spot limit, none by a contact solve: the edges read no grid.
  if (coarse.texture->solves == 0 && coarse.texture->small_spot > 0) return coarse;
  for (int nodes = 2 * kAutoGridStart;; nodes *= 2) {
    DesignResult fine = design_pass(a, nodes);
    fine.texture->coarser = coarse.texture->nodes;
    fine.texture->grid_move = edge_move(coarse, fine);
    fine.texture->solves += coarse.texture->solves;
    fine.texture->small_spot += coarse.texture->small_spot;
    if (fine.texture->grid_move <= kAutoGridAccuracy) return fine;
    if (2 * nodes > kAutoGridMax) {
      fine.notes.push_back("--grid auto: an edge still moves by " + model::number_text(fine.texture->grid_move, 2) +
                           " of itself from " + std::to_string(coarse.texture->nodes) + " to " + std::to_string(nodes) +
                           " nodes a pitch, more than the stated " + model::number_text(kAutoGridAccuracy, 2) +
                           "; give a finer --grid (up to " + std::to_string(engine::kMaxGridNodes) + ")");
      return fine;
    }
    coarse = std::move(fine);
  }
}

}  // namespace

DesignResult design(const input::Keywords& keywords) { return design(split_keywords(keywords)); }

}  // namespace punchsweep::engine
