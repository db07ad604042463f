#pragma once

#include <cmath>

namespace punchsweep::model {

/// Outcome of a scalar root search.
struct RootResult {
  double x = 0.0;
  bool converged = false;
  int iterations = 0;
};

/// Safeguarded Newton (Numerical Recipes' rtsafe idea): Newton steps from `guess`, falling
/// back to bisection whenever a step leaves the bracket [lo, hi] or fails to halve the
/// bracket. `f(x, &dfdx)` returns f; f(lo) < 0 < f(hi) is the caller's promise (f increasing).
/// Stops when the step, or the bracket, is below `x_tol` + `relative_tol` |x| or after
/// `max_iterations` (a relative tolerance serves roots whose size is not known beforehand).
template <class F>
RootResult newton_bisect_increasing(F&& f, double lo, double hi, double guess, double x_tol,
                                    int max_iterations = 100, double relative_tol = 0.0) {
  double x = (guess > lo && guess < hi) ? guess : 0.5 * (lo + hi);
  double dx_old = hi - lo;
  double dx = dx_old;
  RootResult result;
  for (int it = 1; it <= max_iterations; ++it) {
    double df = 0.0;
    const double fx = f(x, &df);
    result.iterations = it;
    if (fx == 0.0) {
      result.x = x;
      result.converged = true;
      return result;
    }
    if (fx < 0.0) lo = x; else hi = x;
    const double newton = x - fx / df;
    const bool newton_ok = df > 0.0 && newton > lo && newton < hi && std::abs(2.0 * fx) < std::abs(dx_old * df);
    dx_old = dx;
    if (newton_ok) {
      dx = fx / df;
      x = newton;
    } else {
      dx = 0.5 * (hi - lo);
      x = lo + dx;
    }
    const double tol = x_tol + relative_tol * std::abs(x);
    if (std::abs(dx) <= tol || hi - lo <= tol) {
      result.x = x;
      result.converged = true;
      return result;
    }
  }
  result.x = x;
  return result;
}

}  // namespace punchsweep::model
