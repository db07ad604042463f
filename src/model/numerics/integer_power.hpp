#pragma once

namespace punchsweep::model {

/// x^n for an integer n by repeated squaring: the shape exponent s is an integer, and
/// std::pow(double, int) goes through the general real power (several times slower on the
/// sweep's hot path).
inline double ipow(double x, int n) {
  if (n < 0) return 1.0 / ipow(x, -n);
  double result = 1.0;
  while (n > 0) {
    if (n & 1) result *= x;
    x *= x;
    n >>= 1;
  }
  return result;
}

}  // namespace punchsweep::model
