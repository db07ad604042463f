#pragma once

#include <array>

#include "model/problem/contact_problem.hpp"
#include "model/problem/localization.hpp"
#include "model/shells/shell_sums.hpp"
#include "model/paper/two_level.hpp"

namespace punchsweep::model {

/// The two-level phase under a localization of the family of docs/model.md, section 11, at
/// creep-scaled pressure X (X = pbar0 J(t) under a step; the elastic state at t = 0 is the
/// one at X = pbar(0+) J(0)): around a punch of level i every punch of either level within
/// the D = localization.shells nearest distinct distances is kept (kept_neighbours; D = 2,
/// point loads: the paper's eight, eqs 9.12-9.15), each as a point load or spread over its
/// own spot (ShellSums); the nominal pressure X acts beyond A_i with pi A_i^2 X = the
/// creep-scaled loads kept, itself included. The radii follow the loads at every X (eq 9.13
/// at every moment, not frozen as eq 9.18 does): so the state is a function of X alone, as
/// the paper's is, and the load history of section 9.4 applies unchanged. With
/// Q1 + Q2 = X l^2:
///   balance_i  Q_i = K_P a_i^(s+1) + sum_kept Q_j <w(a_i, .)>_j + 2X (A_i^2 asin(a_i/A_i) - a_i sqrt(A_i^2 - a_i^2))
///   depth      d_1 - d_2 = dh,  d_i = K_d a_i^s + sum_kept Q_j <1/(pi sqrt(.^2 - a_i^2))>_j - 2X sqrt(A_i^2 - a_i^2).
/// Solved by damped Newton in (a1, z, Q1, Q2), z = a2^2 for s >= 2 (a2 for s = 1) as in
/// TwoLevelSystem, with a forward-difference Jacobian. The same solve/continue_to face as
/// TwoLevelSystem, so that the point evaluation runs either.
/// Units: lengths in R, X in E0*, Q in R^2 E0*.
class TwoLevelShells {
 public:
  /// Newton stops when the scaled residuals are below this, and accepts the root if they
  /// are below kResidualTolerance.
  static constexpr double kConvergedResidual = 1e-13;
  static constexpr double kResidualTolerance = 1e-11;
  static constexpr int kMaxIterations = 60;

  TwoLevelShells(const ContactProblem& problem, Localization localization);

  /// Newton from `guess` at X (guess.Q1 + guess.Q2 <= 0: a 9:1 split of X l^2 is tried).
  TwoLevelSolve solve(double X, const TwoLevelState& guess, int max_iterations = kMaxIterations) const;
  /// Follows the branch from `from` at X_from to X_to (continue_branch, at most
  /// `max_solves` Newton solves).
  TwoLevelSolve continue_to(const TwoLevelState& from, double X_from, double X_to,
                            int max_solves = kMaxContinuationSolves, int* solves = nullptr) const;

  /// The nominal-pressure radii A1, A2 (in R) of a state at X.
  NominalRadii radii(const TwoLevelState& state, double X) const;

  /// The residuals (balance 1, balance 2, load sum, depth), each scaled by X l^2 (the depth
  /// by X l), at (a1, a2, Q1, Q2).
  std::array<double, 4> residuals(double X, const std::array<double, 4>& z) const;

 private:
  /// The neighbourhood sums about a level-1 and a level-2 punch: what the radii fix.
  struct Sums {
    ShellSums::Sums same[2];
    ShellSums::Sums cross[2];
  };
  Sums sums(double a1, double a2) const;
  std::array<double, 4> residuals(double X, const std::array<double, 4>& z, const Sums& sums) const;

  ContactProblem problem_;
  double K_P_, K_d_;
  const ShellSums* sums_;  ///< shared, scaled by l
  double margin_;          ///< Localization::merge_margin: the spots stay this far from touching
};

}  // namespace punchsweep::model
