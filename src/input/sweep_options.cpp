#include "input/sweep_options.hpp"

#include <boost/program_options.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "input/command_options.hpp"
#include "input/ini_lines.hpp"
#include "input/text_file.hpp"
#include "input/usage_error.hpp"
#include "input/value_parsing.hpp"
#include "input/scaled_value.hpp"
#include "io/crc32.hpp"
#include "model/problem/localization.hpp"
#include "model/laws/creep_laws.hpp"
#include "model/laws/material.hpp"
#include "model/numerics/number_text.hpp"
#include "model/point/parameters.hpp"
#include "model/point/point_axes.hpp"
#include "reference/reference_point.hpp"
#include "run/text_lines.hpp"
#include "input/axis_parser.hpp"

namespace po = boost::program_options;

namespace punchsweep::input {
namespace {

constexpr const char* kSeeHelp = " (see punchsweep sweep --help)";
constexpr const char* kBoolRange = "true, false, 1, 0, yes or no";
constexpr std::array<const char*, 6> kSections{"grid", "model", "time", "output", "run", "reference"};

// The config keys that are not grid axes; the order is that of the help text and of
// resolved_text, after the [grid] keys.
enum class Fixed {
  none,  // a [grid] key: a model parameter's axis
  grid_pressure, model_R, model_C, model_creep_law, model_material, model_load_table, model_localization, time_times, output_file, output_quantities, output_tolerance,
  run_chunk, run_quiet, run_resume, run_overwrite,
  reference_method, reference_grid, reference_sample, reference_seed
};

enum class Source { default_value, file, command_line };

struct Setting {
  std::string text;
  Source source = Source::default_value;
};

// What a key's reader sees beside its text: where the text came from, the physical scales
// (model.R, the material) for a value with a unit, and the axis a [grid] key fills.
struct KeyContext {
  const Setting& setting;
  const input::PhysicalScales& scales;
  map::Axis& axis;
};

// One config key, declared once: its help, how it is read into the config, how its final
// value is written back (resolved_text) and what it adds to the map's identity.
struct KeySpec {
  std::string section;
  std::string name;
  std::string value_name;
  std::string default_text;
  std::string meaning;  // with the unit
  std::string range;    // as printed after "valid range: "
  Fixed fixed = Fixed::none;
  const model::Parameter* parameter = nullptr;  // the axis's, or model.C's
  /// Reads the key's text into the config: empty, or why the text is refused.
  std::function<std::string(const std::string& text, const KeyContext& context, sweep::SweepConfig& config)> apply;
  /// The final value resolved_text writes (empty function: the text as given).
  std::function<std::string(const sweep::SweepConfig& config)> canonical = {};
  /// The values of its identity lines, "KEY = VALUE" each (empty function: none).
  std::function<std::vector<std::string>(const sweep::SweepConfig& config)> identity = {};
};

std::string listed(const std::vector<double>& values) {
  constexpr std::size_t kShown = 5;
  if (values.size() <= kShown) return input::format_axis_values(values);
  return input::format_axis_values({values.begin(), values.begin() + kShown}) + ", ... (" +
         std::to_string(values.size()) + " in all)";
}

// Empty, or why `text` is not an axis whose values all pass `in_range`. With a `scale`, a
// value may carry a physical unit (input::read_scaled_axis); with `required` it must.
template <class InRange>
std::string check_axis(const std::string& text, bool integers, InRange in_range, map::Axis& axis,
                       const std::optional<input::Scale>& scale = std::nullopt, bool required = false) {
  try {
    axis = scale ? input::read_scaled_axis(text, integers, *scale, required) : input::parse_axis(text, integers);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  std::vector<double> outside;
  for (const double v : axis.values) {
    if (!in_range(v)) outside.push_back(v);
  }
  if (outside.empty()) return {};
  return (outside.size() == 1 ? "value " : "values ") + listed(outside) +
         (outside.size() == 1 ? " is" : " are") + " outside its range";
}

std::string check_bool(const std::string& text, bool& value) {
  if (text == "true" || text == "1" || text == "yes") {
    value = true;
  } else if (text == "false" || text == "0" || text == "no") {
    value = false;
  } else {
    return "'" + text + "' is not a boolean";
  }
  return {};
}

std::string check_chunk(const std::string& text, std::size_t& chunk) {
  if (text == "auto") {
    chunk = sweep::kAutoChunk;  // resolved at the start of the run (sweep::auto_chunk)
    return {};
  }
  int value = 0;
  try {
    value = parse_integer(text, "run.chunk");
  } catch (const UsageError&) {
    const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
    return digits ? "value " + text + " is too large (at most " + std::to_string(std::numeric_limits<int>::max()) + ")"
                  : "'" + text + "' is not an integer";
  }
  if (value < 1) return "value " + text + " is outside its range";
  chunk = static_cast<std::size_t>(value);
  return {};
}

// A whole non-negative decimal integer up to `max`; empty, or why `text` is not one.
std::string check_whole(const std::string& text, std::uint64_t max, std::uint64_t& value) {
  const char* end = text.data() + text.size();
  const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
  if (!digits) return "'" + text + "' is not a whole number";
  std::uint64_t parsed = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), end, parsed);
  if (ec != std::errc() || ptr != end || parsed > max) {
    return "value " + text + " is too large (at most " + std::to_string(max) + ")";
  }
  value = parsed;
  return {};
}

std::string check_bem_grid(const std::string& text, int& grid) {
  std::uint64_t value = 0;
  if (std::string problem = check_whole(text, std::numeric_limits<int>::max(), value); !problem.empty()) {
    return problem;
  }
  if (!sweep::is_bem_grid(static_cast<double>(value))) return "value " + text + " is outside its range";
  grid = static_cast<int>(value);
  return {};
}

std::string check_sample(const std::string& text, sweep::ReferenceConfig& reference) {
  using Rule = sweep::ReferenceConfig::SampleRule;
  std::optional<std::uint64_t>& sample = reference.sample;
  reference.rule = text == "invalid" ? Rule::invalid : text == "boundary" ? Rule::boundary : Rule::count;
  if (text == "all" || reference.rule != Rule::count) {
    sample.reset();
    return {};
  }
  std::uint64_t value = 0;
  if (std::string problem = check_whole(text, std::numeric_limits<std::uint64_t>::max(), value);
      !problem.empty()) {
    return problem;
  }
  if (value < 1) return "value " + text + " is outside its range";
  sample = value;  // not above the grid's point count: checked once the grid is known
  return {};
}

// The canonical text of a [reference] key, as resolved_text and identity write it.
std::string reference_value(Fixed key, const sweep::ReferenceConfig& reference) {
  switch (key) {
    case Fixed::reference_method:
      return reference.on() ? "bem" : "none";
    case Fixed::reference_grid:
      return std::to_string(reference.grid);
    case Fixed::reference_sample:
      if (reference.rule == sweep::ReferenceConfig::SampleRule::invalid) return "invalid";
      if (reference.rule == sweep::ReferenceConfig::SampleRule::boundary) return "boundary";
      return reference.sample ? std::to_string(*reference.sample) : "all";
    default:
      return std::to_string(reference.seed);
  }
}

std::string bool_text(bool value) { return value ? "true" : "false"; }

// The material files of model.material (a comma-separated list) read into `config`.
std::string apply_materials(const std::string& text, const KeyContext& context, sweep::SweepConfig& config) {
  config.material_path = text;
  config.materials.clear();
  config.material_labels.clear();
  try {
    std::string item;
    std::istringstream list(text);
    while (std::getline(list, item, ',')) {
      item = run::trim(item);
      if (item.empty()) continue;
      // A path in a config file is taken from the file's folder, as a user reads it.
      std::filesystem::path file(item);
      if (context.setting.source == Source::file && file.is_relative()) {
        file = std::filesystem::path(config.config_path).parent_path() / file;
      }
      config.materials.push_back(read_material_file(file.string(), ""));
      config.input_files.push_back(file.string());
      std::string label = std::filesystem::path(item).stem().string();
      if (std::find(config.material_labels.begin(), config.material_labels.end(), label) !=
          config.material_labels.end()) {
        throw UsageError("two material files are named " + label + "; valid: files of different names");
      }
      config.material_labels.push_back(label);
    }
    if (config.materials.size() == 1) {
      config.material = config.materials.front();
      config.material_spec = std::make_shared<const model::CreepLawSpec>(config.material->spec());
    } else if (config.materials.size() > 1) {
      config.material_spec = std::make_shared<const model::CreepLawSpec>(model::material_choice(config.materials));
    }
  } catch (const UsageError& e) {
    return e.what();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

// Every key, one row each: the [grid] axes of every creep law (the default law's axes first,
// in their order: model::sweep_axes), then the fixed keys in the order of the help text,
// resolved_text and the map's identity. A new key is a row here and its field in
// sweep::SweepConfig.
std::vector<KeySpec> make_keys() {
  using Config = sweep::SweepConfig;
  std::vector<KeySpec> keys;
  const auto add_axis = [&](const model::Parameter* p) {
    for (const KeySpec& k : keys) {
      if (k.parameter == p) return;
    }
    keys.push_back({"grid", std::string(p->name), "AXIS", std::string(p->sweep_default), std::string(p->meaning),
                    std::string(p->range), Fixed::none, p,
                    [p](const std::string& text, const KeyContext& c, Config&) {
                      std::string problem = check_axis(
                          text, p->integer, [p](double v) { return p->in_range(v); }, c.axis,
                          input::scale_of(p->scale, c.scales));
                      c.axis.name = std::string(p->name);
                      return problem;
                    }});
  };
  for (const model::CreepLawSpec& law : model::creep_laws()) {
    for (const model::Parameter* p : model::sweep_axes(law.parameters)) add_axis(p);
  }
  add_axis(&model::temperature_parameter());
  add_axis(&model::ramp_time_parameter());
  keys.push_back({"grid", "pressure", "AXIS", "",
                  "the nominal pressure in a pressure unit (1kPa, 2kPa or linspace(1kPa, 5kPa, 9)), divided by the "
                  "material's E0* into the pbar axis; instead of grid.pbar",
                  "empty, or pressures > 0 each with its unit (Pa, kPa, MPa or GPa); needs model.material",
                  Fixed::grid_pressure, nullptr, [](const std::string& text, const KeyContext& c, Config&) {
                    if (text.empty()) return std::string();
                    const model::Parameter& pbar = *model::find_parameter(model::kPressure);
                    std::string problem = check_axis(
                        text, false, [](double v) { return v > 0.0; }, c.axis, input::scale_of(pbar.scale, c.scales),
                        true);
                    c.axis.name = std::string(pbar.name);
                    return problem;
                  }});
  keys.push_back({"model", "R", "LENGTH", "",
                  "the punch's radius of curvature R with its unit (50um; for a spherical cap, s = 2 and C = 0.5): "
                  "grid.l and grid.dh may then be given in a length unit (150um), and the map adds them in R's unit",
                  "empty (lengths in R), or a length > 0 with its unit (m, mm, um or nm)", Fixed::model_R, nullptr,
                  [](const std::string& text, const KeyContext&, Config& config) {
                    config.R.reset();
                    if (text.empty()) return std::string();
                    try {
                      config.R = input::read_length_scale(text);
                    } catch (const std::invalid_argument& e) {
                      const std::string what = e.what();
                      return what.substr(0, what.find("; valid"));
                    }
                    return std::string();
                  },
                  [](const Config& config) {
                    return config.R ? input::format_axis_value(config.R->number) + std::string(config.R->unit->name) : "";
                  },
                  // R names the physical unit of the map's lengths; maps without it keep their identity.
                  [](const Config& config) {
                    if (!config.R) return std::vector<std::string>{};
                    return std::vector<std::string>{"model.R = " + input::format_axis_value(config.R->number) + " " +
                                                    std::string(config.R->unit->name)};
                  }});
  const model::Parameter& C = *model::find_parameter(model::kShapeConstant);
  keys.push_back({"model", "C", "C", std::string(C.point_default), std::string(C.meaning), std::string(C.range),
                  Fixed::model_C, &C,
                  [&C](const std::string& text, const KeyContext&, Config& config) {
                    try {
                      config.C = parse_real(text, "model.C");
                    } catch (const UsageError&) {
                      return "'" + text + "' is not a finite number";
                    }
                    if (!C.admits(config.C)) return "value " + input::format_axis_value(config.C) + " is outside its range";
                    return std::string();
                  },
                  [](const Config& config) { return input::format_axis_value(config.C); },
                  [](const Config& config) {
                    return std::vector<std::string>{"model.C = " + input::format_axis_value(config.C)};
                  }});
  keys.push_back({"model", "creep_law", "NAME", std::string(model::creep_laws().front().name),
                  "creep law of the half-space (its parameters are [grid] axes)", model::creep_law_names(),
                  Fixed::model_creep_law, nullptr,
                  [](const std::string& text, const KeyContext&, Config& config) {
                    const model::CreepLawSpec* law = model::find_creep_law(text);
                    if (law == nullptr) return "'" + text + "' is not a known creep law";
                    config.creep_law = law;
                    return std::string();
                  },
                  [](const Config& config) {
                    return std::string(config.material_spec ? model::creep_laws().front().name : config.creep_law->name);
                  },
                  [](const Config& config) {
                    return std::vector<std::string>{"model.creep_law = " + std::string(config.creep_law->name)};
                  }});
  keys.push_back({"model", "material", "FILES", "",
                  "material file (materials/NAME.ini, see docs/materials.md); replaces creep_law: the axes are then l, dh, "
                  "[temperature when the file has a [shift]], pbar, s, and times are in the file's time_unit. A "
                  "list (a.ini, b.ini) adds a categorical axis material after dh, labelled by the files' names",
                  "empty, or readable material files (several: one time_unit, all or none with a [shift])",
                  Fixed::model_material, nullptr, apply_materials, {},
                  [](const Config& config) {
                    std::vector<std::string> lines;
                    for (const auto& material : config.materials) {
                      // The material's content, not its path: the same file moved is the same map.
                      std::uint32_t crc = io::crc32(reinterpret_cast<const unsigned char*>(material->text().data()),
                                                    material->text().size());
                      char hex[9];
                      std::snprintf(hex, sizeof hex, "%08x", crc);
                      lines.push_back("model.material = " + material->name() + " (file crc32 " + hex + ")");
                    }
                    return lines;
                  }});
  keys.push_back({"model", "load_table", "T:PHI,...", "",
                  "the nominal pressure pbar phi(t), phi piecewise linear through the points t:phi (time in T_eps "
                  "or the material's unit), from 0:phi0 to t_n:1; empty: a step (a ramp: grid.ramp_time)",
                  "empty, or points from 0:phi0 to t_n:1 with phi non-decreasing in [0, 1]", Fixed::model_load_table,
                  nullptr,
                  [](const std::string& text, const KeyContext&, Config& config) {
                    config.load_text = text;
                    config.loading = model::LoadShape{};
                    if (text.empty()) return std::string();
                    try {
                      config.loading = parse_load_table(text, "model.load_table");
                    } catch (const UsageError& e) {
                      const std::string what = e.what();
                      return what.substr(what.find(": ") + 2);
                    }
                    return std::string();
                  },
                  {},
                  [](const Config& config) {
                    if (config.load_text.empty()) return std::vector<std::string>{};
                    return std::vector<std::string>{"model.load_table = " + config.load_text};
                  }});
  keys.push_back({"model", "localization", "L", std::string(model::kDefaultLocalization),
                  "the model (docs/model.md, sections 11, 14)", model::localization_spellings(),
                  Fixed::model_localization, nullptr,
                  [](const std::string& text, const KeyContext&, Config& config) {
                    try {
                      config.localization = model::parse_localization(text);
                    } catch (const std::invalid_argument& e) {
                      const std::string what = e.what();
                      return what.substr(0, what.find(';'));
                    }
                    return std::string();
                  },
                  [](const Config& config) { return config.localization.spelling(); },
                  // The paper's model leaves no line, so that maps made before the choice existed resume.
                  [](const Config& config) {
                    if (config.localization.is_paper()) return std::vector<std::string>{};
                    return std::vector<std::string>{"model.localization = " + config.localization.spelling()};
                  }});
  keys.push_back({"time", "times", "AXIS", "0, 0.5, 1, 2, 5",
                  "snapshot times of the stored time series, in T_eps (or the material's time_unit)", kTimesRange,
                  Fixed::time_times, nullptr,
                  [](const std::string& text, const KeyContext& c, Config& config) {
                    map::Axis times;
                    std::string problem = check_axis(
                        text, false, [](double t) { return t >= 0.0; }, times, input::scale_of("T_eps", c.scales));
                    config.times = times.values;
                    return problem;
                  },
                  {},
                  [](const Config& config) {
                    return std::vector<std::string>{"time.times = " + input::format_axis_values(config.times)};
                  }});
  keys.push_back({"output", "file", "FILE", "regime_map.h5", "the HDF5 regime map to write",
                  "a non-empty file name without '#' or line breaks", Fixed::output_file, nullptr,
                  [](const std::string& text, const KeyContext&, Config& config) {
                    config.output = text;
                    return text.empty() ? std::string("the file name is empty") : std::string();
                  }});
  keys.push_back({"output", "quantities", "WHAT", "full",
                  "what the map stores: regime (regime, t*, validity, long-term state) or full (also the time "
                  "series at time.times)",
                  "regime or full", Fixed::output_quantities, nullptr,
                  [](const std::string& text, const KeyContext&, Config& config) {
                    if (text != "regime" && text != "full") return "'" + text + "' is not one of regime, full";
                    config.quantities = text == "full" ? map::Quantities::full : map::Quantities::regime;
                    return std::string();
                  },
                  {},
                  [](const Config& config) {
                    return std::vector<std::string>{std::string("output.quantities = ") +
                                                    (config.quantities == map::Quantities::full ? "full" : "regime")};
                  }});
  keys.push_back({"output", "tolerance", "LIST", "",
                  "a box of tolerances about every point, e.g. 'dh=0.5um, pressure=10%': the map adds t* at the "
                  "box's ends and the regimes there (t_star_low, t_star_high, regime_low, regime_high; where the two "
                  "regimes agree, the regime holds over the box); empty: none",
                  "empty, or NAME=VALUE, ... (at most 6) with NAME an axis of the grid (l, dh, pbar or pressure, the "
                  "law's T or temperature) or C, VALUE >= 0: a percentage, a number in the axis's scale, or one with "
                  "a unit (0.5um, 2kPa, 1K)",
                  Fixed::output_tolerance, nullptr,
                  [](const std::string& text, const KeyContext& c, Config& config) {
                    config.tolerance.clear();
                    config.tolerance_text = text;
                    if (text.empty()) return std::string();
                    try {
                      config.tolerance = input::parse_tolerances(
                          text, "output.tolerance", [](std::string_view name) { return model::find_parameter(name); },
                          c.scales, "l, dh, pbar or pressure, C, T, temperature");
                    } catch (const UsageError& e) {
                      return std::string(e.what());
                    }
                    if (config.tolerance.size() > model::kMaxTolerances) {
                      return "at most " + std::to_string(model::kMaxTolerances) + " tolerances (" +
                             std::to_string(1u << model::kMaxTolerances) + " corners)";
                    }
                    return std::string();
                  },
                  {},
                  // Maps without a box keep their identity.
                  [](const Config& config) {
                    if (config.tolerance_text.empty()) return std::vector<std::string>{};
                    return std::vector<std::string>{"output.tolerance = " + config.tolerance_text};
                  }});
  const auto chunk_text = [](const Config& config) {
    return config.chunk == sweep::kAutoChunk ? std::string("auto") : std::to_string(config.chunk);
  };
  keys.push_back({"run", "chunk", "N", "4096",
                  "target number of values per tile and HDF5 chunk of the largest variable: grid points, or "
                  "grid points x snapshot times for a map with time series (then chunk / times points, at "
                  "least 1)",
                  "an integer >= 1, or auto (from the work and the rank count: about 16 tiles a rank, "
                  "256 to 4096 values; a resumed run keeps the size its map was started with)",
                  Fixed::run_chunk, nullptr,
                  [](const std::string& text, const KeyContext&, Config& config) { return check_chunk(text, config.chunk); },
                  chunk_text,
                  [chunk_text](const Config& config) { return std::vector<std::string>{"run.chunk = " + chunk_text(config)}; }});
  keys.push_back({"run", "quiet", "BOOL", "false", "no progress output", kBoolRange, Fixed::run_quiet, nullptr,
                  [](const std::string& text, const KeyContext&, Config& config) { return check_bool(text, config.quiet); },
                  [](const Config& config) { return bool_text(config.quiet); }});
  keys.push_back({"run", "resume", "BOOL", "false",
                  "continue an interrupted sweep into the existing partial map; refused if its grid, model or "
                  "reference differ",
                  kBoolRange, Fixed::run_resume, nullptr,
                  [](const std::string& text, const KeyContext&, Config& config) { return check_bool(text, config.resume); },
                  [](const Config& config) { return bool_text(config.resume); }});
  keys.push_back({"run", "overwrite", "BOOL", "false", "replace an existing map at output.file", kBoolRange,
                  Fixed::run_overwrite, nullptr,
                  [](const std::string& text, const KeyContext&, Config& config) {
                    return check_bool(text, config.overwrite);
                  },
                  [](const Config& config) { return bool_text(config.overwrite); }});
  // The [reference] keys: canonical values and identity lines by reference_value.
  const auto reference_row = [&](const char* name, const char* value_name, const char* default_text,
                                 const char* meaning, const char* range, Fixed fixed,
                                 std::function<std::string(const std::string&, Config&)> apply) {
    keys.push_back({"reference", name, value_name, default_text, meaning, range, fixed, nullptr,
                    [apply](const std::string& text, const KeyContext&, Config& config) { return apply(text, config); },
                    [fixed](const Config& config) { return reference_value(fixed, config.reference); },
                    [fixed, name](const Config& config) {
                      std::vector<std::string> lines{"reference." + std::string(name) + " = " +
                                                     reference_value(fixed, config.reference)};
                      // Maps with BEM points name the solver: one made by another does not resume.
                      if (fixed == Fixed::reference_seed && config.reference.on()) {
                        lines.push_back("reference.solver = " + std::string(reference::kSolverRevision));
                      }
                      return lines;
                    }});
  };
  reference_row("method", "METHOD", "none",
                "reference solver evaluated beside the model: none, or bem (the periodic boundary-element solver "
                "of `punchsweep reference`; adds the bem_* variables)",
                "none or bem", Fixed::reference_method, [](const std::string& text, Config& config) {
                  if (text != "none" && text != "bem") return "'" + text + "' is not one of none, bem";
                  config.reference.method = text == "bem" ? sweep::ReferenceMethod::bem : sweep::ReferenceMethod::none;
                  return std::string();
                });
  reference_row("grid", "N", "128",
                "BEM nodes per side N of the l x l cell (spacing l/N; the cost of a point grows faster than N^2, "
                "--dry-run measures it)",
                "an even integer in [16, 2048]", Fixed::reference_grid,
                [](const std::string& text, Config& config) { return check_bem_grid(text, config.reference.grid); });
  reference_row("sample", "K", "all",
                "the grid points that get the reference: all; K distinct points drawn uniformly at random (a "
                "pure function of the grid's shape, K and reference.seed); invalid: the points the model flags "
                "invalid (where it has no answer); boundary: the points whose model regime differs from a grid "
                "neighbour's (one step along any axis: where a regime is least sure); the others read "
                "not_computed",
                "all, invalid, boundary, or an integer in [1, the grid's point count]", Fixed::reference_sample,
                [](const std::string& text, Config& config) { return check_sample(text, config.reference); });
  reference_row("seed", "SEED", "1", "seed of the random sample of reference.sample = K",
                "an integer in [0, 9223372036854775807]", Fixed::reference_seed,
                // The map stores the seed as an int64 attribute.
                [](const std::string& text, Config& config) {
                  return check_whole(text, std::numeric_limits<std::int64_t>::max(), config.reference.seed);
                });
  return keys;
}

const std::vector<KeySpec>& keys() {
  static const std::vector<KeySpec> kKeys = make_keys();
  return kKeys;
}

std::size_t key_index(const model::Parameter* axis) {
  for (std::size_t k = 0; k < keys().size(); ++k) {
    if (keys()[k].parameter == axis) return k;
  }
  return keys().size();
}

std::size_t key_index(Fixed fixed) {
  for (std::size_t k = 0; k < keys().size(); ++k) {
    if (keys()[k].fixed == fixed) return k;
  }
  return keys().size();
}

// Command-line shortcuts for the keys one sets most often.
struct Shortcut {
  const char* option;
  Fixed key;
  bool takes_value;  // false: a flag that sets the key to true
};

constexpr std::array<Shortcut, 9> kShortcuts{{
    {"output", Fixed::output_file, true},
    {"quantities", Fixed::output_quantities, true},
    {"tolerance", Fixed::output_tolerance, true},
    {"chunk", Fixed::run_chunk, true},
    {"resume", Fixed::run_resume, false},
    {"overwrite", Fixed::run_overwrite, false},
    {"quiet", Fixed::run_quiet, false},
    {"reference", Fixed::reference_method, true},
    {"bem-grid", Fixed::reference_grid, true},
}};

std::string dotted(const KeySpec& key) { return key.section + "." + key.name; }
std::string dotted(Fixed fixed) { return dotted(keys()[key_index(fixed)]); }

using run::join;
using run::trim;

std::string section_keys(const std::string& section) {
  std::vector<std::string> names;
  for (const KeySpec& spec : keys()) {
    if (section == spec.section) names.emplace_back(spec.name);
  }
  return join(names, ", ");
}

bool is_section(const std::string& name) {
  for (const char* section : kSections) {
    if (name == section) return true;
  }
  return false;
}

const KeySpec* find_key(const std::string& key) {
  for (const KeySpec& spec : keys()) {
    if (key == dotted(spec)) return &spec;
  }
  return nullptr;
}

po::options_description key_options(const char* caption) {
  po::options_description opts(caption);
  for (const KeySpec& spec : keys()) {
    const bool stated = spec.parameter != nullptr && !spec.parameter->default_meaning.empty();
    const std::string description = std::string(spec.meaning) + "; " + spec.range + "; default " +
                                    (stated ? std::string(spec.parameter->default_meaning) : spec.default_text);
    opts.add_options()(dotted(spec).c_str(), po::value<std::string>()->value_name(spec.value_name),
                       description.c_str());
  }
  return opts;
}

po::options_description command_line_options() {
  po::options_description opts("Options");
  opts.add_options()
      ("help", "print this help and exit")
      ("config", po::value<std::string>()->value_name("FILE.ini"),
       "read settings from this INI file (format below); keys it leaves out keep their defaults")
      ("output", po::value<std::string>()->value_name("FILE.h5"),
       "same as --output.file: the HDF5 regime map to write; default regime_map.h5")
      ("resume",
       "same as --run.resume true: continue an interrupted sweep; refused if its grid, model or reference differ")
      ("overwrite", "same as --run.overwrite true: replace an existing map at the output file")
      ("dry-run", "resolve and check the configuration, report the grid and the work, compute nothing")
      ("quiet", "same as --run.quiet true: no progress output")
      ("quantities", po::value<std::string>()->value_name("WHAT"),
       "same as --output.quantities: regime or full; default full")
      ("tolerance", po::value<std::string>()->value_name("LIST"),
       "same as --output.tolerance: a box of tolerances about every point ('dh=0.5um, pressure=10%'); the map "
       "adds t_star_low, t_star_high, regime_low, regime_high; default none")
      ("chunk", po::value<std::string>()->value_name("N"),
       "same as --run.chunk: target values per tile and HDF5 chunk (points x times with time series); an "
       "integer >= 1; default 4096")
      ("reference", po::value<std::string>()->value_name("METHOD"),
       "same as --reference.method: bem evaluates the periodic BEM reference at every grid point (or at "
       "--reference.sample K random ones, or the invalid or boundary points of the model) into the bem_* "
       "variables; none or bem; default none")
      ("bem-grid", po::value<std::string>()->value_name("N"),
       "same as --reference.grid: BEM nodes per side of the l x l cell; an even integer in [16, 2048]; "
       "default 128");
  opts.add(key_options("Config keys, each also an option --SECTION.KEY VALUE (it overrides the config file)"));
  return opts;
}

// Line-numbered check of the file's structure, done before Boost parses it because Boost
// names neither the file nor the line; it follows Boost's rules ('#' starts a comment
// anywhere, whitespace around names and values is dropped).
std::vector<std::string> config_file_problems(const std::string& path, const std::string& text) {
  return scan_ini(path, text, is_section, "sections: " + join({kSections.begin(), kSections.end()}, ", "),
                  [](const std::string& section, const std::string& name) {
                    const std::string key = section + "." + name;
                    return find_key(key) == nullptr
                               ? "unknown key " + key + " (keys of [" + section + "]: " + section_keys(section) + ")"
                               : std::string();
                  })
      .problems;
}

// The values the file sets, by key.
std::map<std::string, std::string> read_config_file(const std::string& path) {
  if (path.empty()) throw UsageError("--config needs a file name" + std::string(kSeeHelp));
  const std::string text = read_text_file(path, "config file");

  const std::vector<std::string> problems = config_file_problems(path, text);
  if (!problems.empty()) throw UsageError(join(problems, "\n"));

  po::variables_map vm;
  try {
    std::istringstream stream(text);
    po::store(po::parse_config_file(stream, key_options(""), false), vm);
  } catch (const po::error& e) {
    throw UsageError("config file " + path + ": " + e.what());
  }
  std::map<std::string, std::string> values;
  for (const auto& [key, value] : vm) values[key] = value.as<std::string>();
  return values;
}

po::variables_map parse_command_line(const std::vector<std::string>& args, const po::options_description& opts) {
  po::variables_map cli;
  const po::positional_options_description no_positionals;
  try {
    // Long options only, so that "--grid.dh -0.5" reads -0.5 as a value; no guessing of
    // abbreviations, because the key names are the config file's vocabulary.
    const int style = (po::command_line_style::unix_style ^ po::command_line_style::allow_short) &
                      ~po::command_line_style::allow_guessing;
    po::store(po::command_line_parser(args).options(opts).style(style).positional(no_positionals).run(), cli);
  } catch (const po::unknown_option& e) {
    const std::string name = e.get_option_name();
    std::string hint = kSeeHelp;
    if (const std::size_t dot = name.find('.'); name.rfind("--", 0) == 0 && dot != std::string::npos &&
                                                is_section(name.substr(2, dot - 2))) {
      const std::string section = name.substr(2, dot - 2);
      hint = " (keys of [" + section + "]: " + section_keys(section) + ")";
    }
    throw UsageError("unknown option " + name + hint);
  } catch (const po::too_many_positional_options_error&) {
    throw UsageError(std::string("unexpected argument (every input is an --option)") + kSeeHelp);
  } catch (const po::error& e) {
    throw UsageError(e.what() + std::string(kSeeHelp));
  }
  return cli;
}

// Each key's text and where it came from: command line > config file > default.
std::vector<Setting> resolve_settings(const po::variables_map& cli, const std::string& config_path) {
  std::vector<std::string> conflicts;
  for (const Shortcut& shortcut : kShortcuts) {
    const std::string key = dotted(shortcut.key);
    if (cli.count(shortcut.option) && cli.count(key)) {
      conflicts.push_back(std::string("--") + shortcut.option + " and --" + key + " both set " + key +
                          "; give only one");
    }
  }
  if (!conflicts.empty()) throw UsageError(join(conflicts, "\n"));

  std::vector<Setting> settings(keys().size());
  for (std::size_t k = 0; k < keys().size(); ++k) settings[k] = {keys()[k].default_text, Source::default_value};
  if (cli.count("config")) {
    const std::map<std::string, std::string> file_values = read_config_file(config_path);
    for (std::size_t k = 0; k < keys().size(); ++k) {
      const auto it = file_values.find(dotted(keys()[k]));
      if (it != file_values.end()) settings[k] = {trim(it->second), Source::file};
    }
  }
  for (std::size_t k = 0; k < keys().size(); ++k) {
    const std::string key = dotted(keys()[k]);
    if (cli.count(key)) settings[k] = {trim(cli[key].as<std::string>()), Source::command_line};
  }
  for (const Shortcut& shortcut : kShortcuts) {
    if (!cli.count(shortcut.option)) continue;
    settings[key_index(shortcut.key)] = {shortcut.takes_value ? trim(cli[shortcut.option].as<std::string>()) : "true",
                              Source::command_line};
  }
  return settings;
}

// Whether key `spec` reads values whose unit depends on model.R or the material: read after them.
bool reads_scaled_values(const KeySpec& spec) {
  return spec.fixed == Fixed::none || spec.fixed == Fixed::grid_pressure || spec.fixed == Fixed::time_times ||
         spec.fixed == Fixed::output_tolerance;
}

// Fills `config` from the settings; returns one line per bad value, in the keys' order.
std::vector<std::string> apply_settings(const std::vector<Setting>& settings, sweep::SweepConfig& config) {
  std::vector<std::pair<std::size_t, std::string>> keyed;  // (key, problem)
  std::vector<map::Axis> axes(keys().size());  // by key; [grid] keys only
  // The scales first (model.R, model.material), then the values that may be given in units.
  std::vector<std::size_t> order;
  for (const bool scaled : {false, true}) {
    for (std::size_t k = 0; k < keys().size(); ++k) {
      if (reads_scaled_values(keys()[k]) == scaled) order.push_back(k);
    }
  }
  input::PhysicalScales scales;
  bool scales_known = false;
  for (const std::size_t k : order) {
    const KeySpec& spec = keys()[k];
    if (reads_scaled_values(spec) && !scales_known) {
      scales_known = true;
      // One material gives E0*; several share their time unit only.
      scales = input::scales_of(config.materials.size() == 1 ? config.materials.front().get() : nullptr, config.R);
      if (config.materials.size() > 1) scales.time = input::scales_of(config.materials.front().get()).time;
    }
    const std::string& text = settings[k].text;
    std::string problem;
    if (text.find_first_of("#\r\n") != std::string::npos) {
      // A config file could not hold it, so resolved_text would not read back.
      problem = "it contains '#' or a line break, which a config file cannot hold";
    } else {
      problem = spec.apply(text, KeyContext{settings[k], scales, axes[k]}, config);
    }
    if (!problem.empty()) {
      keyed.emplace_back(k, dotted(spec) + " = " + (text.empty() ? "''" : text) + ": " + problem +
                                "; valid range: " + spec.range);
    }
  }
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> problems;
  for (auto& [k, line] : keyed) problems.push_back(std::move(line));
  // grid.pressure is the pbar axis given in a pressure unit.
  const std::size_t pressure_key = key_index(Fixed::grid_pressure);
  const std::size_t pbar_key = key_index(model::find_parameter(model::kPressure));
  const bool by_pressure = !settings[pressure_key].text.empty();
  if (by_pressure && settings[pbar_key].source != Source::default_value) {
    problems.push_back("grid.pressure = " + settings[pressure_key].text + ": grid.pbar = " + settings[pbar_key].text +
                       " is given too; valid range: one of grid.pbar and grid.pressure");
  }
  if (by_pressure) axes[pbar_key] = axes[pressure_key];
  // A material replaces the creep law (and its parameters) by the file's.
  if (config.material_spec) {
    const std::size_t law_key = key_index(Fixed::model_creep_law);
    if (settings[law_key].source != Source::default_value) {
      problems.push_back(dotted(Fixed::model_creep_law) + " = " + settings[law_key].text +
                         ": model.material is given too; valid range: one of model.creep_law and model.material");
    }
    config.creep_law = config.material_spec.get();
  }
  // The grid: a point's coordinates under the creep law (model::PointAxes), in their order,
  // ramp_time last when it is set. A [grid] key set for a parameter the law does not have is
  // refused.
  config.grid.axes.clear();
  const std::size_t ramp_key = key_index(&model::ramp_time_parameter());
  config.ramp = settings[ramp_key].source != Source::default_value;
  const model::PointAxes wanted(config.creep_law->parameters, config.ramp);
  for (const model::PointAxis& coordinate : wanted) {
    const model::Parameter* p = coordinate.parameter;
    if (p->name == model::material_parameter().name) {
      // The categorical axis of the material files, labelled by their names.
      map::Axis axis;
      axis.name = std::string(p->name);
      axis.text = config.material_path;
      axis.labels = config.material_labels;
      for (std::size_t k = 0; k < axis.labels.size(); ++k) axis.values.push_back(static_cast<double>(k));
      config.grid.axes.push_back(axis);
      continue;
    }
    for (std::size_t k = 0; k < keys().size(); ++k) {
      const KeySpec& spec = keys()[k];
      if (spec.fixed != Fixed::none || spec.name != p->name) continue;
      map::Axis axis = axes[k];
      if (settings[k].source == Source::default_value && !p->sweep_default.empty() &&
          std::string(p->sweep_default) != spec.default_text) {
        // A parameter whose default depends on the material (temperature: the shift's T_ref).
        check_axis(std::string(p->sweep_default), p->integer, [](double) { return true; }, axis);
        axis.name = spec.name;
      }
      // The shape exponent is held to the localization's reach (the periodic model's tables
      // answer s up to Localization::kMaxPeriodicExponent).
      // (One line a key: an axis already outside the parameter's range says that alone.)
      const bool in_range = std::all_of(axis.values.begin(), axis.values.end(), [&](double v) { return p->admits(v); });
      if (p->name == model::kExponent && in_range) {
        for (const double v : axis.values) {
          if (const std::string e = config.localization.exponent_error(static_cast<int>(v)); !e.empty()) {
            problems.push_back(dotted(spec) + " = " + settings[k].text + ": " + e);
            break;
          }
        }
      }
      // A material's temperature is also held to its shift's range (WLF diverges below
      // T_ref - C2).
      if (p->name == model::temperature_parameter().name) {
        for (const auto& material : config.materials) {
          const auto bad = std::find_if(axis.values.begin(), axis.values.end(),
                                        [&](double v) { return !material->shift()->admits(v); });
          if (bad != axis.values.end()) {
            problems.push_back(dotted(spec) + " = " + settings[k].text + ": value " + input::format_axis_value(*bad) +
                               " is outside its range for " + material->name() + ": " + material->shift()->range());
            break;
          }
        }
      }
      config.grid.axes.push_back(axis);
    }
  }
  // A tolerance is on an axis of this map's grid, or on C, and its box stays within the
  // parameter's range about every value of the grid.
  for (const model::StatedTolerance& t : config.tolerance) {
    const std::size_t k = key_index(Fixed::output_tolerance);
    const std::string head = dotted(keys()[k]) + " = " + settings[k].text + ": ";
    const std::size_t a = config.grid.find(t.parameter->name);
    if (t.parameter->name != "C" && a == config.grid.rank()) {
      problems.push_back(head + std::string(t.parameter->name) + " is no axis of this map; valid range: " +
                         keys()[k].range);
      continue;
    }
    // The first grid value about which the box leaves the range, if any.
    const auto outside = [&]() -> std::string {
      for (const double v : a < config.grid.rank() ? config.grid.axes[a].values : std::vector<double>{config.C}) {
        const model::Tolerance box = t.at(v);
        for (const double corner : {v - box.minus, v + box.plus}) {
          if (!t.parameter->admits(corner)) {
            return "about " + std::string(t.parameter->name) + " = " + input::format_axis_value(v) +
                   " the box reaches " + input::format_axis_value(corner) + ", outside its range: " +
                   std::string(t.parameter->range);
          }
        }
      }
      return {};
    };
    if (const std::string why = outside(); !why.empty()) problems.push_back(head + why);
  }
  for (std::size_t k = 0; k < keys().size(); ++k) {
    const KeySpec& spec = keys()[k];
    if (spec.fixed != Fixed::none || settings[k].source == Source::default_value) continue;
    if (wanted.find(spec.name) == wanted.size()) {
      problems.push_back(dotted(spec) + " = " + settings[k].text + ": the creep law " +
                         std::string(config.creep_law->name) + " has no parameter " + spec.name +
                         "; valid range: the axes of that law's grid");
    }
  }
  return problems;
}

// A material map's snapshot times where time.times is left at its default: 0 and up to 8
// log-spaced times (one a decade where fewer) over the span in which the material creeps,
// from 1% to 99% of the way from J(0) to J(inf) at the grid's warmest and coldest
// temperature (a power law, which creeps without end: 1e-3 to 1e3 of its time scale), held
// within 1 ms to a year, each to 2 significant digits. The default 0, 0.5, 1, 2, 5 is in T_eps, which a material's
// seconds are not: a silicone whose creep ends in milliseconds, or a rubber creeping for
// hours, got snapshots that missed all of it.
std::vector<double> material_times(const sweep::SweepConfig& config) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  const std::size_t t_axis = config.grid.find(model::temperature_parameter().name);
  for (const auto& material : config.materials) {
    std::vector<std::vector<double>> at{{}};
    if (material->shift() && t_axis < config.grid.rank()) {
      const std::vector<double>& T = config.grid.axes[t_axis].values;
      at = {{*std::min_element(T.begin(), T.end())}, {*std::max_element(T.begin(), T.end())}};
    } else if (material->shift()) {
      at = {{material->shift()->T_ref}};
    }
    for (const std::vector<double>& values : at) {
      const std::unique_ptr<model::CreepLaw> law = material->make(values);
      const double J0 = law->creep_initial(), Jinf = law->creep_final();
      if (std::isfinite(Jinf)) {
        lo = std::min(lo, law->time_at_creep(J0 + 0.01 * (Jinf - J0)));
        hi = std::max(hi, law->time_at_creep(J0 + 0.99 * (Jinf - J0)));
      } else {
        lo = std::min(lo, 1e-3 * law->creep_time_scale());
        hi = std::max(hi, 1e3 * law->creep_time_scale());
      }
    }
  }
  // Within the times a user waits: 1 ms to a year (a PLA creeps on for 1e16 s at 25 C).
  if (const model::Unit* unit = model::find_unit(model::Dimension::time, config.time_unit())) {
    lo = std::max(lo, 1e-3 / unit->si);
    hi = std::min(hi, 3.15576e7 / unit->si);
  }
  if (!(lo > 0.0 && hi > lo && std::isfinite(hi))) return config.times;
  const double decades = std::log10(hi / lo);
  const int n = std::clamp(static_cast<int>(std::ceil(decades)) + 1, 2, 8);
  std::vector<double> times{0.0};
  for (int k = 0; k < n; ++k) {
    const double t = std::stod(model::number_text(lo * std::pow(hi / lo, static_cast<double>(k) / (n - 1)), 2));
    if (t > times.back()) times.push_back(t);
  }
  return times;
}

// Grid::points() must not wrap around; empty when it does not.
std::string grid_size_problem(const map::Grid& grid) {
  constexpr std::size_t kMax = std::numeric_limits<std::size_t>::max();
  std::size_t points = 1;
  bool overflows = false;
  std::string shape;
  for (const map::Axis& axis : grid.axes) {
    const std::size_t n = axis.values.size();
    overflows = overflows || points > kMax / n;
    points = overflows ? points : points * n;
    shape += (shape.empty() ? "" : " x ") + std::to_string(n);
  }
  if (!overflows) return {};
  return "grid = " + shape + " points: their number does not fit in 64 bits; valid range: at most " +
         std::to_string(kMax) + " points";
}

// The sample must fit the grid: empty, or the problem line.
std::string sample_size_problem(const sweep::SweepConfig& config, const std::string& text) {
  const std::size_t points = config.grid.points();
  if (!config.reference.sample || *config.reference.sample <= points) return {};
  return dotted(Fixed::reference_sample) + " = " + text + ": value " + text + " is more than the grid's " +
         std::to_string(points) + (points == 1 ? " point" : " points") +
         "; valid range: all, invalid, boundary, or an integer in [1, " + std::to_string(points) +
         "] (the grid's point count)";
}

std::string resolved_text(const std::vector<Setting>& settings, const sweep::SweepConfig& config) {
  std::string text =
      "# punchsweep sweep: the resolved configuration (command line > config file > defaults).\n"
      "# Every key has its final value; the comment above it says where the value came from.\n";
  std::string section;
  for (std::size_t k = 0; k < keys().size(); ++k) {
    const KeySpec& spec = keys()[k];
    // A [grid] key of another creep law's parameter is no axis of this map; grid.pressure
    // stands for grid.pbar where it is given.
    if (spec.fixed == Fixed::none && config.grid.find(spec.name) == config.grid.rank()) continue;
    const bool by_pressure = !settings[key_index(Fixed::grid_pressure)].text.empty();
    if (spec.fixed == Fixed::grid_pressure && !by_pressure) continue;
    if (spec.parameter != nullptr && spec.parameter->name == model::kPressure && by_pressure) continue;
    if (section != spec.section) {
      section = spec.section;
      text += "\n[" + section + "]\n";
    }
    switch (settings[k].source) {
      case Source::default_value:
        text += "# default\n";
        break;
      case Source::file:
        text += "# from " + config.config_path + "\n";
        break;
      case Source::command_line:
        text += "# from the command line\n";
        break;
    }
    text += spec.name + " = " + (spec.canonical ? spec.canonical(config) : settings[k].text) + "\n";
  }
  return text;
}

std::vector<std::string> identity(const sweep::SweepConfig& config) {
  std::vector<std::string> lines;
  for (const map::Axis& axis : config.grid.axes) {
    lines.push_back("grid." + axis.name + " = " + input::format_axis_values(axis.values));
  }
  for (const KeySpec& spec : keys()) {
    if (!spec.identity) continue;
    for (std::string& line : spec.identity(config)) lines.push_back(std::move(line));
  }
  return lines;
}

void write_help(std::ostream& out, const po::options_description& opts) {
  out << "usage: punchsweep sweep [--config FILE.ini] [--output FILE.h5] [--resume] [--overwrite]\n"
         "                        [--dry-run] [--quiet] [--quantities regime|full] [--chunk N]\n"
         "                        [--reference none|bem] [--bem-grid N]\n"
         "                        [--SECTION.KEY VALUE ...]\n\n"
         "punchsweep sweep: the regime map (immediate, delayed, never), t* and the contact state\n"
         "at every point of a grid over l, dh, pbar, s and the creep law's parameters (for the\n"
         "standard linear solid: l, dh, T, pbar, s), written to one HDF5 file.\n"
         "A texture's map (any lattice, levels, cell file, supercell or height map) takes a config\n"
         "with a [texture] section: punchsweep sweep --texture.lattice hexagonal --help explains it.\n\n"
         "Units: lengths in R (punch size), pressures in E0* = E0/(1-nu^2), time in T_eps\n"
         "(creep time); T = T_eps/T_sigma, s and C are dimensionless.\n\n"
      << opts << "\n"
      << "Where values come from: the command line wins over the --config file, which wins\n"
         "over the embedded defaults. Keys the file leaves out keep their defaults, [grid] axes\n"
         "included, so a file may set only the axes it changes. A shortcut and its key (e.g.\n"
         "--output and --output.file) may not both be given.\n\n"
         "The periodic BEM reference (--reference bem, or [reference] method = bem): beside the\n"
         "model, every grid point, or reference.sample = K points drawn at random, is solved by the\n"
         "boundary-element solver of `punchsweep reference` on an N x N grid (--bem-grid N) at the\n"
         "time.times snapshots, into bem_regime, bem_t_star, bem_a1, bem_a2, bem_P1, bem_P2 and\n"
         "bem_area_fraction (also with --quantities regime); points outside the sample read\n"
         "not_computed (-1) or NaN. A BEM point costs milliseconds to seconds where a model point\n"
         "costs microseconds: check --dry-run's estimate, and keep tiles short with --chunk (a\n"
         "tile is the unit of scheduling, of resuming and of finishing after a stop signal).\n"
         "  [reference]\n"
         "  method = bem\n"
         "  grid = 64\n"
         "  sample = 500\n"
         "  seed = 1\n\n"
         "Config file (INI: [section] headers, key = value lines, '#' starts a comment;\n"
         "unknown sections and keys are errors):\n"
         "  # my_sweep.ini\n"
         "  [grid]\n"
         "  l = linspace(0.5, 1.25, 16)\n"
         "  dh = 0, 0.025, 0.05, 0.075, 0.1\n"
         "  T = 2, 5, 10\n"
         "  pbar = logspace(0.005, 0.08, 32)\n"
         "  s = 2\n"
         "  [model]\n"
         "  C = 0.5\n"
         "  creep_law = standard_linear_solid\n"
         "  [time]\n"
         "  times = 0, 0.5, 1, 2, 5\n"
         "  [output]\n"
         "  file = my_map.h5\n"
         "  quantities = full\n"
         "  [run]\n"
         "  chunk = 4096\n"
         "  quiet = false\n\n"
         "Axis syntax (the [grid] keys and time.times):\n"
         "  0.5, 0.75, 1        a list (commas and/or spaces), strictly increasing\n"
         "  0.75                a single value\n"
         "  linspace(a, b, n)   n values evenly spaced from a to b, both included\n"
         "  logspace(a, b, n)   n values geometrically spaced from a to b, both included\n"
         "                      (a and b are the values, not exponents; a, b > 0)\n"
         "  n is an integer in [1, "
      << input::kMaxAxisCount
      << "]; n = 1 needs a == b. s takes integers only.\n"
         "  Generated values are rounded to 15 significant digits, so that\n"
         "  linspace(0.5, 1.25, 16) equals the list 0.5, 0.55, 0.6, ..., 1.25.\n\n"
         "Embedded default grid (without --config, and for [grid] keys a file leaves out):\n";
  std::size_t points = 1;
  std::string product;
  for (const model::Parameter* p : model::sweep_axes(model::creep_laws().front().parameters)) {
    const map::Axis axis = input::parse_axis(std::string(p->sweep_default), p->integer);
    std::string line = "  " + std::string(p->name);
    line.resize(7, ' ');
    line += "= " + std::string(p->sweep_default);
    line.resize(38, ' ');
    out << line << axis.values.size() << " values\n";
    points *= axis.values.size();
    product += (product.empty() ? "" : " x ") + std::to_string(axis.values.size());
  }
  out << "  " << product << " = " << points << " points\n\n"
      << "Examples:\n"
         "  punchsweep sweep --dry-run\n"
         "  punchsweep sweep --config my_sweep.ini --output my_map.h5\n"
         "  punchsweep sweep --config my_sweep.ini --grid.T 2,5,10 --model.C 0.7 --quiet\n"
         "  punchsweep sweep --reference bem --bem-grid 64 --reference.sample 500 --chunk 256\n\n"
         "Exit codes: 0 success, 2 bad input (one line per problem:\n"
         "KEY = VALUE: PROBLEM; valid range: RANGE), 3 stopped by SIGTERM, SIGUSR1 or\n"
         "SIGINT (finished tiles kept; finish with --resume), 1 failure.\n";
}

}  // namespace

sweep::SweepConfig parse_sweep_options(const std::vector<std::string>& args, std::ostream& help_out,
                                       bool* help_shown) {
  if (help_shown != nullptr) *help_shown = false;
  const po::options_description opts = command_line_options();
  const po::variables_map cli = parse_command_line(args, opts);
  if (cli.count("help")) {
    write_help(help_out, opts);
    if (help_shown != nullptr) *help_shown = true;
    return {};
  }

  sweep::SweepConfig config;
  config.config_path = cli.count("config") ? cli["config"].as<std::string>() : "";
  if (!config.config_path.empty()) config.input_files.push_back(config.config_path);
  config.dry_run = cli.count("dry-run") > 0;
  std::vector<Setting> settings = resolve_settings(cli, config.config_path);
  std::vector<std::string> problems = apply_settings(settings, config);
  if (Setting& times = settings[key_index(Fixed::time_times)];
      problems.empty() && times.source == Source::default_value && !config.materials.empty()) {
    config.times = material_times(config);
    times.text = input::format_axis_values(config.times);
  }
  if (problems.empty()) {
    if (std::string problem = grid_size_problem(config.grid); !problem.empty()) problems.push_back(problem);
  }
  if (problems.empty() && config.ramp && !config.load_text.empty()) {
    problems.push_back("model.load_table = " + config.load_text +
                       ": a ramp_time axis is given too; valid range: one of grid.ramp_time and model.load_table");
  }
  if (config.resume && config.overwrite) {
    problems.push_back("run.resume = true and run.overwrite = true: give only one (--resume finishes or checks the "
                       "existing map, --overwrite replaces it)");
  }
  if (problems.empty()) {
    if (std::string problem = sample_size_problem(config, settings[key_index(Fixed::reference_sample)].text); !problem.empty()) {
      problems.push_back(problem);
    }
  }
  if (!problems.empty()) throw UsageError(join(problems, "\n"));

  config.resolved_text = resolved_text(settings, config);
  config.identity = identity(config);
  return config;
}

}  // namespace punchsweep::input
