#pragma once
/// @file
/// The periodic grid of the boundary-element reference solver and the surface profiles on
/// it. Units as in model/units.hpp: lengths in R (pressures in E0*, time in T_eps).

#include <cstddef>
#include <string>
#include <vector>

#include "model/contact_problem.hpp"
#include "model/shape.hpp"

namespace punchsweep::reference {

/// A periodic nx x ny grid of collocation nodes on the Lx x Ly cell. Node (i, j) sits at
/// (i hx, j hy) and is stored row-major at index i ny + j. A node stands for the hx x hy
/// cell centred on it (pressure piecewise constant, contact area = nodes x cell area).
struct PeriodicGrid {
  int nx = 0;
  int ny = 0;
  double Lx = 1.0;  ///< cell length along x, in R
  double Ly = 1.0;  ///< cell length along y, in R

  /// The n x n grid of a length x length square cell.
  static PeriodicGrid square(int n, double length) { return {n, n, length, length}; }

  double hx() const { return Lx / nx; }
  double hy() const { return Ly / ny; }
  double cell_area() const { return hx() * hy(); }
  std::size_t size() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(ny) + static_cast<std::size_t>(j);
  }
  double x(int i) const { return i * hx(); }
  double y(int j) const { return j * hy(); }
};

/// Empty when the grid is usable (nx, ny >= 1, finite positive lengths), else a sentence
/// naming the bad field and its range.
std::string grid_error(const PeriodicGrid& grid);

/// d wrapped into [-L/2, L/2]: the offset to the nearest periodic image.
double periodic_offset(double d, double L);

/// Profile of one punch centred at (cx, cy), f(r) = C r^s / R^(s-1) with R = 1 (docs/model.md,
/// section 2), r the distance to the nearest periodic image of the centre.
std::vector<double> punch_profile(const PeriodicGrid& grid, const model::Shape& shape, double cx,
                                  double cy);

/// The periodic unit cell of the two-level square lattice (docs/model.md, section 3): the
/// l x l square with the level-1 punch at the corners (0, 0) and the level-2 punch, lower by
/// dh, at the centre (l/2, l/2).
struct TwoLevelCell {
  PeriodicGrid grid;
  /// Initial separation at zero approach, min(f(r1), f(r2) + dh), in R.
  std::vector<double> profile;
  /// Share of each node in the level-2 punch: 1 where the level-2 surface f(r2) + dh is the
  /// lower of the two, 0 where the level-1 one is, 1/2 on ties (within
  /// kProfileTieTolerance). Loads and areas of a level are sums over its share; this is
  /// not the equidistant (Voronoi) split, which a taller level-1 spot crosses.
  std::vector<double> level2_weight;
  std::size_t tip1 = 0;  ///< node of the level-1 tip O = (0, 0)
  std::size_t tip2 = 0;  ///< node of the level-2 tip M = (l/2, l/2)
};

/// Relative difference under which the two punch surfaces count as tied at a node.
inline constexpr double kProfileTieTolerance = 1e-12;

/// Smallest grid of a two-level cell, and its parity: both tips must be nodes.
inline constexpr int kMinTwoLevelNodes = 4;

/// Empty when n is usable for a two-level cell (even, >= kMinTwoLevelNodes), else a sentence.
std::string two_level_grid_error(int n);

/// The two-level cell of `problem` on an n x n grid (n even, so both tips are nodes; the
/// problem must satisfy model::problem_error() == "").
TwoLevelCell make_two_level_cell(const model::ContactProblem& problem, int n);

}  // namespace punchsweep::reference
