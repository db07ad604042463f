#pragma once
/// @file
/// The aimed bisection that finds where a site touches: the load curve's touchdowns (in
/// log X, load_curve.cpp) and a share of a level's caps over the level's drop
/// (level_closure.cpp). A bracket [lo, hi] with the site untouched at lo and touched at hi;
/// its gap is smooth on the untouched side and falls to 0 where it touches, so the secant
/// through the last two untouched trials predicts the touchdown. The gap falls ever slower
/// as the touchdown nears (it is convex), so the secant overshoots: a trial short of its
/// zero (by at least half a tolerance) stays untouched and brings the next secant close;
/// once the zero lies within half a tolerance of lo, one just past it closes the bracket,
/// usually in a few trials (as the time stepping's t* search does). A trial that lands on
/// the other side than aimed makes the next one the midpoint.

#include <algorithm>
#include <cmath>
#include <limits>

namespace punchsweep::reference {

class TouchdownSearch {
 public:
  /// The bracket [lo, hi] (untouched at lo, touched at hi), an untouched point x at or
  /// below lo with its gap (lo itself where it is the first), and the bracket's width at
  /// which the search stops.
  TouchdownSearch(double lo, double hi, double x, double gap, double tolerance)
      : lo_(lo), hi_(hi), x1_(x), g1_(gap), tolerance_(tolerance) {}

  /// Whether the bracket is still wider than the tolerance.
  bool open() const { return hi_ - lo_ > tolerance_; }

  /// The next trial, aimed (or the midpoint).
  double trial() {
    double trial = 0.5 * (lo_ + hi_);
    aim_touched_ = true;
    const double secant = two_ && g0_ > g1_ && g1_ > 0.0 && std::isfinite(g0_) ? x1_ + g1_ * (x1_ - x0_) / (g0_ - g1_) : hi_;
    if (!halve_ && secant < hi_) {  // (a zero at or past the touched end says the secant is far off)
      const double predicted = secant;
      aim_touched_ = predicted - lo_ <= 0.5 * tolerance_;
      // Short by a tenth of the way, or by twice the last move of the prediction once that
      // is less (the secant converging).
      const double short_of =
          std::max(0.45 * tolerance_, std::min(0.1 * (predicted - lo_), 2.0 * std::abs(predicted - last_predicted_)));
      last_predicted_ = predicted;
      const double margin = std::min(0.1 * tolerance_, 0.25 * (hi_ - lo_));
      trial = std::clamp(aim_touched_ ? predicted + 0.45 * tolerance_ : predicted - short_of, lo_ + margin, hi_ - margin);
    }
    return trial;
  }

  /// The trial at x touched: the bracket's touched end.
  void touched(double x) {
    halve_ = !halve_ && !aim_touched_;
    hi_ = x;
  }
  /// The trial at x did not touch, its gap `gap`: the bracket's untouched end and the
  /// secant's newest point.
  void untouched(double x, double gap) {
    halve_ = !halve_ && aim_touched_;
    lo_ = x;
    x0_ = x1_;
    g0_ = g1_;
    x1_ = x;
    g1_ = gap;
    two_ = true;
  }

  double lo() const { return lo_; }
  double hi() const { return hi_; }

 private:
  double lo_, hi_;
  double x0_ = 0.0, g0_ = 0.0, x1_, g1_;
  double tolerance_;
  bool two_ = false, halve_ = false, aim_touched_ = true;
  double last_predicted_ = std::numeric_limits<double>::infinity();
};

}  // namespace punchsweep::reference
