#include "input/texture_sweep_options.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "input/ini_lines.hpp"
#include "input/text_file.hpp"
#include "run/text_lines.hpp"
#include "input/usage_error.hpp"

namespace punchsweep::input {
namespace {

constexpr std::array<std::string_view, 7> kSections{"texture", "grid", "model", "time", "reference", "output", "run"};

bool is_section(const std::string& name) {
  return std::find(kSections.begin(), kSections.end(), name) != kSections.end();
}

std::string sections_list() {
  std::string out;
  for (const std::string_view s : kSections) out += (out.empty() ? "" : ", ") + std::string(s);
  return out;
}

/// "section.key" = value, in the order first given.
using Settings = std::vector<std::pair<std::string, std::string>>;

void set(Settings& settings, const std::string& key, const std::string& value) {
  for (auto& [k, v] : settings) {
    if (k == key) {
      v = value;
      return;
    }
  }
  settings.emplace_back(key, value);
}

Settings read_config(const std::string& path) {
  if (path.empty()) throw UsageError("--config needs a file name (see punchsweep sweep --help)");
  const IniScan scan = scan_ini(path, read_text_file(path, "config file"), is_section,
                                "sections of a texture's map: " + sections_list(),
                                [](const std::string&, const std::string&) { return std::string(); });
  if (!scan.problems.empty()) throw UsageError(run::join(scan.problems, "\n"));
  Settings settings;
  for (const IniSetting& s : scan.settings) settings.emplace_back(s.key(), s.value);
  return settings;
}

bool read_switch(const std::string& key, const std::string& value) {
  if (value == "true" || value == "1" || value == "yes") return true;
  if (value == "false" || value == "0" || value == "no") return false;
  throw UsageError(key + " = " + value + ": valid: true or false");
}

/// surface's option for a [texture], [grid] or [model] key.
std::string keyword_of(const std::string& name) {
  if (name == "ramp_time") return "ramp";
  std::string out = name;
  std::replace(out.begin(), out.end(), '_', '-');
  return out;
}

}  // namespace

bool is_texture_sweep(const std::vector<std::string>& args) {
  std::string config;
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (args[k].rfind("--texture.", 0) == 0) return true;
    if (args[k] == "--config" && k + 1 < args.size()) config = args[k + 1];
    if (args[k].rfind("--config=", 0) == 0) config = args[k].substr(9);
  }
  if (config.empty()) return false;
  std::ifstream in(config);
  for (std::string line; std::getline(in, line);) {
    if (const std::size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    line = run::trim(line);
    if (line.size() > 2 && line.front() == '[' && line.back() == ']' && run::trim(line.substr(1, line.size() - 2)) == "texture") {
      return true;
    }
  }
  return false;
}

TextureSweepOptions parse_texture_sweep_options(const std::vector<std::string>& args) {
  TextureSweepOptions out;
  Settings command_line;
  const auto value_of = [&](std::size_t& k, const std::string& option) {
    const std::string& a = args[k];
    if (const std::size_t equals = a.find('='); equals != std::string::npos) return a.substr(equals + 1);
    if (k + 1 >= args.size()) throw UsageError(option + " needs a value (see punchsweep sweep --help)");
    return args[++k];
  };
  for (std::size_t k = 0; k < args.size(); ++k) {
    const std::string& a = args[k];
    const std::string option = a.substr(0, a.find('='));
    if (option == "--help") {
      out.help = true;
    } else if (option == "--config") {
      out.config_path = value_of(k, option);
    } else if (option == "--output") {
      set(command_line, "output.file", value_of(k, option));
    } else if (option == "--resume" || option == "--overwrite" || option == "--quiet") {
      set(command_line, "run." + option.substr(2), a.find('=') == std::string::npos ? "true" : value_of(k, option));
    } else if (option == "--chunk") {
      set(command_line, "run.chunk", value_of(k, option));
    } else if (option == "--quantities") {
      set(command_line, "output.quantities", value_of(k, option));
    } else if (a == "--dry-run") {
      out.dry_run = true;
    } else if (option.rfind("--", 0) == 0 && option.find('.') != std::string::npos) {
      const std::string key = option.substr(2);
      const std::string section = key.substr(0, key.find('.'));
      if (!is_section(section)) {
        throw UsageError("unknown option " + option + " (sections of a texture's map: " + sections_list() + ")");
      }
      set(command_line, key, value_of(k, option));
    } else {
      throw UsageError("unknown option " + a + " for a texture's map (see punchsweep sweep --help)");
    }
  }
  if (out.help) return out;
  Settings settings = out.config_path.empty() ? Settings{} : read_config(out.config_path);
  // A file a config names is taken from the config's own folder, as a user reads it (and as
  // a regime map's config takes its material); one on the command line from where it runs.
  for (auto& [key, value] : settings) {
    if (key != "model.material" && key != "texture.cell" && key != "texture.height_map") continue;
    const std::filesystem::path file(run::trim(value));
    if (file.is_relative()) value = (std::filesystem::path(out.config_path).parent_path() / file).string();
  }
  for (const auto& [key, value] : command_line) set(settings, key, value);
  for (const auto& [key, value] : settings) {
    const std::string section = key.substr(0, key.find('.'));
    const std::string name = key.substr(key.find('.') + 1);
    if (section == "output") {
      if (name == "file") {
        out.output = value;
      } else if (name == "tolerance" || name == "quantities") {
        out.keywords.emplace_back(name, value);
        out.origins.push_back(key);
      } else {
        throw UsageError("unknown key " + key + " (keys of [output] for a texture's map: file, tolerance, quantities)");
      }
    } else if (section == "run") {
      if (name == "resume") {
        out.resume = read_switch(key, value);
      } else if (name == "overwrite") {
        out.overwrite = read_switch(key, value);
      } else if (name == "quiet") {
        out.quiet = read_switch(key, value);
      } else if (name == "chunk") {
        // The map's tiles (engine::TextureMapPlan): a keyword of the map, part of its identity.
        out.keywords.emplace_back("chunk", value);
        out.origins.push_back(key);
      } else {
        throw UsageError("unknown key " + key + " (keys of [run] for a texture's map: resume, overwrite, quiet, chunk)");
      }
    } else if (section == "reference") {
      // A sample of the map's load points stepped in time on the same cell (surface --check).
      if (name != "sample" && name != "seed") {
        throw UsageError("unknown key " + key + " (keys of [reference] for a texture's map: sample, seed)");
      }
      out.keywords.emplace_back(name == "sample" ? "check-sample" : "check-seed", value);
      out.origins.push_back(key);
    } else if (section == "time") {
      if (name != "times") throw UsageError("unknown key " + key + " (keys of [time]: times)");
      out.keywords.emplace_back("times", value);
      out.origins.push_back(key);
    } else {
      out.keywords.emplace_back(keyword_of(name), value);
      out.origins.push_back(key);
    }
  }
  if (out.resume && out.overwrite) {
    throw UsageError("run.resume = true and run.overwrite = true: give only one (--resume finishes or checks the existing "
                     "map, --overwrite replaces it)");
  }
  return out;
}

const char* const kTextureSweepHelp =
    "A texture's map (any lattice, levels, cell file, scattered supercell or height map): a\n"
    "config with a [texture] section, or --texture.KEY on the command line. Each geometry\n"
    "(a value of l, dh, dh2) is one load curve; the pressures, the law's values and the ramp\n"
    "times are read off it in tiles (rows of the pressure axis, about run.chunk load points x\n"
    "times each), dealt to the ranks as units of work and journalled when done (--resume\n"
    "computes only what the journal lacks). The map is a netCDF-4 file with a level\n"
    "dimension (docs/cli.md, \"A texture's map through sweep\").\n"
    "  # hexagonal.ini\n"
    "  [texture]\n"
    "  lattice = hexagonal\n"
    "  grid = 64\n"
    "  [model]\n"
    "  material = materials/nbr_linder2011.ini\n"
    "  R = 60um\n"
    "  s = 2\n"
    "  [grid]\n"
    "  l = 200um\n"
    "  dh = 2um, 3um\n"
    "  dh2 = 5um\n"
    "  pressure = logspace(5kPa, 50kPa, 6)\n"
    "  [time]\n"
    "  times = 0, 1s, 1min\n"
    "  [output]\n"
    "  file = hexagonal.nc\n"
    "Keys: [texture] surface's texture options with '_' for '-' (lattice, dh2, cell, height_map,\n"
    "pixel, supercell, scatter, seed, grid, curve, ...); [grid] l, dh, dh2, pbar or pressure, T or\n"
    "temperature, ramp_time; [model] material, R, s, C, load_table; [time] times; [reference]\n"
    "sample (K load points stepped in time on the same cell, as surface --check), seed; [output]\n"
    "file, tolerance, quantities (regime or full); [run] resume, overwrite, quiet, chunk (4096).\n"
    "--dry-run: each curve's grid, memory,\n"
    "whether the cache holds it and an estimate of its time on this machine; nothing is run.\n";

}  // namespace punchsweep::input
