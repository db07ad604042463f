#pragma once

#include <string>

namespace punchsweep::model {

/// Punch profile f(r) = C r^s / R^(s-1) (docs/model.md, section 2).
struct Shape {
  int s = 2;        ///< shape exponent, an integer in [kMinExponent, kMaxExponent]
  double C = 0.5;   ///< dimensionless shape constant, C > 0 (sphere: s = 2, C = 1/2)

  static constexpr int kMinExponent = 1;
  /// Beyond s = 32 the tip is so flat that a^s underflows near the small-contact limit
  /// and h(a1) stops being numerically monotone; the range is tested up to this bound.
  static constexpr int kMaxExponent = 32;
};


/// K_P(s, C): load of an isolated punch, P = K_P E* a^(s+1) (Sneddon; notes section 2).
double load_coefficient(const Shape& shape);

/// K_d(s, C): indentation depth of an isolated punch, d = K_d a^s (notes section 2).
double depth_coefficient(const Shape& shape);

}  // namespace punchsweep::model
