#pragma once
/// @file
/// The elastic load curve of a periodic texture (model::LoadCurve; docs/model.md, section
/// 17) by the boundary elements: the contact solve of the cell (make_cell) continued in load
/// from the first resolved contact to full contact or a stated top, each solve started from
/// the last one's pressure, with samples added where the levels' areas and loads bend and at
/// every site's touchdown. Units: lengths in R, loads X in E0* (unit compliance).

#include <functional>
#include <limits>
#include <vector>

#include "model/numerics/stop_request.hpp"
#include "model/problem/cell_geometry.hpp"
#include "model/surface/load_curve.hpp"
#include "reference/contact_solver.hpp"
#include "reference/periodic_grid.hpp"

namespace punchsweep::reference {

/// Where a curve's build stands, after each contact solve: the march in load runs from
/// X_start up to X_full (known before the first solve: full_contact_load), so the share of
/// that range (in log X) its front has passed is the share of the curve done.
struct LoadCurveProgress {
  int solves = 0;        ///< contact solves so far
  double X = 0.0;        ///< the load of the last solve (a bisection's may lie behind the front)
  double X_front = 0.0;  ///< the highest load solved so far, in E0*
  double X_start = 0.0;  ///< the march's first load
  double X_full = 0.0;   ///< where it ends: full contact (full_contact_load), or its top if less
  /// Full contact's load (full_contact_load) whether or not the march gets there: X_full is
  /// less where the curve stops at its top (LoadCurveOptions::X_top, X_reach's march end).
  double X_full_contact = 0.0;
  /// The share of the load range done, log(X_front / X_start) / log(X_full / X_start), in [0, 1].
  double fraction() const;
  /// The share of the whole curve's load range (to full contact) that this one's spans, in
  /// log X: 1 where it goes to full contact.
  double range_share() const;
};

/// The curve's numerical choices.
struct LoadCurveOptions {
  /// Stop here if full contact has not come before (E0*); the curve then ends at X_top.
  double X_top = std::numeric_limits<double>::infinity();
  /// The largest load the question reads (E0*): the march stops at its first sample at or
  /// past it (march_end), so the curve is the full curve's first samples, bit for bit, and
  /// every reading at or below X_reach is the full curve's (docs/model.md 17.3). A site not
  /// touched by then has site_touchdown +infinity: it never touches under a load that stays
  /// at or below X_reach. +infinity: to full contact.
  double X_reach = std::numeric_limits<double>::infinity();
  /// The first sample: where each of the tallest sites' spots, as an isolated punch's,
  /// covers this many nodes (a radius of 5.6 node spacings).
  int min_spot_nodes = 100;
  /// Where the curve starts to answer for the continuum (LoadCurve::X_resolved): spots of
  /// this many nodes (a radius of 12 spacings: there a lone cap's area is within 0.6% of
  /// Hertz's and t* within 2e-3 of the periodic model's; at 5.6 spacings areas were 2-4%
  /// off). Below it the curve is still the grid's own solution (what the time stepping on the
  /// same grid gives), but a snapshot is flagged below_resolution.
  int resolved_spot_nodes = 450;
  /// The march in load: samples per decade of X before refinement.
  int samples_per_decade = 4;
  /// Refinement: an interval is halved (in log X) until the interpolation of LoadCurve::at
  /// meets the solve at its middle, each level's area to area_tolerance of itself (plus half
  /// a node's area) and its load share Q_L / (X Lx Ly) to load_tolerance.
  double area_tolerance = 1e-3;
  double load_tolerance = 1e-4;
  /// At most this many halvings of one interval of the march.
  int max_refinements = 10;
  /// Each site's touchdown and full contact are found to this relative accuracy in X.
  double touchdown_tolerance = 1e-7;
  ContactSolverOptions solver{};
  model::StopRequest stop{};
  /// Called after every contact solve (LoadCurveProgress).
  std::function<void(const LoadCurveProgress&)> progress;
};

/// The load at which `cell` comes into full contact, from its profile alone: in full contact
/// the gap vanishes at every node, so the displacement is the profile's mean less the profile
/// and the pressure X + S(mean - profile) = X - S profile, S the half-space's stiffness (the
/// inverse of the influence operator on every mode but the mean); it is non-negative at every
/// node once X >= max S profile. The discrete problem's own full-contact load (the curve's
/// X_full, found by bisection to its touchdown_tolerance), from one transform pair.
double full_contact_load(const Cell& cell);

/// Where a curve whose march starts at X_first (its first sample) stops under `options`
/// short of full contact: its first march sample at or past X_reach, and at least the one
/// after X_first (the march's samples are X_first times step^k, step = 10^(1 /
/// samples_per_decade), each the last times step as the march computes it), or X_top if
/// less; X_top for an infinite X_reach. A cached curve cut here (model::LoadCurve::up_to) is
/// the curve built with these options.
double march_end(double X_first, const LoadCurveOptions& options);

/// The load (E0*) at which each of `geometry`'s tallest sites' spots, as an isolated punch's
/// sharing the cell's load with the others at their drop, covers `spot_nodes` nodes of
/// `grid`: a curve's first sample (LoadCurveOptions::min_spot_nodes) and its X_resolved
/// (resolved_spot_nodes) on that grid.
double spot_load(const model::CellGeometry& geometry, const PeriodicGrid& grid, int spot_nodes);

/// Where a curve's march stopped short of full contact: the pressure at its last sample
/// (the next solve's start) and each site's h there (its gap's closure). With it the march
/// goes on as if it had not stopped (extend_load_curve). Empty for a curve at full contact.
struct CurveFront {
  std::vector<double> p;  ///< the stored grid's pressure, in E0*
  std::vector<double> h;  ///< per site: u(tallest tip) - u(its tip), in R
};

/// The load curve of `geometry` on the grid of `cell` (make_cell(geometry, grid)); `front`,
/// where given, receives where it stopped. Throws std::invalid_argument for a bad option,
/// std::runtime_error where a contact solve misses its tolerance from both the last
/// pressure and the uniform one, model::Stopped on a stop request.
model::LoadCurve build_load_curve(const model::CellGeometry& geometry, const Cell& cell,
                                  const LoadCurveOptions& options = {}, CurveFront* front = nullptr);

/// `curve` (build_load_curve's on this cell with these options but a smaller reach, its
/// front `from`) continued to `options`' reach: the curve build_load_curve gives for it, bit
/// for bit (the march's samples, warm starts and touchdown bisections are the same), at the
/// cost of the part past the old end. std::invalid_argument where the curve or front is not
/// this cell's or the curve reached full contact.
model::LoadCurve extend_load_curve(const model::CellGeometry& geometry, const Cell& cell, model::LoadCurve curve,
                                   const CurveFront& from, const LoadCurveOptions& options = {}, CurveFront* front = nullptr);

}  // namespace punchsweep::reference
