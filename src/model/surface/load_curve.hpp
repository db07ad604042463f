#pragma once
/// @file
/// The elastic load curve of a periodic texture (docs/model.md, section 17): the state of
/// its cell (model::CellGeometry) from first contact to full contact as a function of the
/// load X alone. While the contact only grows, the viscoelastic state at time t is the
/// elastic one at the creep-weighted load X(t) (section 14.1), so one curve per geometry
/// answers every material, temperature and load history. The boundary elements fill it
/// (reference/load_curve.hpp); this is its data and its reading. Units: lengths in R, loads
/// X in E0* (unit compliance), level loads in R^2 E0*.

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace punchsweep::model {

/// One solve of the curve: the cell under mean pressure X.
struct LoadCurveSample {
  double X = 0.0;                   ///< in E0*
  std::vector<double> level_load;   ///< Q_L per level, in R^2 E0*; they sum to X Lx Ly
  std::vector<double> level_area;   ///< contact area per level, in R^2
};

/// Where a load falls on the curve.
enum class CurveRange {
  /// Below the first sample (the tallest sites' spots span fewer than the curve's
  /// min_spot_nodes nodes): areas follow the isolated punch's a^(s+1) ~ load from the first
  /// sample down; the loads are the first sample's shares; a level not yet at its touchdown
  /// has neither (its share of the load is the tallest level's).
  below_resolution,
  sampled,       ///< between the samples: interpolated (see LoadCurve::at)
  full_contact,  ///< every node in contact: exact (areas the levels' shares, loads grow by them)
  above_top,     ///< past the curve's stated top without full contact: not answered
};

/// The state of the cell at a load, read from the curve.
struct CurveState {
  double X = 0.0;
  CurveRange range = CurveRange::sampled;
  std::vector<double> level_load;  ///< per level, in R^2 E0*
  std::vector<double> level_area;  ///< per level, in R^2
  double area_fraction = 0.0;      ///< total contact area over the cell's
  /// Sites whose tip has touched by X, over all sites (per site X*: exact, not interpolated).
  double sites_touched = 0.0;
  std::vector<double> level_sites_touched;  ///< the same within each level
};

/// The curve of one geometry on one grid.
struct LoadCurve {
  double cell_area = 1.0;               ///< Lx Ly, in R^2
  int nx = 0, ny = 0;                   ///< the grid it was solved on
  std::vector<int> site_level;          ///< per site (the geometry's order)
  /// Per site, the load at which its tip touches (its gap to the tallest tip closes): 0 for
  /// the tallest sites, +infinity where it has not touched by the curve's end.
  std::vector<double> site_touchdown;
  std::vector<double> level_touchdown;  ///< per level: the least of its sites'
  std::vector<double> level_share;      ///< per level: its share of the cell in full contact
  /// The isolated punch's exponent of the tallest sites (area ~ X^(2/(s+1)) below the first
  /// sample).
  int s_tallest = 2;
  std::vector<LoadCurveSample> samples;  ///< increasing X; the last is full contact or the top
  /// Per interval between samples k and k + 1: whether the pressure grew at every node (the
  /// condition for the viscoelastic pressure to stay >= 0, docs/model.md section 14.1).
  std::vector<char> pressure_monotone;
  /// The load of full contact (every node pressed), the last sample; +infinity where the
  /// curve stops at its top before.
  double X_full = std::numeric_limits<double>::infinity();
  /// From this load on the tallest spots span enough nodes for the curve to answer for the
  /// continuum (reference::LoadCurveOptions::resolved_spot_nodes); below it a reading is the
  /// grid's own and flagged.
  double X_resolved = 0.0;
  /// Per level: 1 where its touchdown is the small-spot limit's (model::answer_small_spots,
  /// docs/model.md section 17.6), which holds it below X_resolved as well; empty on a curve
  /// as built or read (the limit is taken after, from the geometry; tables() leaves it out).
  std::vector<char> level_small_spot;
  /// Per site: 1 where its touchdown is the small-spot limit's (as level_small_spot; empty
  /// alike on a curve as built or read).
  std::vector<char> site_small_spot;
  /// The load up to which the readings are the small-spot limit's states, the same on every
  /// grid (model::resolve_small_spots); 0 where none are (a curve as built or read).
  double X_small_spot = 0.0;

  int levels() const { return static_cast<int>(level_touchdown.size()); }
  std::size_t sites() const { return site_level.size(); }
  double X_first() const { return samples.front().X; }
  /// Each of `levels` levels' touchdown: the least of its sites' (site_touchdown by
  /// site_level; +infinity for a level none of whose sites has touched).
  std::vector<double> least_site_touchdowns(int levels) const;
  double X_last() const { return samples.back().X; }

  /// The state at load X >= 0: between samples, each level's area interpolated linearly
  /// in log X as log area (as the isolated punch's power law, exact for it) and its load as
  /// the share Q_L / (X Lx Ly); over an interval that starts at the level's touchdown (or
  /// at zero area) its area linearly in X, as new spots grow.
  CurveState at(double X) const;
  /// Whether the pressure grew at every node over loads [X_a, X_b] (the samples' record;
  /// true in full contact, where extra load spreads evenly).
  bool monotone_between(double X_a, double X_b) const;

  /// The curve as far as X_end, a sample of it (or past its last): its samples up to X_end,
  /// the touchdowns past X_end +infinity, full contact only where it comes by X_end. A curve
  /// built to full contact, cut at the sample where the march of a curve built for a smaller
  /// reach stops (reference::march_end), is that curve (engine's cache reads a longer curve
  /// so).
  LoadCurve up_to(double X_end) const;

  /// The curve as numbers (what the table cache keeps): kFormat, then the sizes, the
  /// per-site and per-level fields, the intervals' record and the samples.
  std::vector<double> tables() const;
  /// The curve of tables(); nullopt for numbers of another format, sizes that do not add
  /// up, or a curve load_curve_error refuses.
  static std::optional<LoadCurve> from_tables(const std::vector<double>& numbers);
  /// 2: touchdowns by the tip's pressure; 3: X_resolved; 4: solves scale-free at any relief; 5: a
  /// midpoint's and a bisection's solve started between its bracket's (the last bits move)
  static constexpr double kFormat = 5.0;
};

/// Empty when `curve` is one the readers can use (samples increasing in X, sizes matching,
/// finite values), else a sentence naming what is not: a cached curve is checked by it.
std::string load_curve_error(const LoadCurve& curve);

}  // namespace punchsweep::model
