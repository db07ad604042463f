#pragma once

#include <cmath>
#include <numbers>

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

}  // namespace punchsweep::model
