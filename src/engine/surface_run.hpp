#pragma once
/// @file
/// One texture as `punchsweep surface` evaluates it (surface_command.hpp) and prints it
/// (surface_output.hpp): its inputs, geometry, curve, history and checks.

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "input/command_options.hpp"
#include "model/point/sensitivity.hpp"
#include "model/problem/cell_geometry.hpp"
#include "model/surface/load_curve.hpp"
#include "model/surface/surface_history.hpp"
#include "reference/cell_stepping.hpp"
#include "model/numerics/sample_statistics.hpp"
#include "reference/measured_cell.hpp"

namespace punchsweep::engine {

/// Where a texture's load curve comes from (--curve): the periodic model's tables
/// (model/surface/periodic_curve.hpp; the two-level square lattice), the cell's own boundary
/// elements (reference/load_curve.hpp), or the tables where they reach the lattice's dh and
/// the cell otherwise (--curve auto on the two-level square lattice).
enum class CurveSource { tables, cell, tables_or_cell };

/// One texture evaluated: its inputs, geometry, curve and history.
struct SurfaceRun {
  input::PointInputs inputs;
  model::LatticeKind lattice = model::LatticeKind::square;
  std::string cell_file;  ///< --cell FILE or --height-map FILE, or empty for a lattice
  std::optional<reference::MeasuredCell> measured;  ///< --height-map: the map's cell and summits
  model::CellGeometry geometry;
  std::vector<double> times;
  int supercell = 1;   ///< K: the cell is K x K lattice cells
  model::HeightScatter scatter;
  model::HeightScatter curvature;  ///< --curvature-scatter: each cap's C changed by C (1 + d)
  std::uint64_t seed = 1;          ///< --seed: the scatters' (an ensemble's first draw's)
  /// A supercell's: how far its tallest tip drawn (the drops' origin) lies above the tallest
  /// tips' design height, in R (0 without a height scatter).
  double tallest_rise = 0.0;
  /// --part-caps N: how far the tallest tip of a part of N caps would lie above the tall caps'
  /// design height (p5, median, p95, R), and of this supercell's caps, from the height
  /// scatter's distribution (model::tallest_rise_quantile); part_caps 0: not asked.
  double part_caps = 0.0;
  std::array<double, 3> part_rise{}, supercell_rise{};
  int seeds = 1;       ///< --seeds N: an ensemble of N draws of the scatter (evaluate_ensemble)
  double target_error = 0.0;  ///< --target-error: the ensemble stops at this standard error (0: all N)
  int grid_nodes = 0;  ///< nodes per pitch (0: --grid auto, until evaluated)
  /// --grid auto: the grid the taken one was held to (half its nodes; 0 where not held),
  /// each level's relative move of t* between them (+infinity where the regime changed),
  /// and the levels still moving at the grid's top (marked unresolved).
  int grid_coarser = 0;
  std::vector<double> grid_t_star_change;
  std::vector<int> unresolved_levels;
  /// --grid auto: per time, the estimated relative error of the area fraction on the grid
  /// taken (a third of its move from the coarser grid; empty where not held).
  std::vector<double> grid_area_error;
  /// --grid auto: the load (E0*) up to which the small-spot limit answers the given
  /// geometry's areas and loads (model::small_spot_reach; 0 where it does not take the
  /// cell), found once: no grid need resolve the spots below half of it. Empty until asked.
  std::optional<double> small_spot_reach;
  CurveSource curve_source = CurveSource::cell;  ///< asked; after evaluation tables or cell, what served
  model::LoadCurve curve;
  model::SurfaceHistory history;
  /// The largest creep-weighted load the curve is read at (E0*): the run's own X(inf), over
  /// the tolerances' corners and any more load points held (MoreLoadPoints::X_reach); the
  /// curve's march stops at its first sample past it (reference::LoadCurveOptions::X_reach).
  /// +infinity: to full contact (unlimited creep, --full-curve, or a reader of every load).
  double X_reach = std::numeric_limits<double>::infinity();
  bool full_curve = false;  ///< --full-curve: to full contact, whatever the loads reach
  double curve_seconds = 0.0;
  bool curve_cached = false;  ///< read from the table cache (texture/curve_cache.hpp)
  bool check = false;         ///< --check: step the same cell in time too
  std::vector<model::Tolerance> tolerances;  ///< --tolerance: on the pressure and the law's parameters
  /// Per level: d t*/dx along pbar and the law's parameters (empty for level 0), and the
  /// range of t* over the tolerances (none without).
  std::vector<std::vector<model::TStarDerivative>> derivatives;
  std::vector<std::optional<model::TStarRange>> ranges;
  std::optional<reference::CellReference> stepped;
  double check_seconds = 0.0;
  /// The stepping's touch times are the middles of intervals this wide (their uncertainty
  /// is half of it): reference::CellReferenceOptions::t_star_resolution, scaled to the law.
  double check_t_star_resolution = 0.0;
};

/// What an ensemble of drawn textures (--seeds N: the scatter drawn with seeds --seed to
/// --seed + N - 1, each its own supercell and curve) says: per level the touch times of its
/// first, median and last cap, per time the area fraction and the shares of caps in
/// contact (all and each level's), each as its mean, spread and 5-95% band over the draws;
/// and each draw's own values.
struct SurfaceEnsemble {
  struct Member {
    std::uint64_t seed = 0;
    /// Per level: the touch time of its first, median and last cap (+infinity: never).
    std::vector<double> first, median, last;
    /// Per series (SurfaceEnsemble::series_names), per time.
    std::vector<std::vector<double>> series;
    std::vector<char> resolved;  ///< per level: whether the draw's curve resolves its touch
    std::vector<double> valid;   ///< per time: 1 where the draw's snapshot is valid, else 0
  };
  struct Level {
    model::SampleStatistics first, median, last;
  };
  std::vector<Member> members;
  std::vector<Level> levels;
  /// --target-error: asked (0: none) and the largest standard error of a mean share or area
  /// fraction at the draws taken (NaN without one).
  double target_error = 0.0;
  double reached_error = std::numeric_limits<double>::quiet_NaN();
  /// area_fraction, touched, touched_0, touched_1, ...: per series, per time.
  std::vector<std::string> series_names;
  std::vector<std::vector<model::SampleStatistics>> series;
};

}  // namespace punchsweep::engine
