#pragma once
/// @file
/// The elastic state of a periodic cell of any geometry (model::CellGeometry, on the grid
/// of make_cell) under a mean pressure, and each level's touchdown: the first piece of the
/// elastic load curve of a geometry (issue 38). Units: lengths in R, pressures in E0* (the
/// elastic modulus E* = 1: a creep-weighted load X reads as the pressure).

#include <limits>
#include <vector>

#include "model/problem/cell_geometry.hpp"
#include "reference/contact_solver.hpp"
#include "reference/periodic_grid.hpp"

namespace punchsweep::reference {

/// The cell under mean pressure X: each level's load (the pressure over its share of the
/// cell, level 0's what the others leave), and h_L = u(tip of site 0) - u(tip of level L's
/// first site), the displacement difference that closes level L's gap: L touches where it
/// reaches that site's drop (its tip the level's lowest point; the tall tip carries load).
struct CellState {
  double X = 0.0;
  std::vector<double> level_load;  ///< per level, in R^2 E0*; they sum to X Lx Ly
  std::vector<double> h;           ///< per level (0 for level 0), in R
  ContactStatus status;
};

/// Solves the cell at X, from the uniform pressure.
CellState cell_state(const model::CellGeometry& geometry, const Cell& cell, ContactSolver& solver, double X);

/// Each level's touchdown load X*_L: the X at which h_L reaches the drop of its first site
/// (within 1e-9 of it: once touched h_L stays there, to the solve's tolerance), by bisection
/// in log X (h_L grows with X) to a relative `tolerance`, between 1e-12 and `X_max`, each
/// solve from the uniform pressure (a warm start across the bisection's jumps in X failed
/// to converge); +infinity where the level has not touched by X_max; 0 for level 0.
std::vector<double> level_touchdowns(const model::CellGeometry& geometry, const Cell& cell, double X_max,
                                     double tolerance = 1e-6);

}  // namespace punchsweep::reference
