#pragma once
/// @file
/// A periodic texture's cell, declared once (issue 38): a rectangular periodic cell and its
/// sites, each a punch of its own shape whose tip lies some depth below the tallest tip, the
/// sites grouped into levels (the sites that touch together). The boundary elements read a
/// cell from it (reference/periodic_grid.hpp: make_cell); the two-level square lattice of
/// the paper is one such geometry (two_level_square). Lengths in R.

#include <cstddef>
#include <string>
#include <vector>

#include "model/problem/contact_problem.hpp"
#include "model/problem/shape.hpp"

namespace punchsweep::model {

/// One punch of the cell: f(r) = C r^s / R^(s-1) about its tip at (x, y), the tip `drop`
/// below the tallest one.
struct Site {
  double x = 0.0;     ///< the tip's position in the cell, in R (0 <= x < Lx)
  double y = 0.0;     ///< likewise, 0 <= y < Ly
  Shape shape{};
  double drop = 0.0;  ///< how far the tip lies below the tallest tip, in R (>= 0)
  int level = 0;      ///< the level it belongs to: 0 the tallest, then 1, 2, ...
};

/// The periodic cell: Lx x Ly, repeated in x and y, and its sites.
struct CellGeometry {
  double Lx = 1.0;  ///< in R
  double Ly = 1.0;  ///< in R
  std::vector<Site> sites;

  /// The number of levels: one more than the highest site's level (0 without sites).
  int levels() const;
};

/// Empty when the geometry is usable: Lx, Ly finite and > 0; at least one site; each
/// site inside the cell, of a valid shape (s an integer in [1, 32], C > 0) and a finite
/// drop >= 0; the levels numbered 0 .. levels() - 1, each with a site. Else one sentence
/// naming the first bad field, its value and its valid range.
std::string geometry_error(const CellGeometry& geometry);

/// Whether the sites, as a set, are even in x and in y about the cell's corner (0, 0): each
/// site's mirror images (Lx - x, y) and (x, Ly - y), taken modulo the cell, are sites of the
/// same shape, drop and level (positions within 1e-12 of the cell). Such a cell's fields
/// are even, so the boundary elements may solve its quarter.
bool mirror_symmetric(const CellGeometry& geometry);

/// The lattices a texture's tallest sites may sit on.
enum class LatticeKind {
  /// Pitch l: the l x l cell with the tallest site at its corner; level 1 at the square's
  /// centre (l/2, l/2) (the paper's lattice), level 2 at the edges' midpoints (l/2, 0) and
  /// (0, l/2).
  square,
  /// Pitch l, the densest packing: the l x l sqrt(3) cell with the tallest sites at (0, 0)
  /// and (l/2, l sqrt(3)/2); level 1 at the centres of the triangles between them (two per
  /// tallest site); with a level 2, level 1 the centres of the upward triangles and level 2
  /// those of the downward ones.
  hexagonal,
};

/// "square" or "hexagonal".
std::string lattice_name(LatticeKind lattice);

/// A lattice of punches of one shape: the tallest at the lattice's sites, then one level
/// per entry of `drops` (at most 2; each its depth below the tallest tip, in R) at the
/// places Lattice names.
CellGeometry lattice_cell(LatticeKind lattice, double l, const Shape& shape, const std::vector<double>& drops);

/// How the heights of a supercell's sites scatter about their lattice's.
struct HeightScatter {
  enum class Kind { none, normal, uniform, list };
  Kind kind = Kind::none;
  double width = 0.0;          ///< normal: the standard deviation; uniform: the half-width (in R, >= 0)
  std::vector<double> values;  ///< list: one height change per site of the supercell, in R
  unsigned long long seed = 1;
};

/// The draws of `scatter` for `count` sites, in R: normal by Box-Muller and uniform on
/// [-width, width], both from std::mt19937_64 seeded with `seed` (the engine's sequence is fixed by
/// the C++ standard); list: its values (std::invalid_argument unless there are `count`).
std::vector<double> scatter_draws(const HeightScatter& scatter, std::size_t count);

/// K x K copies of `cell` as one periodic cell (K >= 1), each copy's site raised by the
/// next draw of `scatter` (a draw > 0 lowers the tip: it adds to the drop), the drops then
/// taken from the tallest tip of all (the least drop becomes 0). The sites keep their
/// levels; the copies of site k follow each other row by row.
CellGeometry supercell(const CellGeometry& cell, int K, const HeightScatter& scatter);

/// The two-level square lattice of `problem` (docs/model.md, section 3): the l x l cell, the
/// level-1 punch at its corner (0, 0), the level-2 punch, lower by dh, at its centre
/// (l/2, l/2), both of the problem's shape.
CellGeometry two_level_square(const ContactProblem& problem);

}  // namespace punchsweep::model
