#pragma once
/// @file
/// The periodic grid of the boundary-element reference solver and the surface profiles on
/// it. Units as in model/numerics/units.hpp: lengths in R (pressures in E0*, time in T_eps).

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "model/problem/cell_geometry.hpp"
#include "model/problem/contact_problem.hpp"
#include "model/problem/shape.hpp"

namespace punchsweep::reference {

/// Which nodes of a periodic grid carry the fields.
enum class Symmetry {
  /// All nx x ny nodes.
  none,
  /// Fields even in x and in y about node (0, 0), hence also about (nx/2, ny/2): only the
  /// quarter 0 <= i <= nx/2, 0 <= j <= ny/2 is stored ((nx/2 + 1)(ny/2 + 1) nodes, nx and ny
  /// even). Node (i, j) stands for its mirror images: multiplicity() of them. The two-level
  /// cell is such a field (its punches sit at (0, 0) and (l/2, l/2)).
  mirror,
  /// Fields even in x alone, about node column i = 0 (hence about i = nx/2): only the half
  /// 0 <= i <= nx/2 is stored ((nx/2 + 1) ny nodes, nx even); node (i, j) stands for
  /// itself and its image across x = 0, multiplicity() 1 or 2. The hexagonal lattice of
  /// three levels is such a field (its levels alternate along y).
  mirror_x,
};

/// A periodic nx x ny grid of collocation nodes on the Lx x Ly cell. Node (i, j) sits at
/// (i hx, j hy) and is stored row-major at index i stored_ny() + j. A node stands for the
/// hx x hy cell centred on it (pressure piecewise constant, contact area = nodes x cell
/// area); under Symmetry::mirror for that cell and its mirror images.
struct PeriodicGrid {
  int nx = 0;
  int ny = 0;
  double Lx = 1.0;  ///< cell length along x, in R
  double Ly = 1.0;  ///< cell length along y, in R
  Symmetry symmetry = Symmetry::none;

  /// The n x n grid of a length x length square cell.
  static PeriodicGrid square(int n, double length, Symmetry symmetry = Symmetry::none) {
    return {n, n, length, length, symmetry};
  }

  double hx() const { return Lx / nx; }
  double hy() const { return Ly / ny; }
  double cell_area() const { return hx() * hy(); }
  bool mirrored() const { return symmetry == Symmetry::mirror; }  ///< the quarter stored
  bool mirrored_x() const { return symmetry != Symmetry::none; }  ///< even in x: half the rows stored
  bool mirrored_y() const { return symmetry == Symmetry::mirror; }  ///< even in y: half the columns stored
  int stored_nx() const { return mirrored_x() ? nx / 2 + 1 : nx; }  ///< rows i = 0 .. stored_nx() - 1
  int stored_ny() const { return mirrored_y() ? ny / 2 + 1 : ny; }  ///< columns j likewise
  /// Stored nodes: the length of every field on the grid.
  std::size_t size() const { return static_cast<std::size_t>(stored_nx()) * static_cast<std::size_t>(stored_ny()); }
  /// Nodes of the whole periodic cell, nx ny: what a mean over the cell divides by.
  std::size_t nodes() const { return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny); }
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(stored_ny()) + static_cast<std::size_t>(j);
  }
  double x(int i) const { return i * hx(); }
  double y(int j) const { return j * hy(); }
  /// How many nodes of the whole cell stored node `k` stands for: 1 without symmetry; under
  /// mirror 1, 2 or 4 (nodes on the lines i = 0, nx/2 or j = 0, ny/2 are their own images),
  /// under mirror_x 1 or 2. Sums over the cell are sums over the stored nodes weighted by it.
  double multiplicity(std::size_t k) const {
    if (!mirrored_x()) return 1.0;
    const int i = static_cast<int>(k / static_cast<std::size_t>(stored_ny()));
    const int j = static_cast<int>(k % static_cast<std::size_t>(stored_ny()));
    return ((i == 0 || 2 * i == nx) ? 1.0 : 2.0) * ((!mirrored_y() || j == 0 || 2 * j == ny) ? 1.0 : 2.0);
  }
};

/// Empty when the grid is usable (nx, ny >= 1, even under Symmetry::mirror, finite positive
/// lengths), else a sentence naming the bad field and its range.
std::string grid_error(const PeriodicGrid& grid);

/// d wrapped into [-L/2, L/2]: the offset to the nearest periodic image.
double periodic_offset(double d, double L);

/// Profile of one punch centred at (cx, cy), f(r) = C r^s / R^(s-1) with R = 1 (docs/model.md,
/// section 2), r the distance to the nearest periodic image of the centre.
/// On a mirrored grid the centre must be a mirror point, 0 or half the cell along each axis
/// (else std::invalid_argument: the profile would not be even).
std::vector<double> punch_profile(const PeriodicGrid& grid, const model::Shape& shape, double cx,
                                  double cy);

/// A periodic cell of any geometry (model::CellGeometry) on a grid of its Lx x Ly cell.
struct Cell {
  PeriodicGrid grid;
  /// Initial separation at zero approach: the lowest of the sites' surfaces f(r) + drop, in R.
  std::vector<double> profile;
  /// For each level from 1 on (level_weight[L - 1]): the share of each node's square in
  /// level L, the part of it where L's surface is the lowest of all (ties, within
  /// kProfileTieTolerance, count half). Level 0's share is what the others leave.
  std::vector<std::vector<double>> level_weight;
  /// For each level from 1 on: whether the node itself is that level's (its surface there
  /// the lowest, or tied).
  std::vector<std::vector<char>> level_node;
  std::vector<std::size_t> tips;  ///< per site, in the geometry's order: the node of its tip (or its image's)
  /// Per site: whether its tip is on the texture's surface (model::tip_exposed). A site
  /// under a taller cap, or hidden under the tall caps entirely, never touches as a punch of
  /// its own: its tip's node is pressed only when the taller cap's contact spreads over it.
  std::vector<char> tip_exposed;

  /// Whether site k has touched under pressure p: its tip is on the surface and its node
  /// carries pressure (the discrete contact's own test, the curve's and the time stepping's).
  bool touched(std::size_t k, std::span<const double> p) const { return tip_exposed[k] != 0 && p[tips[k]] > 0.0; }
};

/// The cell of `geometry` on `grid` (its cell must be the geometry's, model::geometry_error
/// empty, every tip a node, and under Symmetry::mirror the sites even in x and y,
/// model::mirror_symmetric, under mirror_x even in x; else std::invalid_argument naming
/// what is not). Under a mirror a tip outside the stored part is given as its image's node.
Cell make_cell(const model::CellGeometry& geometry, const PeriodicGrid& grid);

/// Each level's lowest surface f(r) + drop at the grid's stored nodes (+infinity where none
/// of its sites is the texture's lowest within its reach): make_cell's profile is their
/// least. For a caller that moves one level and keeps the rest (reference::LevelClosure).
/// Throws std::invalid_argument as make_cell does.
std::vector<std::vector<double>> level_surfaces(const model::CellGeometry& geometry, const PeriodicGrid& grid);

/// The most symmetry the sites of `geometry` allow a grid of its cell: mirror where they
/// are even in x and y, mirror_x where in x alone, else none.
Symmetry symmetry_of(const model::CellGeometry& geometry);

/// Whether FFTW transforms `n` points with its fast codelets: 2^a 3^b 5^c 7^d 11^e 13^f with
/// e + f at most 1 (FFTW's manual, "Complex DFTs"); a larger prime factor takes its generic
/// algorithms, several times slower.
bool fft_friendly(int n);

/// The grid of a lattice's cell (model::lattice_cell) with `n` nodes per pitch along x (n
/// even, >= kMinTwoLevelNodes; two_level_grid_error) and as many along y as keep the nodes
/// near square with every site's tip a node (the hexagonal cell: a multiple of 6, the
/// FFT-friendly one nearest n sqrt 3 within 3% where there is one: 216 for 128 rather than
/// 222 = 6 x 37, whose transforms took twice as long); its
/// quarter or half where the sites are even (symmetry_of).
/// A supercell of K x K lattice cells (model::supercell) takes K times the nodes each way.
PeriodicGrid lattice_grid(const model::CellGeometry& geometry, model::LatticeKind lattice, int n, int K = 1);

/// The grid of any cell with n nodes along x (n even) and, along y, the even number within
/// 10% of square nodes (n Ly / Lx) that puts the tips nearest to nodes (on them where one
/// does; the nearest to square among equals); its quarter or half where the sites are
/// even (symmetry_of).
PeriodicGrid cell_grid(const model::CellGeometry& geometry, int n);

/// `geometry` with every tip moved to its nearest node of `grid` (make_cell needs tips on
/// nodes); `moved` receives the longest move, in R (at most half a node's diagonal).
model::CellGeometry snap_tips(const model::CellGeometry& geometry, const PeriodicGrid& grid, double* moved);

/// The periodic unit cell of the two-level square lattice (docs/model.md, section 3): the
/// l x l square with the level-1 punch at the corners (0, 0) and the level-2 punch, lower by
/// dh, at the centre (l/2, l/2).
struct TwoLevelCell {
  PeriodicGrid grid;
  /// Initial separation at zero approach, min(f(r1), f(r2) + dh), in R.
  std::vector<double> profile;
  /// Share of each node's square in the level-2 punch: the part of it where the level-2
  /// surface f(r2) + dh is the lower of the two (ties, within kProfileTieTolerance, count
  /// half), so 1 or 0 away from where the surfaces cross and a fraction on that line. Loads
  /// and areas of a level are sums over its share, so a level's share of the cell converges
  /// as the line's length times hx hy, not node by node; this is not the equidistant
  /// (Voronoi) split, which a taller level-1 spot crosses.
  std::vector<double> level2_weight;
  /// Whether the node itself is level 2's: its level-2 surface is the lower one or tied.
  /// Level 2 has touched once such a node carries pressure.
  std::vector<char> level2_node;
  std::size_t tip1 = 0;  ///< node of the level-1 tip O = (0, 0)
  std::size_t tip2 = 0;  ///< node of the level-2 tip M = (l/2, l/2)
};

/// A level's share of the cell's area: the nodes' `weight` in it (Cell::level_weight),
/// each times its multiplicity, over the cell's nodes.
double level_share(const PeriodicGrid& grid, const std::vector<double>& weight);

/// The level-2 share of the two-level cell: level_share of its level2_weight.
double level2_share(const TwoLevelCell& cell);

/// Relative difference under which the two punch surfaces count as tied at a node.
inline constexpr double kProfileTieTolerance = 1e-12;

/// Smallest grid of a two-level cell, and its parity: both tips must be nodes.
inline constexpr int kMinTwoLevelNodes = 4;

/// Empty when n is usable for a two-level cell (even, >= kMinTwoLevelNodes), else a sentence.
std::string two_level_grid_error(int n);

/// The two-level cell of `problem` on an n x n grid (n even, so both tips are nodes; the
/// problem must satisfy model::problem_error() == ""), stored whole or, under
/// Symmetry::mirror, as its quarter [0, l/2]^2 (the same discrete problem, a quarter of the
/// unknowns).
TwoLevelCell make_two_level_cell(const model::ContactProblem& problem, int n,
                                 Symmetry symmetry = Symmetry::none);

}  // namespace punchsweep::reference
