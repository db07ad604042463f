#pragma once

#include <vector>

#include "model/numerics/lattice.hpp"
#include "model/problem/localization.hpp"
#include "model/problem/shape.hpp"
#include "model/shells/shell_sums.hpp"

namespace punchsweep::model {

/// The single-level phase under a localization of the family of docs/model.md, section 11:
/// the level-1 punches of the kept neighbourhood of a punch (kept_neighbours: either level
/// within the D = localization.shells nearest distances; n_k at rho_k) and of the square
/// centre M (n_m at r_m), each as a point load or spread over its own spot, and the nominal
/// pressure X beyond A (pi A^2 = (1 + sum n_k) l^2) and A_M (pi A_M^2 = sum n_m l^2).
/// The same neighbourhoods as TwoLevelShells, so that the two join at touchdown. With
/// P = X l^2:
///   balance  P = K_P a^(s+1) + P sum_k n_k <w(a, .)>_k + 2X (A^2 asin(a/A) - a sqrt(A^2 - a^2))
///   h = K_d a^s + P sum_k n_k <1/(pi sqrt(.^2 - a^2))>_k - 2X sqrt(A^2 - a^2)
///       - (P sum_m n_m <1/(pi .)>_m - 2X A_M).
/// The paper's localization (D = 2, point loads) is SingleLevel's eqs 9.5/9.10, which
/// this reproduces to rounding; the engine's sweeps use SingleLevel. The same public face
/// as SingleLevel, for `punchsweep single-level --localization`.
/// Units: lengths in R, X in E0*, h in R.
class SingleLevelShells {
 public:
  SingleLevelShells(double l, Shape shape, Localization localization);

  /// X = pbar0 J at which the contact radius is a1 (the balance solved for X); +infinity
  /// at and beyond radius_limit().
  double creep_scaled_pressure(double a1) const;
  /// h at contact radius a1 and creep-scaled pressure X.
  double displacement_difference(double a1, double X) const;
  /// h along the solution curve.
  double displacement_difference(double a1) const;
  /// dh/da1 along the solution curve (Richardson-extrapolated central differences, to
  /// about 1e-10); NaN within 1e-3 a1 of radius_limit().
  double displacement_difference_rate(double a1) const;
  /// The contact radius at X (Brent's method to 1e-15 of radius_limit()), in (0, radius_limit()).
  double contact_radius(double X) const;
  /// The contact radius at which h(a1) = dh along the solution curve (Brent's method to
  /// 1e-15 of radius_limit(); h grows with a1); 0 for dh <= 0, radius_limit() where h stays
  /// below dh.
  double contact_radius_at_gap(double dh) const;
  /// Where the balance needs X -> infinity, or where spread neighbours count as merged with
  /// the spot (a = Localization::kMergeMargin l/2), whichever is first.
  double radius_limit() const { return a_limit_; }

 private:
  /// The neighbours' sums at contact radius a, per unit load P: carried share, depth and
  /// centre displacement kernels (1/length).
  struct Sums {
    double carried = 0.0;
    double depth = 0.0;
    double centre = 0.0;
  };
  Sums sums(double a) const;
  /// The balance's denominator: l^2 (1 - carried) - 2 (A^2 asin(a/A) - a sqrt(A^2 - a^2)).
  double capacity(double a, const Sums& s) const;

  double l_;
  Shape shape_;
  double K_P_;
  double K_d_;
  const ShellSums* sums_;  ///< the kept neighbourhoods' sums (shared, scaled by l)
  double A_;               ///< A, about the punch
  double A_M_;
  double a_limit_ = 0.0;
};

}  // namespace punchsweep::model
