#pragma once
/// @file
/// A periodic texture's cell, declared once (issue 38): a rectangular periodic cell and its
/// sites, each a punch of its own shape whose tip lies some depth below the tallest tip, the
/// sites grouped into levels (the sites that touch together). The boundary elements read a
/// cell from it (reference/periodic_grid.hpp: make_cell); the two-level square lattice of
/// the paper is one such geometry (two_level_square). Lengths in R.

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

/// The two-level square lattice of `problem` (docs/model.md, section 3): the l x l cell, the
/// level-1 punch at its corner (0, 0), the level-2 punch, lower by dh, at its centre
/// (l/2, l/2), both of the problem's shape.
CellGeometry two_level_square(const ContactProblem& problem);

}  // namespace punchsweep::model
