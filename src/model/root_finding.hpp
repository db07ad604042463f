#pragma once

#include <cmath>
#include <utility>

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

/// Plain bisection for where a predicate stops holding: `below(x)` holds on [lo, x_root)
/// and fails on (x_root, hi]. Halves the bracket until hi - lo <= relative_tol hi, or for
/// at most max_iterations; returns the final bracket (lo, hi).
template <class Below>
std::pair<double, double> bisect_boundary(Below&& below, double lo, double hi, double relative_tol,
                                          int max_iterations = 1100) {
  for (int i = 0; i < max_iterations && hi - lo > relative_tol * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (below(mid) ? lo : hi) = mid;
  }
  return {lo, hi};
}

}  // namespace punchsweep::model
