#pragma once

#include <optional>
#include <vector>

#include "model/problem/contact_problem.hpp"
#include "model/paper/two_level.hpp"

namespace punchsweep::model {

/// Starting guesses for the two-level state at any creep-scaled pressure X beyond
/// touchdown, for one (l, s, C, dh).
///
/// With the delayed-phase radii (A1 = sqrt(5/pi) l, A2 = 2 l/sqrt(pi)) the two-level
/// solution is a curve X -> (a1, z) that every (pbar, T) of a sweep shares; a Newton
/// solve started on it needs about two residual evaluations instead of five or six. The
/// guide interpolates the curve piecewise: segment j covers X in [X* 2^j, X* 2^(j+1)]
/// (segment 0 from X* itself), 8 Chebyshev nodes in v = sqrt(X - X*), in which the curve
/// is analytic although a2 ~ sqrt(X - X*). Segments are built on first use, each from
/// the end of the one before, so every guess is a pure function of (l, s, C, dh, X): a
/// sweep and `punchsweep point` get the same guess, hence the same converged bits.
/// Also a good start for immediate points, whose radii differ by ~0.1% (Table 9.1).
class LongTermGuide {
 public:
  explicit LongTermGuide(const ContactProblem& problem);

  /// A guess at X (a1 and a2; Q left 0), or empty where no guide exists (dh = 0, X below
  /// touchdown or beyond the last segment that could be built).
  std::optional<TwoLevelState> guess(double X) const;

  /// The same for other nominal radii (an immediate point's, from the elastic solution at
  /// t = 0): corrected to first order in the radii with the curve's own rates
  /// d(a1, z)/d(A1, A2), interpolated like the curve. That removes most of the guess's
  /// error there (median 7e-3 -> 2e-4 relative), about one Newton step.
  std::optional<TwoLevelState> guess(double X, const NominalRadii& radii) const;

 private:
  static constexpr int kNodes = 8;
  static constexpr int kMaxSegments = 40;
  struct Segment {
    double v_lo = 0.0;
    double v_hi = 0.0;
    double inv_width = 0.0;  ///< 1 / (v_hi - v_lo)
    double a1[kNodes] = {};  ///< Chebyshev coefficients in t (v mapped onto [-1, 1])
    double z[kNodes] = {};
    double rate[4][kNodes] = {};  ///< d(a1, z)/d(A1, A2) row-major, coefficients likewise
  };
  bool build_next() const;  ///< appends segment segments_.size(); false if it failed

  ContactProblem problem_;
  TwoLevelSystem system_;  ///< at the delayed-phase radii
  double X_star_ = 0.0;
  double inv_X_star_ = 0.0;
  TwoLevelState touch_state_;
  bool usable_ = false;
  int z_power_ = 2;
  mutable std::vector<Segment> segments_;
  mutable bool exhausted_ = false;
  mutable TwoLevelState last_state_;  ///< solution at the end of the last built segment
  mutable double last_X_ = 0.0;
};

}  // namespace punchsweep::model
