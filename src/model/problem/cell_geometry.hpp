#pragma once
/// @file
/// A periodic texture's cell, declared once (issue 38): a rectangular periodic cell and its
/// sites, each a punch of its own shape whose tip lies some depth below the tallest tip, the
/// sites grouped into levels (the sites that touch together). The boundary elements read a
/// cell from it (reference/periodic_grid.hpp: make_cell); the two-level square lattice of
/// the paper is one such geometry (two_level_square). Lengths in R.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
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

/// The texture's surface, the lowest of the sites' f(r) + drop (r to the nearest periodic
/// image of the tip), found from the sites near a point alone. Every point of the cell lies
/// within the covering radius rho of some site (bounded from a coarse scan of the cell), so
/// the surface is nowhere above top = max_k (C_k rho^s_k + drop_k); a site can be the lowest
/// only within its reach, where C r^s + drop <= top. Sites are kept in square buckets of
/// about the mean spacing, and a query reads the buckets within the longest reach: the cost
/// of a point is that of its neighbourhood, not of the cell's site count.
class SurfaceLocator {
 public:
  explicit SurfaceLocator(const CellGeometry& geometry);

  /// The lowest f(r) + drop at (x, y) among the sites k with accept(k) (in R), and that
  /// site; +infinity and sites() where no accepted site reaches the point (then every
  /// accepted site's surface there lies above the texture's).
  template <class Accept>
  std::pair<double, std::size_t> lowest(double x, double y, const Accept& accept) const {
    std::pair<double, std::size_t> best{std::numeric_limits<double>::infinity(), geometry_.sites.size()};
    visit(x, y, [&](std::size_t k, double r) {
      if (r > reach_[k] || !accept(k)) return;
      const double f = surface(k, r);
      if (f < best.first) best = {f, k};
    });
    return best;
  }
  /// Site k's f(r) + drop at distance r from its tip.
  double surface(std::size_t k, double r) const;
  /// How far from its tip site k can be the lowest surface (the window a grid pass visits).
  double reach(std::size_t k) const { return reach_[k]; }
  /// The bound of the surface over the cell (above every point's lowest surface).
  double top() const { return top_; }
  /// The distance from (x, y) to the tip of site k (to its nearest periodic image).
  double distance(double x, double y, std::size_t k) const;

 private:
  template <class Visit>
  void visit(double x, double y, const Visit& f) const;
  std::size_t bucket_of(double x, double y) const;

  const CellGeometry& geometry_;
  int bx_ = 1, by_ = 1;        ///< buckets along x and y
  double wx_ = 1.0, wy_ = 1.0; ///< their widths, in R
  int span_x_ = 0, span_y_ = 0;  ///< buckets read each side of a query's own
  std::vector<std::vector<std::size_t>> buckets_;
  std::vector<double> reach_;
  double top_ = 0.0;
};

template <class Visit>
void SurfaceLocator::visit(double x, double y, const Visit& f) const {
  const std::size_t home = bucket_of(x, y);
  const int hi = static_cast<int>(home / static_cast<std::size_t>(by_)), hj = static_cast<int>(home % static_cast<std::size_t>(by_));
  // Each bucket once, even where the span wraps past the cell.
  const int nx = std::min(2 * span_x_ + 1, bx_), ny = std::min(2 * span_y_ + 1, by_);
  for (int a = 0; a < nx; ++a) {
    const int i = ((hi - std::min(span_x_, (bx_ - 1) / 2) + a) % bx_ + bx_) % bx_;
    for (int b = 0; b < ny; ++b) {
      const int j = ((hj - std::min(span_y_, (by_ - 1) / 2) + b) % by_ + by_) % by_;
      for (const std::size_t k : buckets_[static_cast<std::size_t>(i) * static_cast<std::size_t>(by_) + static_cast<std::size_t>(j)]) {
        f(k, distance(x, y, k));
      }
    }
  }
}

/// The first site whose tip is not on the texture's surface (or sites.size() where every
/// tip is): a site that lies under another's surface at its tip or on it (f(r) + drop at
/// most its own drop, ties within a relative 1e-12) or shares an earlier site's tip (within
/// 1e-12 of the cell). Such a site never touches as a punch of its own; `by` receives the site that
/// covers it.
std::size_t covered_site(const CellGeometry& geometry, const SurfaceLocator& surface, std::size_t* by = nullptr);

/// Whether site k's tip is on the texture's surface (covered_site's test for one site).
bool tip_exposed(const CellGeometry& geometry, const SurfaceLocator& surface, std::size_t k, std::size_t* by = nullptr);

/// The deepest drop of level `level`'s tallest site at which each of the level's tips still
/// lies on the texture's surface, the level moving as one (each of its sites keeping its
/// offset below the level's tallest): the least, over the level's tips, of the other sites'
/// surfaces there (each to its nearest image; the level's own sites left out) less the tip's
/// offset. +infinity where the level has no site or no other site reaches its tips.
double deepest_exposed_drop(const CellGeometry& geometry, int level);

/// Whether the sites, as a set, are even in x and in y about the cell's corner (0, 0): each
/// site's mirror images (Lx - x, y) and (x, Ly - y), taken modulo the cell, are sites of the
/// same shape, drop and level (positions within 1e-12 of the cell). Such a cell's fields
/// are even, so the boundary elements may solve its quarter.
bool mirror_symmetric(const CellGeometry& geometry);
/// Whether the sites are even in x alone (each site's image (Lx - x, y) a site of the same
/// shape, drop and level): the boundary elements may then solve its half 0 <= x <= Lx/2. The
/// hexagonal lattice of three levels is (its levels alternate along y, so not even in y).
bool mirror_symmetric_x(const CellGeometry& geometry);

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

/// How the heights of a supercell's sites scatter about their lattice's (or, as a pure
/// number, their shapes' C: supercell's `curvature`).
struct HeightScatter {
  enum class Kind { none, normal, uniform, list };
  Kind kind = Kind::none;
  double width = 0.0;          ///< normal: the standard deviation; uniform: the half-width (in R, >= 0)
  std::vector<double> values;  ///< list: one height change per site of the supercell, in R
  unsigned long long seed = 1;
};

/// Whether `scatter` draws at random (normal or uniform), as a seed, an ensemble of seeds
/// and the tallest of many caps ask; a list or none does not.
bool drawn_at_random(const HeightScatter& scatter);

/// The draws of `scatter` for `count` sites, in R: normal by Box-Muller and uniform on
/// [-width, width], both from std::mt19937_64 seeded with `seed` (the engine's sequence is fixed by
/// the C++ standard); list: its values (std::invalid_argument unless there are `count`).
std::vector<double> scatter_draws(const HeightScatter& scatter, std::size_t count);

/// The `q` quantile (0 < q < 1) of how far the tallest tip of a part lies above the tall
/// caps' design height, where the part holds `counts[L]` caps of each level L (design drop
/// `drops[L]`, R) and each cap's height changes by an independent draw of `scatter` (normal
/// or uniform): the rise x with prod_L F(x + drops[L])^counts[L] = q, F the draws' CDF
/// (symmetric: a draw raises as often as it lowers). Solved by bisection to 1e-12 of the
/// scatter's width. Throws std::invalid_argument for a scatter not drawn at random, a width
/// of 0 or q outside (0, 1).
double tallest_rise_quantile(const HeightScatter& scatter, const std::vector<double>& drops, const std::vector<double>& counts,
                             double q);

/// K x K copies of `cell` as one periodic cell (K >= 1), each copy's site raised by the
/// next draw of `scatter` (a draw > 0 lowers the tip: it adds to the drop), the drops then
/// taken from the tallest tip of all (the least drop becomes 0), and its shape's C changed
/// by the next draw d of `curvature` to C (1 + d) (a relative change: a paraboloid's tip
/// radius 1 / (2C) over 1 + d). Where both draw at random, the curvature's draws follow the
/// heights' from one generator, seeded with the heights' seed (so the heights are the same
/// with or without them); alone, from the curvature's own seed. The sites keep their
/// levels; the copies of site k follow each other row by row. Throws std::invalid_argument
/// where a draw leaves C <= 0 (naming the cap). `rise` (where given) receives how far the
/// tallest tip drawn, from which the drops are taken, lies above the tallest tips' design
/// height (the least drop of `cell`): the scatter's extreme, which grows with K.
CellGeometry supercell(const CellGeometry& cell, int K, const HeightScatter& scatter, const HeightScatter& curvature = {},
                       double* rise = nullptr);

/// The two-level square lattice of `problem` (docs/model.md, section 3): the l x l cell, the
/// level-1 punch at its corner (0, 0), the level-2 punch, lower by dh, at its centre
/// (l/2, l/2), both of the problem's shape.
CellGeometry two_level_square(const ContactProblem& problem);

}  // namespace punchsweep::model
