#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "model/problem/contact_problem.hpp"
#include "model/contact/regime.hpp"
#include "model/contact/two_level_branch.hpp"
#include "model/paper/two_level.hpp"
#include "model/shells/two_level_shells.hpp"

namespace punchsweep::model {

/// The two-level branch of a localization of the family (docs/model.md, section 11.1) for
/// one (l, s, C, dh), tabulated. Its radii follow the loads, so its state is a function of
/// X alone, from touchdown (X*, a1*, a2 = 0) to where its spots reach the merge margin or
/// its equations stop having a solution (X_end): one curve that every pbar, material and
/// load history of a sweep shares, and every time of a point.
///
/// The curve is interpolated piecewise in v = sqrt(X - X*), in which it is analytic
/// although a2 ~ sqrt(X - X*) at touchdown: segment j covers X in [X* 2^j, X* 2^(j+1)]
/// (segment 0 from X* itself), each in pieces of kNodes Chebyshev nodes in v, every node a
/// TwoLevelShells Newton root. A piece is halved until the interpolant agrees with Newton
/// roots at four points between its nodes to kTolerance (a1/l, z/l^z_power and
/// q1 = Q1/(X l^2)); Q2 = X l^2 - Q1 exactly, so the loads sum to the nominal load.
/// Segments are built on first use, each from the end of the one before, so the curve is a
/// pure function of (l, s, C, dh, localization): a sweep and `punchsweep point` read the
/// same bits.
/// Units: lengths in R, X in E0*, Q in R^2 E0*.
class ShellsBranch final : public TwoLevelBranch {
 public:
  /// Agreement of the interpolant with the Newton roots (relative, see above).
  static constexpr double kTolerance = 1e-10;
  static constexpr int kNodes = 12;
  /// Newton solves one curve may spend, continuations included (a curve usually takes a few
  /// hundred): where its roots can only be reached in ever shorter steps the curve ends
  /// where its pieces do, and the points beyond have no solution (Validity::no_solution),
  /// rather than the build crawling on for minutes.
  static constexpr int kMaxSolves = 6000;

  /// `touch`: the family's touchdown of the problem (touchdown(problem)).
  ShellsBranch(const ContactProblem& problem, const Touchdown& touch);

  /// The state at X: converged for X* <= X <= X_end. Beyond X_end (or if no branch exists:
  /// X* = 0 or infinite) not converged, with the last state the branch reached.
  TwoLevelSolve at(double X) const override;

  /// The nominal-pressure radii of a state at X (TwoLevelShells::radii).
  NominalRadii radii(const TwoLevelState& state, double X) const override { return system_.radii(state, X); }

  double X_star() const override { return X_star_; }
  /// Where the curve ends, once a query has reached it (+infinity before).
  double X_end() const { return X_end_; }

  /// How many Newton roots the curve has cost so far (nodes and checks).
  int roots() const { return roots_; }
  /// How many Newton solves they took, continuations included (at most kMaxSolves: the
  /// curve ends where its budget does).
  int solves() const { return solves_; }

 private:
  struct Piece {
    double v_lo = 0.0, v_hi = 0.0;
    double a1[kNodes] = {}, z[kNodes] = {}, q1[kNodes] = {};  ///< Chebyshev coefficients in v
  };
  /// Appends segment segments_built_ (its pieces); false when the curve ends in it (X_end_
  /// set, and its pieces up to X_end_ appended).
  bool build_next() const;
  /// A root on the curve, and its spots' gap to the merge margin (gap()).
  struct Root {
    double X = 0.0;
    TwoLevelState state;
    double gap = 0.0;
  };
  /// Where a root failed: at X, above the roots `below` and (if known) `under`.
  struct Failure {
    double X = 0.0;
    Root below;
    std::optional<Root> under;
  };
  /// Appends the pieces of [v_lo, v_hi] (halving until they meet kTolerance, `depth`
  /// halvings so far), from the root at the end of the pieces built (last_ at v_lo); false
  /// if a root failed (*failure says where). `end_root`: the root at v_hi, if known (the
  /// curve's end).
  bool build_pieces(double v_lo, double v_hi, int depth, Failure* failure, const Root* end_root = nullptr) const;
  /// Newton root at X from `guess`, else by continuation from `from` (not where the gap,
  /// extrapolated from `before` through `from`, has closed by X).
  TwoLevelSolve root(double X, const TwoLevelState& guess, const Root& from, const Root* before) const;
  /// Newton at X from `guess`, and continuation from `from` to X, within the curve's budget
  /// of solves (not converged once it is spent).
  TwoLevelSolve newton(double X, const TwoLevelState& guess) const;
  TwoLevelSolve continuation(const Root& from, double X) const;
  /// A guess at X from the last root (and linearly in v through the one before, if any).
  TwoLevelState predict(double X, const Root& last, const Root* before) const;
  /// How far a state's spots are from merging, in l: the least of 0.98 - 2 a_i/l and
  /// 0.98/sqrt(2) - (a1 + a2)/l (Localization::merge_margin); 0 at the curve's usual end.
  double gap(const TwoLevelState& state) const;
  TwoLevelState state_of(const Piece& piece, double v) const;
  double X_of(double v) const { return X_star_ + v * v; }
  /// The curve's smooth variable z = a2^2 (s >= 2) or a2 (s = 1), as TwoLevelShells' Newton's.
  double z_of(double a2) const { return problem_.shape.s >= 2 ? a2 * a2 : a2; }
  double a2_of(double z) const { return problem_.shape.s >= 2 ? std::sqrt(z) : z; }

  ContactProblem problem_;
  TwoLevelShells system_;
  double X_star_ = 0.0;
  double l2_ = 0.0;       ///< l^2
  double z_scale_ = 0.0;  ///< l^2 (z = a2^2, s >= 2) or l (z = a2, s = 1)
  bool usable_ = false;
  mutable std::vector<Piece> pieces_;  ///< by v, contiguous from 0
  mutable int segments_built_ = 0;
  mutable double X_end_;
  mutable TwoLevelState last_;  ///< the root at the end of the pieces built
  mutable double X_last_ = 0.0;
  mutable TwoLevelState end_state_;  ///< the root at X_end_
  mutable int roots_ = 0;
  mutable int solves_ = 0;
};

}  // namespace punchsweep::model
