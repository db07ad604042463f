#pragma once
/// @file
/// A periodic texture in time (docs/model.md, section 17): its elastic load curve
/// (load_curve.hpp) read at the creep-weighted load X(t) of a material and a load history.
/// While the contact only grows, the state at t is the elastic state at X(t) (section
/// 14.1): each level touches where X(t) reaches its touchdown load, and the areas and the
/// sites in contact are the curve's at X(t). Units: times in the law's unit, X in E0*.

#include <span>
#include <string_view>
#include <vector>

#include "model/contact/regime.hpp"
#include "model/load/creep_weighted_load.hpp"
#include "model/load/load_history.hpp"
#include "model/surface/load_curve.hpp"

namespace punchsweep::model {

/// When one level touches: the classification of docs/model.md section 10 at the level's
/// touchdown load (immediate, delayed at t*, never).
struct LevelTouch {
  Regime regime = Regime::never;
  double t_star = 0.0;  ///< 0 for immediate, +infinity for never
  double X_star = 0.0;  ///< the level's touchdown load, in E0*
  /// Whether the curve resolves the touchdown: X* is 0, +infinity, or at or above the
  /// curve's X_resolved (below it the tallest spots span too few nodes).
  bool resolved = true;
};

/// Why a snapshot's numbers may not be trusted. The integer codes are the output's contract.
enum class SurfaceValidity : int {
  valid = 0,
  /// X(t) lies below the curve's X_resolved: the tallest spots span fewer nodes than the
  /// continuum needs (below its first sample the areas are extrapolated as an isolated
  /// punch's); a finer grid answers.
  below_resolution = 1,
  /// X(t) lies past the curve's top without full contact.
  above_top = 2,
  /// The pressure falls at some node between X(0) and X(t): the contact may recede, which
  /// the correspondence does not cover (the time-stepping reference does).
  unloading = 3,
  /// The loads' history integral would take more work than LoadHistory::kMaxSamples (a
  /// spectrum over more decades than the times resolve): the loads are not computed.
  history_cost = 4,
  /// `surface --check` stepped the same cell in time and its area differs from the curve's
  /// beyond the curve's stated accuracy (1% and half a node per cap): one of them is wrong.
  check_disagrees = 5,
};
std::string_view surface_validity_name(SurfaceValidity validity);

/// The texture at one time.
struct SurfaceSnapshot {
  double t = 0.0;
  double X = 0.0;  ///< the creep-weighted load X(t), in E0*
  CurveState state;  ///< the cell at X(t): areas, sites; its level_load is Q_L(X(t))
  /// The load each level carries at t, P_L(t) = int E(t - tau) dQ_L(X(tau)) (docs/model.md,
  /// section 14.1, eq P1), in R^2 E0* per cell; they sum to the nominal load pbar(t) Lx Ly.
  /// NaN where not computed (history_cost).
  std::vector<double> level_load;
  SurfaceValidity validity = SurfaceValidity::valid;
};

/// The texture under a load: each level's touch, each site's (cap's), and the snapshots.
struct SurfaceHistory {
  std::vector<LevelTouch> levels;
  /// Per site (the geometry's order): when its own tip touches, from its own touchdown load
  /// (LoadCurve::site_touchdown); a level's touch is its first site's.
  std::vector<LevelTouch> sites;
  std::vector<SurfaceSnapshot> snapshots;
};

/// Why the curve's reading `state` (at X = state.X, the load having started at X0) may not
/// be trusted: above_top, unloading (the pressure fell somewhere between X0 and X) or
/// below_resolution; valid otherwise. (history_cost is the loads' alone.)
SurfaceValidity reading_validity(const LoadCurve& curve, double X0, const CurveState& state);

/// Whether `curve` resolves level `level`'s touchdown: its X* is 0, at or above
/// the curve's X_resolved (below it the tallest spots span too few nodes), or the small-spot
/// limit's (LoadCurve::level_small_spot); +infinity (untouched by the curve's end) where the
/// curve reached full contact or ends at or above X_resolved.
bool touchdown_resolved(const LoadCurve& curve, std::size_t level);

/// Whether `curve` resolves site `site`'s touchdown: as its level's where it is the level's
/// first (the same load), else where it is 0, at or above X_resolved, or +infinity with
/// the curve ending at full contact or past X_resolved.
bool site_touchdown_resolved(const LoadCurve& curve, std::size_t site);

/// A level's touch under `load` from its touchdown load X* (model::classify), `resolved` as
/// its parts say.
LevelTouch level_touch(double X_star, bool resolved, const CreepWeightedLoad& load);

/// Each level's touch under `load`: from its touchdown load alone (no solve), what a sweep
/// over materials, temperatures and pressures needs per point.
std::vector<LevelTouch> level_touches(const LoadCurve& curve, const CreepWeightedLoad& load);

/// The same from the levels' touchdown loads X_star, each resolved as `resolved(level)` says:
/// the one loop of level_touches and GeometryParts::touches.
template <class Resolved>
std::vector<LevelTouch> level_touches(std::span<const double> X_star, const Resolved& resolved, const CreepWeightedLoad& load) {
  std::vector<LevelTouch> out;
  out.reserve(X_star.size());
  for (std::size_t level = 0; level < X_star.size(); ++level) out.push_back(level_touch(X_star[level], resolved(level), load));
  return out;
}

/// Reads `curve` along `load` at `times` (non-decreasing, >= 0; t = 0 is the state at 0+).
/// The loads: for each level L >= 1 that touches by the last time, LoadHistory (the point's
/// history quadrature, docs/model.md section 12.7) with Q2 = Q_L(X(tau)), Q1 the rest, from
/// its touch on; level 0 carries what the others leave.
SurfaceHistory surface_history(const LoadCurve& curve, const CreepWeightedLoad& load, std::span<const double> times,
                               const HistoryQuadrature& quadrature = {});


}  // namespace punchsweep::model
