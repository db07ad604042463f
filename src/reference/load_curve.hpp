#pragma once
/// @file
/// The elastic load curve of a periodic texture (model::LoadCurve; docs/model.md, section
/// 17) by the boundary elements: the contact solve of the cell (make_cell) continued in load
/// from the first resolved contact to full contact or a stated top, each solve started from
/// the last one's pressure, with samples added where the levels' areas and loads bend and at
/// every site's touchdown. Units: lengths in R, loads X in E0* (unit compliance).

#include <functional>
#include <limits>

#include "model/numerics/stop_request.hpp"
#include "model/problem/cell_geometry.hpp"
#include "model/surface/load_curve.hpp"
#include "reference/contact_solver.hpp"
#include "reference/periodic_grid.hpp"

namespace punchsweep::reference {

/// The curve's numerical choices.
struct LoadCurveOptions {
  /// Stop here if full contact has not come before (E0*); the curve then ends at X_top.
  double X_top = std::numeric_limits<double>::infinity();
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
  /// Called after every contact solve with the number done so far and the load reached.
  std::function<void(int solves, double X)> progress;
};

/// The load curve of `geometry` on the grid of `cell` (make_cell(geometry, grid)). Throws
/// std::invalid_argument for a bad option, std::runtime_error where a contact solve misses
/// its tolerance from both the last pressure and the uniform one, model::Stopped on a stop
/// request.
model::LoadCurve build_load_curve(const model::CellGeometry& geometry, const Cell& cell,
                                  const LoadCurveOptions& options = {});

}  // namespace punchsweep::reference
