#pragma once

#include <cmath>
#include <numbers>
#include <vector>

namespace punchsweep::model {

/// Chebyshev interpolation on an interval, for the tables that stand in for costly smooth
/// functions (shell_sums.hpp). Nodes of the first kind, x_j = cos(pi (j + 1/2) / n) on
/// [-1, 1]; the interpolant sum_k c_k T_k is evaluated by Clenshaw's recurrence.
namespace chebyshev {

/// The n nodes mapped onto [lo, hi], in the order of j.
inline std::vector<double> nodes(int n, double lo, double hi) {
  std::vector<double> x(n);
  for (int j = 0; j < n; ++j) {
    x[j] = 0.5 * (lo + hi) + 0.5 * (hi - lo) * std::cos(std::numbers::pi * (j + 0.5) / n);
  }
  return x;
}

/// Coefficients c_0..c_(n-1) of the interpolant through values f(x_j) at nodes(n, ...),
/// read with stride `stride` from `values` (c_0 already halved).
inline std::vector<double> coefficients(const double* values, int n, int stride = 1) {
  std::vector<double> c(n, 0.0);
  for (int k = 0; k < n; ++k) {
    double sum = 0.0;
    for (int j = 0; j < n; ++j) sum += values[j * stride] * std::cos(std::numbers::pi * k * (j + 0.5) / n);
    c[k] = (k == 0 ? 1.0 : 2.0) * sum / n;
  }
  return c;
}

/// sum_k c_k T_k(u) at u in [-1, 1], coefficients read with stride `stride`.
inline double clenshaw(const double* c, int n, double u, int stride = 1) {
  double b1 = 0.0;
  double b2 = 0.0;
  const double two_u = 2.0 * u;
  for (int k = n - 1; k >= 1; --k) {
    const double b0 = two_u * b1 - b2 + c[k * stride];
    b2 = b1;
    b1 = b0;
  }
  return u * b1 - b2 + c[0];
}

/// T_0(u) .. T_(n-1)(u) into T (n >= 1), by T_(k+1) = 2u T_k - T_(k-1).
inline void polynomials(double u, int n, double* T) {
  T[0] = 1.0;
  if (n > 1) T[1] = u;
  for (int k = 2; k < n; ++k) T[k] = 2.0 * u * T[k - 1] - T[k - 2];
}

/// [lo, hi] -> [-1, 1].
inline double unit(double x, double lo, double hi) { return (2.0 * x - lo - hi) / (hi - lo); }

}  // namespace chebyshev
}  // namespace punchsweep::model
