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
#include "model/surface/load_curve.hpp"
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
  int solves = 0;        ///< contact solves made for it
  /// at(X, caps): the caps in contact fell as the drop grew at every trial (always for the
  /// level's own caps; see at()); counting() another level's: rose.
  bool steady = true;
  /// counting() another level's caps: `drop` is the least at which they have touched (at
  /// least the caps asked), not the most.
  bool rising = false;
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

  /// The drop of the level's tallest cap at which `caps` of the level's caps (1 to their
  /// number; of every cap of the cell with `every_level`) have touched at load X (a share of
  /// a scattered level's caps, where the first of the level's is at(X)). Past the first cap
  /// the state depends on the drop (the caps in contact carry load), so it is found by
  /// bisection over the drop, one contact solve of the cell a trial (each started from the
  /// last trial's pressure), to kDropTolerance of the deepest drop: fewer than `caps` touch
  /// at a deeper level, at least `caps` at a shallower one (the level's own caps are pressed
  /// the harder the higher it lies; with `every_level` the other levels' the less, so the
  /// count need not fall steadily: `steady` says whether every trial's count did).
  /// -infinity where fewer than `caps` touch even at drop 0 (the level's tallest cap as tall
  /// as the cell's tallest tip); every_drop where they touch at the deepest. Throws
  /// std::invalid_argument for `caps` outside 1 to the caps counted.
  LevelClosed at(double X, std::size_t caps, bool every_level = false);

  /// at(X, caps) counting the caps of `level`: this level's (as at()), every cap of the
  /// cell (kEveryLevel, as at()'s every_level) or another level's. Another level's caps
  /// touch the sooner the deeper this level lies (it carries less of the load): the answer
  /// is then `rising`, the least drop of this level's tallest cap at which `caps` of that
  /// level's have touched at load X, to kDropTolerance of the deepest drop, by the same
  /// aimed bisection: -infinity where they have with this level's tallest cap at the top (so
  /// at every drop), +infinity where they have not even at its deepest; `steady` says whether the count rose steadily with the
  /// drop at every trial. Throws std::invalid_argument for a level the cell lacks or `caps`
  /// outside 1 to the caps counted.
  static constexpr int kEveryLevel = -1;
  LevelClosed counting(double X, std::size_t caps, int level);

  /// The cell's state at load X with the level's tallest cap at `drop` (0 to deepest(), the
  /// others at their offsets below it): each level's contact area and share of its caps
  /// touched (model::CurveState's level_area and level_sites_touched, as a load curve's
  /// sample gives them; level_load and the totals too), from one contact solve of the cell
  /// with the level at that drop, each node counted to the level whose surface is lowest at
  /// its centre. What the design's advisories read at an edge. Throws
  /// std::invalid_argument for a drop outside 0 to deepest() and std::runtime_error where
  /// the solve misses its tolerance.
  model::CurveState state(double X, double drop);

  /// How close a bisection brings at(X, caps) to the drop, relative to deepest().
  static constexpr double kDropTolerance = 1e-10;
  /// The level's number of caps.
  std::size_t caps() const { return caps_; }

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
  std::size_t caps_ = 0;
  std::vector<double> pressure_;  ///< the last trial's, a bisection's first guess
  /// For at(X, caps), made at its first call: the other levels' lowest surface at the nodes
  /// (with the level at its deepest, where their reach is the widest) and the level's with
  /// its tallest cap at drop 0 (where its reach is): the cell's profile with the level at
  /// drop d is their least, the level's raised by d.
  std::vector<double> others_, level_at_top_;
  std::vector<std::vector<double>> deep_;  ///< each level's lowest surface, the level at its deepest
  void prepare_moves();  ///< makes others_, level_at_top_ and deep_ once
};

}  // namespace punchsweep::reference
