#pragma once
/// @file
/// Cubic interpolation on uniform grids: where a value falls, and the Lagrange cubic through
/// the four samples about it (the periodic model's tables read every field this way).

#include <algorithm>
#include <cmath>

namespace punchsweep::model {

/// Where x falls on the uniform grid lo + i step, i = 0 .. count - 1: the interval i (clamped
/// to [0, count - 2]) and the offset u in it (not clamped: u < 0 or > 1 past the ends).
struct GridPosition {
  int i = 0;
  double u = 0.0;
};
inline GridPosition locate(double x, double lo, double hi, int count) {
  const double step = (hi - lo) / (count - 1);
  const double f = (x - lo) / step;
  int i = static_cast<int>(std::floor(f));
  i = std::clamp(i, 0, count - 2);
  return {i, f - i};
}

/// A uniform grid lo + i step, i = 0 .. count - 1, its step computed once: locate() with
/// the same numbers, bit for bit, at one division where locate takes two.
struct UniformGrid {
  double lo = 0.0, step = 1.0;
  int count = 2;
  UniformGrid() = default;
  UniformGrid(double lo_, double hi, int count_) : lo(lo_), step((hi - lo_) / (count_ - 1)), count(count_) {}
  GridPosition at(double x) const {
    const double f = (x - lo) / step;
    int i = static_cast<int>(std::floor(f));
    i = std::clamp(i, 0, count - 2);
    return {i, f - i};
  }
};

/// The weights of the cubic through four equally spaced values p[-1], p[0], p[1], p[2]
/// (Catmull-Rom's interpolating form: the Lagrange cubic on the four nodes) at offset u in
/// [0, 1] from p[0].
struct CubicWeights {
  double wm, w0, w1, w2;
  double apply(double pm, double p0, double p1, double p2) const { return wm * pm + w0 * p0 + w1 * p1 + w2 * p2; }
};
inline CubicWeights cubic_weights(double u) {
  return {-u * (u - 1.0) * (u - 2.0) / 6.0, (u + 1.0) * (u - 1.0) * (u - 2.0) / 2.0,
          -(u + 1.0) * u * (u - 2.0) / 2.0, (u + 1.0) * u * (u - 1.0) / 6.0};
}
/// Their derivatives in u (the cubic's slope per interval).
inline CubicWeights cubic_slope_weights(double u) {
  return {-(3.0 * u * u - 6.0 * u + 2.0) / 6.0, (3.0 * u * u - 4.0 * u - 1.0) / 2.0,
          -(3.0 * u * u - 2.0 * u - 2.0) / 2.0, (3.0 * u * u - 1.0) / 6.0};
}

/// The cubic through the four samples about interval `at.i` of `count` (>= 4): nodes
/// i - 1 .. i + 2, shifted inward at the ends (one-sided). Its weights serve every field
/// sampled on the same nodes.
struct Stencil {
  int first;
  CubicWeights w;
  Stencil(GridPosition at, int count)
      : first(std::clamp(at.i - 1, 0, count - 4)), w(cubic_weights(at.u + (at.i - first - 1))) {}
  /// At `values` with stride 1.
  double operator()(const double* values) const {
    const double* v = values + first;
    return w.apply(v[0], v[1], v[2], v[3]);
  }
};

/// Three fields of one grid stored side by side (the three values of a node, then the next
/// node's; `row` nodes a row): the cubic `inner` picks along each of the four rows from
/// `first_row`, then the cubic `outer` weighs across those rows. The same sums, in the same
/// order, as a Stencil on each field alone (so the same bits), in one pass over the nodes.
struct Three {
  double f0 = 0.0, f1 = 0.0, f2 = 0.0;
};
inline Three bicubic3(const double* fields, int row, int first_row, const CubicWeights& outer, const Stencil& inner) {
  const double wi[4] = {inner.w.wm, inner.w.w0, inner.w.w1, inner.w.w2};
  double rows[3][4];
  for (int m = 0; m < 4; ++m) {
    const double* node = fields + 3 * (static_cast<long>(first_row + m) * row + inner.first);
    double r0 = 0.0, r1 = 0.0, r2 = 0.0;
    for (int k = 0; k < 4; ++k, node += 3) {
      r0 += wi[k] * node[0];
      r1 += wi[k] * node[1];
      r2 += wi[k] * node[2];
    }
    rows[0][m] = r0;
    rows[1][m] = r1;
    rows[2][m] = r2;
  }
  return {outer.apply(rows[0][0], rows[0][1], rows[0][2], rows[0][3]),
          outer.apply(rows[1][0], rows[1][1], rows[1][2], rows[1][3]),
          outer.apply(rows[2][0], rows[2][1], rows[2][2], rows[2][3])};
}

/// The cubic of interval i of `count` (>= 4) uniform samples (the one Stencil evaluates
/// there) in powers of x, the offset from node first + 1, less `minus`: the interval is x in
/// [shift, shift + 1]. Newton steps on it cost a few operations each.
struct IntervalCubic {
  double c0 = 0.0, c1 = 0.0, c2 = 0.0, c3 = 0.0;
  double shift = 0.0;
  IntervalCubic(const double* samples, int i, int count, double minus = 0.0) {
    const int first = std::clamp(i - 1, 0, count - 4);  // as Stencil picks its nodes
    shift = i - first - 1;
    // The cubic through (-1, p0), (0, p1), (1, p2), (2, p3) (cubic_weights() expanded).
    const double* p = samples + first;
    c3 = (p[3] - p[0]) / 6.0 + (p[1] - p[2]) / 2.0;
    c2 = (p[0] + p[2]) / 2.0 - p[1];
    c1 = p[2] - p[0] / 3.0 - p[1] / 2.0 - p[3] / 6.0;
    c0 = p[1] - minus;
  }
  double value(double x) const { return ((c3 * x + c2) * x + c1) * x + c0; }
  double slope(double x) const { return (3.0 * c3 * x + 2.0 * c2) * x + c1; }
};

/// The root u in [0, 1] of an increasing function on an interval, f(0) <= 0 <= f(1):
/// `f(u, &rate)` gives f and df/du. Newton from `u`, kept inside a bracket that every step
/// narrows (bisection where a step would leave it): three or four steps where f is a cubic.
/// A step of 1e-12 leaves an error of its square; a tolerance at the rounding of u is not
/// reached where f's own rounding moves it (it took 12 steps on average).
template <class F>
double newton_in_interval(F&& f, double u) {
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 60; ++k) {
    double rate = 0.0;
    const double value = f(u, &rate);
    if (value == 0.0) break;  // the root to the last bit (a bisection from here went astray for 30 steps)
    (value < 0.0 ? lo : hi) = u;
    double next = rate > 0.0 ? u - value / rate : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - u) <= 1e-12 || next == lo || next == hi) return next;
    u = next;
  }
  return u;
}

}  // namespace punchsweep::model
