#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "map/grid.hpp"
#include "map/quantities.hpp"
#include "model/laws/creep_laws.hpp"
#include "model/problem/localization.hpp"
#include "model/laws/material.hpp"
#include "model/point/sensitivity.hpp"
#include "model/numerics/units.hpp"

namespace punchsweep::sweep {

/// The reference solver a sweep evaluates beside the model: none, or the periodic
/// boundary-element solver (src/reference), whose results go to the map's bem_* variables.
enum class ReferenceMethod { none, bem };

/// The BEM grid sizes (nodes per side of the l x l cell) that `punchsweep sweep` and
/// `punchsweep reference` accept.
inline constexpr int kMinBemGrid = 16;
inline constexpr int kMaxBemGrid = 2048;

/// Whether `n` is an accepted BEM grid size: an even integer in [kMinBemGrid, kMaxBemGrid].
inline bool is_bem_grid(double n) {
  return n >= kMinBemGrid && n <= kMaxBemGrid && std::fmod(n, 2.0) == 0.0;
}

/// [reference]: where and how the sweep evaluates the reference solver.
struct ReferenceConfig {
  ReferenceMethod method = ReferenceMethod::none;  ///< method
  int grid = 128;                                  ///< grid: BEM nodes per side, is_bem_grid
  /// sample: which grid points get the reference. `count`: all of them (`sample` empty) or
  /// `sample` = K drawn at random; `invalid`: those the model flags invalid; `boundary`:
  /// those whose model regime differs from a grid neighbour's (one step along any axis).
  enum class SampleRule { count, invalid, boundary } rule = SampleRule::count;
  std::optional<std::uint64_t> sample;
  std::uint64_t seed = 1;  ///< seed: of the random sample, at most INT64_MAX

  /// Whether the map gets the bem_* variables.
  bool on() const { return method == ReferenceMethod::bem; }
};

/// run.chunk = auto: sized at the start of a run by auto_chunk().
inline constexpr std::size_t kAutoChunk = 0;

/// A fully resolved, validated `punchsweep sweep` configuration (defaults, INI file and
/// command-line overrides merged; the command line wins).
struct SweepConfig {
  map::Grid grid;                     ///< [grid]: model::sweep_axes of the creep law, in that order
  double C = 0.5;                     ///< [model] C: shape constant, > 0
  /// [model] R: the punch's radius of curvature in a physical length unit (as given: the
  /// map's lengths are shown in its unit), or none (lengths in R only).
  std::optional<model::Physical> R;
  /// [model] creep_law: one of model::creep_laws(), or material_spec; the grid's axes
  /// include its parameters.
  const model::CreepLawSpec* creep_law = &model::creep_laws().front();
  /// [model] material: the material file (nullptr when the map is of creep_law) and its
  /// path as given; material_spec is material->spec(), which creep_law then points to.
  std::shared_ptr<const model::Material> material;
  std::string material_path;
  std::shared_ptr<const model::CreepLawSpec> material_spec;
  /// [model] material = a.ini, b.ini: every material file, in order (one for `material`);
  /// with several, the grid has a categorical `material` axis labelled by the files' names
  /// and material_spec is model::material_choice of them (material is then nullptr).
  std::vector<std::shared_ptr<const model::Material>> materials;
  std::vector<std::string> material_labels;
  /// The grid has a ramp_time axis (the load rises over ramp_time, then holds); without it
  /// the load is a step.
  bool ramp = false;
  /// [model] load_table: the load's shape when it is neither a step nor a ramp axis (its
  /// text as given in load_text; empty: a step).
  model::LoadShape loading{};
  std::string load_text;
  /// [model] localization: the localization model (paper by default).
  model::Localization localization{};
  /// The unit of every time: the material's time_unit, or T_eps.
  std::string time_unit() const { return materials.empty() ? "T_eps" : materials.front()->time_unit(); }
  std::vector<double> times{0.0, 0.5, 1.0, 2.0, 5.0};  ///< [time] times, in T_eps
  /// [output] tolerance: a box of tolerances about every point ("dh=0.5um, pressure=10%",
  /// as given in tolerance_text; empty: none): the map then stores t* at its ends and the
  /// regimes there (t_star_low, t_star_high, regime_low, regime_high).
  std::vector<model::StatedTolerance> tolerance;
  std::string tolerance_text;
  std::string output = "regime_map.h5";  ///< [output] file (final name; ".partial" while built)
  map::Quantities quantities = map::Quantities::full;  ///< [output] quantities
  /// [run] chunk: target number of values per tile and HDF5 chunk of the largest variable
  /// (tile_points() grid points).
  std::size_t chunk = 4096;
  ReferenceConfig reference;          ///< [reference] method, grid, sample, seed
  bool resume = false;                ///< [run] resume
  bool overwrite = false;             ///< [run] overwrite
  bool dry_run = false;               ///< --dry-run (command line only)
  bool quiet = false;                 ///< [run] quiet
  /// Where progress goes (set by the command, not a key): a terminal gets a line a second,
  /// a log (a file, a batch job's output) a line each 5% of the points and at least one
  /// every 10 minutes.
  bool progress_to_terminal = true;
  std::string config_path;            ///< the --config file, "" for the embedded default
  /// Every file the configuration was read from (the config file, the material files): no
  /// file of the map may be one of them (io::output_file_problem).
  std::vector<std::string> input_files;
  /// The resolved configuration as INI text, every key with its final value and a comment
  /// line naming its source; stored in the map and compared on --resume.
  std::string resolved_text;
  /// Grid points per tile and HDF5 chunk: `chunk` counts the values of the largest
  /// variable, so a map with time series of n snapshots (full quantities or a BEM
  /// reference) gets chunk / n points a tile, at least 1. A tile's memory, its compute time
  /// and an HDF5 chunk so stay bounded however many times are asked for.
  std::size_t tile_points() const {
    if (chunk == kAutoChunk) return 1;  // resolve auto first (auto_chunk)
    const std::size_t n = values_per_point();
    return chunk / n > 0 ? chunk / n : 1;
  }
  /// The values the largest variable holds per grid point: the snapshot times when the map
  /// has time series (full quantities or a BEM reference), else 1.
  std::size_t values_per_point() const {
    const bool series = quantities == map::Quantities::full || reference.on();
    return series && !times.empty() ? times.size() : 1;
  }
  /// The keys that define the map's content (grid, model, time, quantities, chunk,
  /// reference) as "section.key = value" lines; --resume refuses any difference in these.
  std::vector<std::string> identity;
};

/// run.chunk = auto for `ranks` ranks: about 16 tiles a rank, so the guided schedule ends
/// with a short tail, clamped to 256 .. 4096 values (compression and rank 0's per-tile cost
/// want large tiles; past 4096 nothing is gained).
inline std::size_t auto_chunk(const SweepConfig& config, int ranks) {
  const double values = static_cast<double>(config.grid.points()) * static_cast<double>(config.values_per_point());
  const double per_tile = values / (16.0 * static_cast<double>(ranks > 0 ? ranks : 1));
  return static_cast<std::size_t>(std::clamp(per_tile, 256.0, 4096.0));
}

/// Sets run.chunk (and its identity line) to `chunk`, resolving auto.
inline void set_chunk(SweepConfig& config, std::size_t chunk) {
  config.chunk = chunk;
  for (std::string& line : config.identity) {
    if (line.rfind("run.chunk = ", 0) == 0) line = "run.chunk = " + std::to_string(chunk);
  }
}

}  // namespace punchsweep::sweep
