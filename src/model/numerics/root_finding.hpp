#pragma once

#include <algorithm>
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

/// Brent's method (van Wijngaarden-Dekker-Brent: inverse quadratic interpolation, secant
/// and bisection, as zeroin) for a root of a continuous f in [lo, hi], f(lo) <= 0 <= f(hi)
/// the caller's promise (fa, fb: those values). Superlinear where f is smooth, never slower
/// than bisection by much. Stops when the bracket is below x_tol + 4 eps |x|.
template <class F>
RootResult brent(F&& f, double lo, double hi, double f_lo, double f_hi, double x_tol, int max_iterations = 200) {
  constexpr double kEps = 0x1p-52;
  double a = lo, b = hi, c = hi;
  double fa = f_lo, fb = f_hi, fc = f_hi;
  double d = 0.0, e = 0.0;
  RootResult result;
  for (int it = 1; it <= max_iterations; ++it) {
    result.iterations = it;
    if ((fb > 0.0 && fc > 0.0) || (fb < 0.0 && fc < 0.0)) {
      c = a;
      fc = fa;
      e = d = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2.0 * kEps * std::abs(b) + 0.5 * x_tol;
    const double xm = 0.5 * (c - b);
    if (std::abs(xm) <= tol || fb == 0.0) {
      result.x = b;
      result.converged = true;
      return result;
    }
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      const double s = fb / fa;
      double p, q;
      if (a == c) {
        p = 2.0 * xm * s;
        q = 1.0 - s;
      } else {
        const double qa = fa / fc;
        const double r = fb / fc;
        p = s * (2.0 * xm * qa * (qa - r) - (b - a) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) q = -q;
      p = std::abs(p);
      if (2.0 * p < std::min(3.0 * xm * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = xm;
        e = d;
      }
    } else {
      d = xm;
      e = d;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : std::copysign(tol, xm);
    fb = f(b);
  }
  result.x = b;
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
