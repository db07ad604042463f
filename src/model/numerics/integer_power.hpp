#pragma once

#include <cmath>

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

/// x^(1/n) for x >= 0 and an integer n >= 1: the square and cube roots where they serve (a
/// point of a sweep or of classify takes two or three of these, and pow costs several times
/// a sqrt).
inline double iroot(double x, int n) {
  switch (n) {
    case 1: return x;
    case 2: return std::sqrt(x);
    case 3: return std::cbrt(x);
    case 4: return std::sqrt(std::sqrt(x));
    default: return std::pow(x, 1.0 / n);
  }
}

}  // namespace punchsweep::model
