#pragma once
/// @file
/// The two-level phase's state as every localization model holds it (the contact radii and
/// creep-scaled loads of both levels, the nominal radii, a solve's result), and the
/// continuation that follows any model's solution branch in X.

#include <cmath>

namespace punchsweep::model {

/// How close to a square root's branch point Newton may step (keeps the system real).
inline constexpr double kTwoLevelDomainMargin = 1.0 - 1e-12;

/// State of the two-level phase at one creep-scaled pressure X = pbar0 J(t):
/// contact radii a_i (in R) and creep-scaled loads Q_i = int J dP_i (in R^2).
struct TwoLevelState {
  double a1 = 0.0;
  double a2 = 0.0;
  double Q1 = 0.0;
  double Q2 = 0.0;
};

/// Radii outside which the nominal pressure acts around a level-1 / level-2 punch.
struct NominalRadii {
  double A1 = 0.0;
  double A2 = 0.0;
};

/// A two-level solve: the state, and whether Newton met its tolerance.
struct TwoLevelSolve {
  TwoLevelState state;
  bool converged = false;
};

/// Newton solves a continuation may spend (continue_branch): a branch that Newton only
/// follows in ever shorter steps is taken as ending there, not crawled along.
inline constexpr int kMaxContinuationSolves = 100;

/// Follows a two-level system's solution branch from a known solution `from` at X_from to
/// X_to, halving the step in X where its Newton fails and doubling it where it succeeds;
/// shared by every system with solve(X, guess). Bounded: not converged once a step falls
/// below 2^-20 of the whole or after `max_solves` Newton solves (`*solves`, if given, adds
/// the solves spent), with the last state reached.
template <class System>
TwoLevelSolve continue_branch(const System& system, const TwoLevelState& from, double X_from, double X_to,
                              int max_solves = kMaxContinuationSolves, int* solves = nullptr) {
  TwoLevelSolve current{from, true};
  double X = X_from;
  double step = X_to - X_from;
  const double min_step = std::abs(step) * 0x1p-20;
  int spent = 0;
  while (X != X_to) {
    if (spent >= max_solves) {
      current.converged = false;
      break;
    }
    const bool last = std::abs(X_to - X) <= std::abs(step);
    const double X_next = last ? X_to : X + step;
    const TwoLevelSolve trial = system.solve(X_next, current.state);
    ++spent;
    if (trial.converged) {
      current = trial;
      X = X_next;
      step *= 2.0;
    } else {
      step *= 0.5;
      if (std::abs(step) < min_step) {
        current.converged = false;
        break;
      }
    }
  }
  if (solves != nullptr) *solves += spent;
  return current;
}

}  // namespace punchsweep::model
