#pragma once
/// @file
/// The drop at which a level of a periodic texture touches at a given load, the texture's
/// counterpart of model::dh_touching_at (docs/design.md, "Any texture"). Until a level's
/// first site touches, the cell's state does not depend on that level's drop: the other
/// levels carry the load X, and the depth by which its tip nodes rise towards the tallest
/// tip, h = u(tallest tip) - u(its tip), is the same whatever the drop below it. So the
/// level touches at load X exactly when its drop is the largest h of its sites at X: one
/// contact solve answers "which drop touches by time t" (X = X(t)), where a load curve per
/// trial drop would cost hundreds. A level whose caps lie at different drops (a scattered
/// supercell's, a cell file's) moves as one: each cap keeps its offset below the level's
/// tallest, and the drop is that tallest cap's. Lengths in R, loads in E0*.

#include <vector>

#include "model/problem/cell_geometry.hpp"
#include "reference/contact_solver.hpp"
#include "reference/periodic_grid.hpp"

namespace punchsweep::reference {

/// What one level's tips close at one load.
struct LevelClosed {
  /// The drop (below the cell's tallest tip, as the geometry's drops) of the level's tallest
  /// cap at which its first cap closes at the load, in R: a level this far down (or less)
  /// has touched by then.
  double drop = 0.0;
  /// The other levels' surfaces already press the level's tip at its deepest drop that
  /// still leaves it a punch of its own (`drop` is then that depth, the level's deepest):
  /// at the load it touches at any drop.
  bool every_drop = false;
  ContactStatus status;  ///< the solve's (status.converged: it met its tolerance)
};

/// One level of one geometry on one grid, solved at any load. The level's sites are set
/// just above the depth where the other levels' surfaces would hide them (so they stay
/// punches of their own and carry no pressure while the load leaves them untouched); the
/// rest of the geometry is as given. Each load is solved from the uniform pressure, so an
/// answer does not depend on the loads asked before it.
class LevelClosure {
 public:
  /// `level` >= 1 (level 0 is the tallest, the reference); `grid` a grid of the geometry's
  /// cell on which every tip is a node (lattice_grid, cell_grid; its quarter where the
  /// sites are even). Throws std::invalid_argument for a level without sites or a bad grid.
  LevelClosure(const model::CellGeometry& geometry, int level, const PeriodicGrid& grid, ContactSolverOptions solver = {});

  /// The level's closure at load X >= 0 (E0*); X = 0 closes nothing (drop 0). Throws
  /// std::runtime_error where the contact solve misses its tolerance.
  LevelClosed at(double X);

  /// The deepest drop of the level's tallest cap at which its caps are all still punches of
  /// their own (in R): past it the other levels' surfaces lie above one of its tips.
  double deepest() const { return deepest_; }
  const model::CellGeometry& geometry() const { return geometry_; }

 private:
  model::CellGeometry geometry_;  ///< the level at its deepest exposed drop
  Cell cell_;
  ContactSolver solver_;
  int level_;
  std::size_t reference_ = 0;  ///< a tallest site
  std::vector<double> offset_;  ///< each of the level's sites' drop below its tallest (0 elsewhere)
  double deepest_ = 0.0;
};

}  // namespace punchsweep::reference
