#pragma once
/// @file
/// Fills model::PeriodicTable with the periodic boundary-element solution of the elastic
/// two-level cell (docs/model.md, section 14.3): l = 1, C = 1 and unit compliance, so the
/// solver's numbers are the scaled ones.

#include <functional>

#include "model/periodic/periodic_table.hpp"
#include "model/numerics/stop_request.hpp"
#include "reference/contact_solver.hpp"
#include "reference/periodic_grid.hpp"

namespace punchsweep::reference {

/// The samples and the grid. The defaults are the tables the engine uses (their accuracy:
/// docs/model.md, section 14.4).
struct PeriodicTableOptions {
  int n = 512;              ///< n x n grid on the cell (its quarter is solved)
  int single_samples = 97;  ///< single-level curve: samples in v = xi^(1/(s+1)), 0 included
  int deltas = 33;          ///< two-level surface: values of delta on [0, delta_top]
  int r_samples = 41;       ///< ... and of r on [0, 1] per delta
  /// delta_top as a share of 2^(-s/2), where the level-2 punch hides under level 1.
  double delta_top_share = model::PeriodicTable::kTopShare;
  ContactSolverOptions solver{};
  model::StopRequest stop{};
  /// Called after every contact solve with (solves done, solves planned).
  std::function<void(int, int)> progress;
};

/// The cell of the scaled problem (l = 1, C = 1, quarter stored) at height difference delta;
/// for the single level delta = 2, beyond any 2^(-s/2): the level-2 surface is never the
/// lower one.
TwoLevelCell scaled_cell(int s, double delta, int n);

/// Builds the tables of shape exponent s (1 <= s <= 32). Throws model::Stopped on a stop
/// request and std::runtime_error when a contact solve misses its tolerance.
model::PeriodicTable build_periodic_table(int s, const PeriodicTableOptions& options = {});

/// The elastic state of the scaled problem by direct solve (for tests and the builder):
/// single level (delta = +infinity) or two levels.
model::PeriodicState solve_scaled(int s, double xi, double delta, int n, const ContactSolverOptions& solver = {});

}  // namespace punchsweep::reference
