#pragma once
/// @file
/// Ring-load and nominal-pressure identities of the localization method (model notes,
/// section 3), for a punch of contact radius a. E* = 1 in our units, so loads and
/// "creep-scaled" loads Q = int J dP enter the same way.

#include <cmath>
#include <numbers>

namespace punchsweep::model {

/// w(a, rho): share of a ring load on radius rho > a that the punch carries,
/// (2/pi)(a/sqrt(rho^2 - a^2) - arcsin(a/rho)).
inline double ring_load_share(double a, double rho) {
  return 2.0 / std::numbers::pi * (a / std::sqrt(rho * rho - a * a) - std::asin(a / rho));
}

/// (1/a) dw/da = (2/pi) a / (rho^2 - a^2)^(3/2); finite as a -> 0.
inline double ring_load_share_rate_over_a(double a, double rho) {
  const double q = rho * rho - a * a;
  return 2.0 / std::numbers::pi * a / (q * std::sqrt(q));
}

/// 1/sqrt(rho^2 - a^2): depth added by a unit ring load at rho, times pi.
inline double ring_depth(double a, double rho) { return 1.0 / std::sqrt(rho * rho - a * a); }

/// (1/a) d/da of ring_depth = 1/(rho^2 - a^2)^(3/2).
inline double ring_depth_rate_over_a(double a, double rho) {
  const double q = rho * rho - a * a;
  return 1.0 / (q * std::sqrt(q));
}

/// Every ring quantity of one punch radius a against one ring radius rho > a (inv_rho =
/// 1 / rho, precomputed by the caller), sharing one square root (the Newton residuals
/// need all four).
struct Ring {
  double share = 0.0;       ///< ring_load_share(a, rho)
  double share_rate = 0.0;  ///< ring_load_share_rate_over_a(a, rho)
  double depth = 0.0;       ///< ring_depth(a, rho)
  double depth_rate = 0.0;  ///< ring_depth_rate_over_a(a, rho)
};

inline Ring ring(double a, double rho, double inv_rho) {
  const double depth = 1.0 / std::sqrt(rho * rho - a * a);
  const double depth_rate = depth * depth * depth;
  return Ring{2.0 / std::numbers::pi * (a * depth - std::asin(a * inv_rho)), 2.0 / std::numbers::pi * a * depth_rate,
              depth, depth_rate};
}

/// A^2 arcsin(a/A) - a sqrt(A^2 - a^2): the nominal pressure outside radius A adds
/// 2 p times this to the punch load.
inline double nominal_load_term(double a, double A) {
  return A * A * std::asin(a / A) - a * std::sqrt(A * A - a * a);
}

/// (1/a) d/da of nominal_load_term = 2 a / sqrt(A^2 - a^2).
inline double nominal_load_term_rate_over_a(double a, double A) {
  return 2.0 * a / std::sqrt(A * A - a * a);
}

}  // namespace punchsweep::model
