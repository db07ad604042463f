#pragma once
/// @file
/// `punchsweep sweep` of a texture: a config with a [texture] section (or a --texture.KEY on
/// the command line). Its keys are `surface`'s, by section:
///   [texture] surface's texture keys (lattice, dh2, cell, height_map, supercell, scatter,
///             seed, grid, curve, pixel, summit_radius, level_gap, ...)
///   [grid]    the axes: the geometry's (l, dh, dh2) and the load's (pbar or pressure, the
///             creep law's T or temperature, ramp_time), each a value, a list, linspace()
///             or logspace(), with units where the model has a material and R
///   [model]   material, R, s, C, load_table
///   [time]    times
///   [reference] sample, seed: K load points stepped in time on the same cell (surface
///             --check), into the map's check_* variables
///   [output]  file, tolerance
///   [run]     resume, overwrite, quiet
/// A key's name is surface's option with '_' for '-' (height_map is --height-map); ramp_time
/// is --ramp. The command line's --SECTION.KEY VALUE overrides the file.

#include <string>
#include <vector>

#include "input/command_options.hpp"

namespace punchsweep::input {

/// Whether `args` (after `punchsweep sweep`) ask for a texture's map: a --texture.KEY
/// option, or a --config file with a [texture] section. A file that cannot be read is no
/// texture's (the regime sweep then names its problem).
bool is_texture_sweep(const std::vector<std::string>& args);

struct TextureSweepOptions {
  Keywords keywords;                ///< surface's keywords, axes included
  std::vector<std::string> origins; ///< each keyword's "section.key", for messages
  std::string output = "texture_map.nc";  ///< [output] file
  bool resume = false, overwrite = false, quiet = false;
  bool dry_run = false;             ///< --dry-run: what the map asks (curves, grids, memory, time), nothing run
  std::string config_path;          ///< --config, "" without one
  bool help = false;
};

/// Reads the arguments and the --config file. Throws UsageError naming the file and line,
/// or the option, for an unknown section, a key set twice in one file, a key of [output],
/// [time] or [run] the map does not take, or a switch that is not true or false.
TextureSweepOptions parse_texture_sweep_options(const std::vector<std::string>& args);

/// The help text's section on texture maps.
extern const char* const kTextureSweepHelp;

}  // namespace punchsweep::input
