#pragma once

#include "model/problem/contact_problem.hpp"
#include "model/contact/regime.hpp"
#include "model/contact/two_level_state.hpp"

namespace punchsweep::model {

/// A two-level phase whose state is a function of the creep-weighted load X alone, from
/// touchdown (X*) on: the refined family's (ShellsBranch) and the periodic solution's
/// (PeriodicBranch). A sweep builds one per (l, s, C, dh) and every pbar, material, load
/// history and time of it reads the same curve.
class TwoLevelBranch {
 public:
  virtual ~TwoLevelBranch() = default;

  /// The state at X >= X*; not converged where the branch has none (with the last state
  /// it reached, or NaN).
  virtual TwoLevelSolve at(double X) const = 0;
  /// The radii outside which the nominal pressure acts, for a state at X (what the output
  /// shows as A1, A2 at the start); 0 where the model has none.
  virtual NominalRadii radii(const TwoLevelState& state, double X) const = 0;
  virtual double X_star() const = 0;

  /// The same face as TwoLevelSystem (for evaluate_series): both read the curve at X; the
  /// guess and the start are not needed.
  TwoLevelSolve solve(double X, const TwoLevelState& /*guess*/) const { return at(X); }
  TwoLevelSolve continue_to(const TwoLevelState& /*from*/, double /*X_from*/, double X_to) const { return at(X_to); }
};

}  // namespace punchsweep::model
