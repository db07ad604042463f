#pragma once
/// @file
/// Ring-load and nominal-pressure identities of the localization method (docs/model.md,
/// section 3), for a punch of contact radius a. E* = 1 in our units, so loads and
/// "creep-scaled" loads Q = int J dP enter the same way.

#include <cmath>
#include <numbers>

namespace punchsweep::model {

/// Every ring quantity of one punch radius a against one ring radius rho > a (inv_rho =
/// 1 / rho, precomputed by the caller), sharing one square root (the Newton residuals
/// need all four).
struct Ring {
  /// w(a, rho): share of a ring load on radius rho that the punch carries,
  /// (2/pi)(a/sqrt(rho^2 - a^2) - arcsin(a/rho)).
  double share = 0.0;
  double share_rate = 0.0;  ///< (1/a) dw/da = (2/pi) a / (rho^2 - a^2)^(3/2); finite as a -> 0
  double depth = 0.0;       ///< 1/sqrt(rho^2 - a^2): depth added by a unit ring load at rho, times pi
  double depth_rate = 0.0;  ///< (1/a) d/da of depth = 1/(rho^2 - a^2)^(3/2)
};

inline Ring ring(double a, double rho, double inv_rho) {
  const double depth = 1.0 / std::sqrt(rho * rho - a * a);
  const double depth_rate = depth * depth * depth;
  return Ring{2.0 / std::numbers::pi * (a * depth - std::asin(a * inv_rho)), 2.0 / std::numbers::pi * a * depth_rate,
              depth, depth_rate};
}

// The nominal pressure outside radius A adds 2 p nominal_load_term(a, A) to the punch load,
// nominal_load_term(a, A) = A^2 arcsin(a/A) - a sqrt(A^2 - a^2), with (1/a) d/da = 2a/sqrt(A^2 - a^2);
// TwoLevelSystem::evaluate computes it inline with its own square roots.

}  // namespace punchsweep::model
