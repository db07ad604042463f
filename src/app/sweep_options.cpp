#include "app/sweep_options.hpp"

#include <boost/program_options.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "app/usage_error.hpp"
#include "app/value_parsing.hpp"
#include "model/shape.hpp"
#include "model/standard_linear_solid.hpp"
#include "sweep/axis_parser.hpp"

namespace po = boost::program_options;

namespace punchsweep::app {
namespace {

constexpr const char* kWhitespace = " \t\r\n\f\v";
constexpr const char* kSeeHelp = " (see punchsweep sweep --help)";
constexpr const char* kBoolRange = "true, false, 1, 0, yes or no";
constexpr std::array<const char*, 6> kSections{"grid", "model", "time", "output", "run", "reference"};

// Every config key; the order is that of the help text and of resolved_text.
enum Key : std::size_t {
  kGridL, kGridDh, kGridT, kGridPbar, kGridS,
  kModelC, kModelCreepLaw, kTimeTimes, kOutputFile, kOutputQuantities,
  kRunChunk, kRunQuiet, kRunResume, kRunOverwrite,
  kReferenceMethod, kReferenceGrid, kReferenceSample, kReferenceSeed, kKeyCount
};

struct KeySpec {
  const char* section;
  const char* name;
  const char* value_name;
  const char* default_text;
  const char* meaning;  // with the unit
  const char* range;    // as printed after "valid range: "
};

constexpr std::array<KeySpec, kKeyCount> kKeys{{
    {"grid", "l", "AXIS", "linspace(0.5, 1.25, 7)", "lattice pitch l, in R", "l > 0 (in R)"},
    {"grid", "dh", "AXIS", "linspace(0.01, 0.12, 23)", "height difference dh of the two punch levels, in R",
     "dh >= 0 (in R)"},
    {"grid", "T", "AXIS", "linspace(2, 10, 9)",
     "creep ratio T = T_eps/T_sigma of the standard linear solid (dimensionless; T = 1 is elastic)",
     "T >= 1 (T = T_eps/T_sigma)"},
    {"grid", "pbar", "AXIS", "logspace(0.005, 0.08, 24)", "constant nominal pressure pbar0, in E0* = E0/(1-nu^2)",
     "pbar > 0 (in E0* = E0/(1-nu^2))"},
    {"grid", "s", "AXIS", "1, 2, 3", "shape exponent s of f(r) = C r^s / R^(s-1) (1 cone, 2 paraboloid)",
     "integers in [1, 32]"},
    {"model", "C", "C", "0.5", "shape constant C of f(r) (dimensionless; sphere: s = 2, C = 0.5)", "C > 0"},
    {"model", "creep_law", "NAME", "standard_linear_solid", "creep law of the half-space",
     "standard_linear_solid (alias sls)"},
    {"time", "times", "AXIS", "0, 0.5, 1, 2, 5", "snapshot times of the stored time series, in T_eps",
     "each t >= 0 and finite, strictly increasing (in T_eps)"},
    {"output", "file", "FILE", "regime_map.h5", "the HDF5 regime map to write",
     "a non-empty file name without '#' or line breaks"},
    {"output", "quantities", "WHAT", "full",
     "what the map stores: regime (regime, t*, validity, long-term state) or full (also the time series "
     "at time.times)",
     "regime or full"},
    {"run", "chunk", "N", "4096", "target number of grid points per tile and per HDF5 chunk",
     "an integer >= 1"},
    {"run", "quiet", "BOOL", "false", "no progress output", kBoolRange},
    {"run", "resume", "BOOL", "false",
     "continue an interrupted sweep into the existing partial map; refused if its grid, model or reference "
     "differ",
     kBoolRange},
    {"run", "overwrite", "BOOL", "false", "replace an existing map at output.file", kBoolRange},
    {"reference", "method", "METHOD", "none",
     "reference solver evaluated beside the model: none, or bem (the periodic boundary-element solver of "
     "`punchsweep reference`; adds the bem_* variables)",
     "none or bem"},
    {"reference", "grid", "N", "128",
     "BEM nodes per side N of the l x l cell (spacing l/N; the cost of a point grows faster than N^2, "
     "--dry-run measures it)",
     "an even integer in [16, 2048]"},
    {"reference", "sample", "K", "all",
     "the grid points that get the reference: all, or K distinct points drawn uniformly at random (a pure "
     "function of the grid's shape, K and reference.seed); the others read not_computed",
     "all, or an integer in [1, the grid's point count]"},
    {"reference", "seed", "SEED", "1", "seed of the random sample of reference.sample = K",
     "an integer in [0, 9223372036854775807]"},
}};

// The [grid] keys come first, in the order of the grid's axes.
static_assert(std::size_t{kGridL} == sweep::kAxisL && std::size_t{kGridDh} == sweep::kAxisDh &&
              std::size_t{kGridT} == sweep::kAxisT && std::size_t{kGridPbar} == sweep::kAxisPbar &&
              std::size_t{kGridS} == sweep::kAxisS);

// Command-line shortcuts for the keys one sets most often.
struct Shortcut {
  const char* option;
  Key key;
  bool takes_value;  // false: a flag that sets the key to true
};

constexpr std::array<Shortcut, 8> kShortcuts{{
    {"output", kOutputFile, true},
    {"quantities", kOutputQuantities, true},
    {"chunk", kRunChunk, true},
    {"resume", kRunResume, false},
    {"overwrite", kRunOverwrite, false},
    {"quiet", kRunQuiet, false},
    {"reference", kReferenceMethod, true},
    {"bem-grid", kReferenceGrid, true},
}};

std::string dotted(Key key) { return std::string(kKeys[key].section) + "." + kKeys[key].name; }

std::string trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(kWhitespace);
  if (first == std::string::npos) return {};
  const std::size_t last = text.find_last_not_of(kWhitespace);
  return text.substr(first, last - first + 1);
}

std::string join(const std::vector<std::string>& lines, const char* separator) {
  std::string text;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (i > 0) text += separator;
    text += lines[i];
  }
  return text;
}

std::string section_keys(const std::string& section) {
  std::vector<std::string> names;
  for (const KeySpec& spec : kKeys) {
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
  for (std::size_t k = 0; k < kKeyCount; ++k) {
    if (key == dotted(static_cast<Key>(k))) return &kKeys[k];
  }
  return nullptr;
}

po::options_description key_options(const char* caption) {
  po::options_description opts(caption);
  for (std::size_t k = 0; k < kKeyCount; ++k) {
    const KeySpec& spec = kKeys[k];
    const std::string description =
        std::string(spec.meaning) + "; " + spec.range + "; default " + spec.default_text;
    opts.add_options()(dotted(static_cast<Key>(k)).c_str(), po::value<std::string>()->value_name(spec.value_name),
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
      ("chunk", po::value<std::string>()->value_name("N"),
       "same as --run.chunk: target grid points per tile and HDF5 chunk; an integer >= 1; default 4096")
      ("reference", po::value<std::string>()->value_name("METHOD"),
       "same as --reference.method: bem evaluates the periodic BEM reference at every grid point (or at "
       "--reference.sample K random ones) into the bem_* variables; none or bem; default none")
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
  std::vector<std::string> problems;
  std::map<std::string, int> first_line;
  std::string section;
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (const std::size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    line = trim(line);
    if (line.empty()) continue;
    const std::string where = "config file " + path + ", line " + std::to_string(number) + ": ";
    if (line.front() == '[' && line.back() == ']') {
      section = line.substr(1, line.size() - 2);
      if (!is_section(section)) {
        problems.push_back(where + "unknown section [" + section +
                           "] (sections: " + join({kSections.begin(), kSections.end()}, ", ") + ")");
      }
      continue;
    }
    const std::size_t equals = line.find('=');
    if (equals == std::string::npos) {
      problems.push_back(where + "expected '[section]' or 'key = value', got '" + line + "'");
      continue;
    }
    const std::string name = trim(line.substr(0, equals));
    if (section.empty()) {
      problems.push_back(where + "key '" + name + "' comes before any [section]");
      continue;
    }
    if (!is_section(section)) continue;  // its section is already reported
    const std::string key = section + "." + name;
    if (find_key(key) == nullptr) {
      problems.push_back(where + "unknown key " + key + " (keys of [" + section + "]: " + section_keys(section) + ")");
    } else if (const auto [it, inserted] = first_line.emplace(key, number); !inserted) {
      problems.push_back(where + key + " is set again (first on line " + std::to_string(it->second) + ")");
    }
  }
  return problems;
}

// The values the file sets, by key.
std::map<std::string, std::string> read_config_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.empty()) throw UsageError("--config needs a file name" + std::string(kSeeHelp));
  if (!fs::exists(path, ec)) throw UsageError("config file " + path + " does not exist");
  if (fs::is_directory(path, ec)) throw UsageError("config file " + path + " is a directory");
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (!in) throw UsageError("config file " + path + " cannot be read");
  const std::string text = buffer.str();

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

enum class Source { default_value, file, command_line };

struct Setting {
  std::string text;
  Source source = Source::default_value;
};

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
std::array<Setting, kKeyCount> resolve_settings(const po::variables_map& cli, const std::string& config_path) {
  std::vector<std::string> conflicts;
  for (const Shortcut& shortcut : kShortcuts) {
    const std::string key = dotted(shortcut.key);
    if (cli.count(shortcut.option) && cli.count(key)) {
      conflicts.push_back(std::string("--") + shortcut.option + " and --" + key + " both set " + key +
                          "; give only one");
    }
  }
  if (!conflicts.empty()) throw UsageError(join(conflicts, "\n"));

  std::array<Setting, kKeyCount> settings;
  for (std::size_t k = 0; k < kKeyCount; ++k) settings[k] = {kKeys[k].default_text, Source::default_value};
  if (cli.count("config")) {
    const std::map<std::string, std::string> file_values = read_config_file(config_path);
    for (std::size_t k = 0; k < kKeyCount; ++k) {
      const auto it = file_values.find(dotted(static_cast<Key>(k)));
      if (it != file_values.end()) settings[k] = {trim(it->second), Source::file};
    }
  }
  for (std::size_t k = 0; k < kKeyCount; ++k) {
    const std::string key = dotted(static_cast<Key>(k));
    if (cli.count(key)) settings[k] = {trim(cli[key].as<std::string>()), Source::command_line};
  }
  for (const Shortcut& shortcut : kShortcuts) {
    if (!cli.count(shortcut.option)) continue;
    settings[shortcut.key] = {shortcut.takes_value ? trim(cli[shortcut.option].as<std::string>()) : "true",
                              Source::command_line};
  }
  return settings;
}

std::string listed(const std::vector<double>& values) {
  constexpr std::size_t kShown = 5;
  if (values.size() <= kShown) return sweep::format_axis_values(values);
  return sweep::format_axis_values({values.begin(), values.begin() + kShown}) + ", ... (" +
         std::to_string(values.size()) + " in all)";
}

// Empty, or why `text` is not an axis whose values all pass `in_range`.
template <class InRange>
std::string check_axis(const std::string& text, bool integers, InRange in_range, sweep::Axis& axis) {
  try {
    axis = sweep::parse_axis(text, integers);
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
  int value = 0;
  try {
    value = parse_integer(text, dotted(kRunChunk));
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

std::string check_sample(const std::string& text, std::optional<std::uint64_t>& sample) {
  if (text == "all") {
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

// Fills `config` from the settings; returns one line per bad value.
std::vector<std::string> apply_settings(const std::array<Setting, kKeyCount>& settings, sweep::SweepConfig& config) {
  std::vector<std::string> problems;
  for (std::size_t k = 0; k < kKeyCount; ++k) {
    const Key key = static_cast<Key>(k);
    const std::string& text = settings[k].text;
    std::string problem;
    if (text.find_first_of("#\r\n") != std::string::npos) {
      // A config file could not hold it, so resolved_text would not read back.
      problem = "it contains '#' or a line break, which a config file cannot hold";
    } else {
      switch (key) {
        case kGridL:
          problem = check_axis(text, false, [](double v) { return v > 0.0; }, config.grid.axes[sweep::kAxisL]);
          break;
        case kGridDh:
          problem = check_axis(text, false, [](double v) { return v >= 0.0; }, config.grid.axes[sweep::kAxisDh]);
          break;
        case kGridT:
          problem = check_axis(text, false, [](double v) { return model::creep_ratio_error(v).empty(); },
                               config.grid.axes[sweep::kAxisT]);
          break;
        case kGridPbar:
          problem = check_axis(text, false, [](double v) { return v > 0.0; }, config.grid.axes[sweep::kAxisPbar]);
          break;
        case kGridS:
          problem = check_axis(
              text, true,
              [](double v) { return v >= model::Shape::kMinExponent && v <= model::Shape::kMaxExponent; },
              config.grid.axes[sweep::kAxisS]);
          break;
        case kModelC:
          try {
            config.C = parse_real(text, dotted(key));
            if (!(config.C > 0.0)) problem = "value " + sweep::format_axis_value(config.C) + " is outside its range";
          } catch (const UsageError&) {
            problem = "'" + text + "' is not a finite number";
          }
          break;
        case kModelCreepLaw:
          if (text == "standard_linear_solid" || text == "sls") {
            config.creep_law = "standard_linear_solid";
          } else {
            problem = "'" + text + "' is not a known creep law";
          }
          break;
        case kTimeTimes: {
          sweep::Axis times;
          problem = check_axis(text, false, [](double t) { return t >= 0.0; }, times);
          config.times = times.values;
          break;
        }
        case kOutputFile:
          if (text.empty()) problem = "the file name is empty";
          config.output = text;
          break;
        case kOutputQuantities:
          if (text == "regime") {
            config.quantities = sweep::Quantities::regime;
          } else if (text == "full") {
            config.quantities = sweep::Quantities::full;
          } else {
            problem = "'" + text + "' is not one of regime, full";
          }
          break;
        case kRunChunk:
          problem = check_chunk(text, config.chunk);
          break;
        case kRunQuiet:
          problem = check_bool(text, config.quiet);
          break;
        case kRunResume:
          problem = check_bool(text, config.resume);
          break;
        case kRunOverwrite:
          problem = check_bool(text, config.overwrite);
          break;
        case kReferenceMethod:
          if (text == "none") {
            config.reference.method = sweep::ReferenceMethod::none;
          } else if (text == "bem") {
            config.reference.method = sweep::ReferenceMethod::bem;
          } else {
            problem = "'" + text + "' is not one of none, bem";
          }
          break;
        case kReferenceGrid:
          problem = check_bem_grid(text, config.reference.grid);
          break;
        case kReferenceSample:
          problem = check_sample(text, config.reference.sample);
          break;
        case kReferenceSeed:
          // The map stores the seed as an int64 attribute.
          problem = check_whole(text, std::numeric_limits<std::int64_t>::max(), config.reference.seed);
          break;
        case kKeyCount:
          break;
      }
    }
    if (!problem.empty()) {
      problems.push_back(dotted(key) + " = " + (text.empty() ? "''" : text) + ": " + problem +
                         "; valid range: " + kKeys[k].range);
    }
  }
  return problems;
}

// Grid::points() must not wrap around; empty when it does not.
std::string grid_size_problem(const sweep::Grid& grid) {
  constexpr std::size_t kMax = std::numeric_limits<std::size_t>::max();
  std::size_t points = 1;
  bool overflows = false;
  std::string shape;
  for (std::size_t a = 0; a < sweep::kAxes; ++a) {
    const std::size_t n = grid.axes[a].values.size();
    overflows = overflows || points > kMax / n;
    points = overflows ? points : points * n;
    shape += (a > 0 ? " x " : "") + std::to_string(n);
  }
  if (!overflows) return {};
  return "grid = " + shape + " points: their number does not fit in 64 bits; valid range: at most " +
         std::to_string(kMax) + " points";
}

// The canonical text of a [reference] key, as resolved_text and identity write it.
std::string reference_value(Key key, const sweep::ReferenceConfig& reference) {
  switch (key) {
    case kReferenceMethod:
      return reference.on() ? "bem" : "none";
    case kReferenceGrid:
      return std::to_string(reference.grid);
    case kReferenceSample:
      return reference.sample ? std::to_string(*reference.sample) : "all";
    default:
      return std::to_string(reference.seed);
  }
}

// The sample must fit the grid: empty, or the problem line.
std::string sample_size_problem(const sweep::SweepConfig& config, const std::string& text) {
  const std::size_t points = config.grid.points();
  if (!config.reference.sample || *config.reference.sample <= points) return {};
  return dotted(kReferenceSample) + " = " + text + ": value " + text + " is more than the grid's " +
         std::to_string(points) + (points == 1 ? " point" : " points") + "; valid range: all, or an integer in [1, " +
         std::to_string(points) + "] (the grid's point count)";
}

// The final value of each key as it goes into resolved_text: axes keep their given form
// (linspace stays readable), the rest are canonical.
std::string resolved_value(Key key, const std::string& text, const sweep::SweepConfig& config) {
  switch (key) {
    case kModelC:
      return sweep::format_axis_value(config.C);
    case kModelCreepLaw:
      return config.creep_law;
    case kRunChunk:
      return std::to_string(config.chunk);
    case kRunQuiet:
      return config.quiet ? "true" : "false";
    case kRunResume:
      return config.resume ? "true" : "false";
    case kRunOverwrite:
      return config.overwrite ? "true" : "false";
    case kReferenceMethod:
    case kReferenceGrid:
    case kReferenceSample:
    case kReferenceSeed:
      return reference_value(key, config.reference);
    default:
      return text;
  }
}

std::string resolved_text(const std::array<Setting, kKeyCount>& settings, const sweep::SweepConfig& config) {
  std::string text =
      "# punchsweep sweep: the resolved configuration (command line > config file > defaults).\n"
      "# Every key has its final value; the comment above it says where the value came from.\n";
  const char* section = "";
  for (std::size_t k = 0; k < kKeyCount; ++k) {
    const KeySpec& spec = kKeys[k];
    if (std::string(section) != spec.section) {
      section = spec.section;
      text += std::string("\n[") + section + "]\n";
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
    text += std::string(spec.name) + " = " + resolved_value(static_cast<Key>(k), settings[k].text, config) + "\n";
  }
  return text;
}

std::vector<std::string> identity(const sweep::SweepConfig& config) {
  std::vector<std::string> lines;
  for (std::size_t a = 0; a < sweep::kAxes; ++a) {
    lines.push_back(std::string("grid.") + sweep::kAxisNames[a] + " = " +
                    sweep::format_axis_values(config.grid.axes[a].values));
  }
  lines.push_back("model.C = " + sweep::format_axis_value(config.C));
  lines.push_back("model.creep_law = " + config.creep_law);
  lines.push_back("time.times = " + sweep::format_axis_values(config.times));
  lines.push_back(std::string("output.quantities = ") +
                  (config.quantities == sweep::Quantities::full ? "full" : "regime"));
  lines.push_back("run.chunk = " + std::to_string(config.chunk));
  for (const Key key : {kReferenceMethod, kReferenceGrid, kReferenceSample, kReferenceSeed}) {
    lines.push_back(dotted(key) + " = " + reference_value(key, config.reference));
  }
  return lines;
}

void write_help(std::ostream& out, const po::options_description& opts) {
  out << "usage: punchsweep sweep [--config FILE.ini] [--output FILE.h5] [--resume] [--overwrite]\n"
         "                        [--dry-run] [--quiet] [--quantities regime|full] [--chunk N]\n"
         "                        [--reference none|bem] [--bem-grid N]\n"
         "                        [--SECTION.KEY VALUE ...]\n\n"
         "punchsweep sweep: the regime map (immediate, delayed, never), t* and the contact state\n"
         "at every point of a 5-D grid over (l, dh, T, pbar, s), written to one HDF5 file.\n\n"
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
      << sweep::kMaxAxisCount
      << "]; n = 1 needs a == b. s takes integers only.\n"
         "  Generated values are rounded to 15 significant digits, so that\n"
         "  linspace(0.5, 1.25, 16) equals the list 0.5, 0.55, 0.6, ..., 1.25.\n\n"
         "Embedded default grid (without --config, and for [grid] keys a file leaves out):\n";
  std::size_t points = 1;
  std::string product;
  for (std::size_t a = 0; a < sweep::kAxes; ++a) {
    const sweep::Axis axis = sweep::parse_axis(kKeys[a].default_text, a == sweep::kAxisS);
    std::string line = "  " + std::string(sweep::kAxisNames[a]);
    line.resize(7, ' ');
    line += std::string("= ") + kKeys[a].default_text;
    line.resize(38, ' ');
    out << line << axis.values.size() << " values\n";
    points *= axis.values.size();
    product += (a > 0 ? " x " : "") + std::to_string(axis.values.size());
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
  config.dry_run = cli.count("dry-run") > 0;
  const std::array<Setting, kKeyCount> settings = resolve_settings(cli, config.config_path);
  std::vector<std::string> problems = apply_settings(settings, config);
  if (problems.empty()) {
    if (std::string problem = grid_size_problem(config.grid); !problem.empty()) problems.push_back(problem);
  }
  if (problems.empty()) {
    if (std::string problem = sample_size_problem(config, settings[kReferenceSample].text); !problem.empty()) {
      problems.push_back(problem);
    }
  }
  if (!problems.empty()) throw UsageError(join(problems, "\n"));

  config.resolved_text = resolved_text(settings, config);
  config.identity = identity(config);
  return config;
}

std::vector<std::string> identity_differences(const std::vector<std::string>& existing,
                                              const std::vector<std::string>& requested) {
  // Key order: as the existing map lists them, then keys only this run has.
  const auto split = [](const std::vector<std::string>& lines, std::vector<std::string>& order) {
    std::map<std::string, std::string> values;
    for (const std::string& line : lines) {
      const std::size_t equals = line.find('=');
      const std::string key = trim(line.substr(0, equals));
      const std::string value = equals == std::string::npos ? std::string() : trim(line.substr(equals + 1));
      if (values.emplace(key, value).second && std::find(order.begin(), order.end(), key) == order.end()) {
        order.push_back(key);
      }
    }
    return values;
  };
  std::vector<std::string> order;
  const std::map<std::string, std::string> old_values = split(existing, order);
  const std::map<std::string, std::string> new_values = split(requested, order);

  std::vector<std::string> differences;
  for (const std::string& key : order) {
    const auto old_it = old_values.find(key);
    const auto new_it = new_values.find(key);
    if (old_it == old_values.end()) {
      differences.push_back(key + ": the existing map does not record it; this run asks for " + new_it->second);
    } else if (new_it == new_values.end()) {
      differences.push_back(key + ": the existing map has " + old_it->second + "; this run does not set it");
    } else if (old_it->second != new_it->second) {
      differences.push_back(key + ": the existing map has " + old_it->second + "; this run asks for " +
                            new_it->second);
    }
  }
  return differences;
}

}  // namespace punchsweep::app
