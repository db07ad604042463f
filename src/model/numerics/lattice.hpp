#pragma once

#include <cmath>
#include <numbers>
#include <vector>

namespace punchsweep::model {

/// The square two-level lattice of pitch l (docs/model.md, sections 3 and 4): level-2
/// punches sit at the square centres, l2 = l/sqrt(2) from their level-1 neighbours.
struct Lattice {
  double l;

  double l2() const { return l / std::numbers::sqrt2; }
  /// Radius outside which the nominal pressure acts on a level-1 punch while only level 1
  /// touches (eq 9.3 with M = 5): A1 = sqrt(5/pi) l. Also A1 of the delayed two-level phase.
  double A1_single() const { return std::sqrt(5.0 / std::numbers::pi) * l; }
  /// Radius outside which nominal pressure acts around a square centre M (pi A^2 = 4 l^2):
  /// A = 2 l / sqrt(pi). Also A2 of the delayed two-level phase (eq 9.18).
  double A_single() const { return 2.0 * l / std::sqrt(std::numbers::pi); }
};

/// The far field of a square lattice at small spots (docs/model.md, section 14.7): with unit
/// loads at the sites of a square lattice of pitch 1 on a half-space of E* = 1, G(x) the
/// surface displacement of zero mean over the cell (the lattice of point loads and the
/// nominal pressure that balances it), the constant
///     Psi = lim_{x -> 0} [G(x) - 1/(pi |x|)] - G(M),        M = (1/2, 1/2) the square centre,
/// is what the rest of the lattice adds to a site's depth beyond the centre's displacement.
/// A punch of small spot under load P in a lattice of pitch l has h = K_d a^s + Psi P / l +
/// O(P a^2 / l^3), and two levels d1 - d2 = K_d (a1^s - a2^s) + Psi (Q1 - Q2) / l + ...
/// The lattice sum of 1/|x| over the sites, with the background, is 4 zeta(1/2) beta(1/2)
/// at a site (Glasser and Zucker, "Lattice sums", Theoretical Chemistry 5, 1980: the
/// analytic continuation of sum' (m^2 + n^2)^-s = 4 zeta(s) beta(s)); the centre is a site
/// of the lattice of pitch 1/sqrt(2) that the sites and centres form together, which gives
/// G(M) = (sqrt(2) - 1) times the site's. So Psi = 4 (2 - sqrt(2)) zeta(1/2) beta(1/2) / pi
/// = -0.72724969313843...; tests/model/lattice_test.cpp sums it by Ewald's method.
double lattice_far_field_constant();

/// Punches of one level of the lattice at one distance from a point.
struct DistanceShell {
  double distance = 0.0;  ///< in units of the pitch l
  int count = 0;          ///< punches at that distance
  int level = 1;          ///< 1: the sites (i, j) l; 2: the square centres ((i + 1/2), (j + 1/2)) l
};

/// The K nearest distance shells of the level-`level` sites about the point (cx, cy) l (on
/// the half-integer grid), nearest first, a site at the point itself left out. About a
/// level-1 punch, level 1: 4 at 1, 4 at sqrt(2), 4 at 2, 8 at sqrt(5), ...; about a square
/// centre (0.5, 0.5), level 1: 4 at sqrt(1/2), 8 at sqrt(5/2), ...
std::vector<DistanceShell> lattice_shells(double cx, double cy, int K, int level);

/// The neighbourhood a localization of the family keeps about a punch of `level`
/// (docs/model.md, section 11): the punches of either level within its D nearest distinct
/// distances, by distance. D = 2 is the paper's: about a level-1 punch four level-2 punches
/// at l/sqrt(2) and four level-1 punches at l, and the same about a level-2 punch. In the
/// single-level phase only the level-1 ones carry load.
std::vector<DistanceShell> kept_neighbours(int level, int D);

}  // namespace punchsweep::model
