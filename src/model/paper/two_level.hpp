#pragma once

#include <array>
#include <cmath>
#include <optional>

#include "model/problem/contact_problem.hpp"
#include "model/contact/two_level_state.hpp"

namespace punchsweep::model {

/// The algebraic two-level system at fixed nominal radii, eqs (9.16), (9.17), (9.19):
/// unknowns a1, a2, Q1, Q2 at a given X. For fixed (a1, a2) the load equations are linear
/// in Q (a 2x2 solve), leaving two residuals: load balance Q1 + Q2 = l^2 X, and the
/// height condition. Those are solved by damped Newton with an analytic Jacobian in
/// (a1, z), z = a2^2 for s >= 2 (z = a2 for s = 1): near a2 = 0 the residuals are smooth
/// in z but not in a2, so Newton stays quadratic right from the moment level 2 touches.
class TwoLevelSystem {
 public:
  /// Newton stops when the step is below this, relative to l (or l^2 for z).
  static constexpr double kStepTolerance = 1e-14;
  /// A Newton step below this (relative, as above) from a point whose residuals are below
  /// kResidualTolerance * 1e3 is taken as the last: quadratic convergence leaves an error
  /// of order (1e-9)^2 after it, below rounding, so the root is not evaluated again (its
  /// loads Q come from the linearisation, to the same order).
  static constexpr double kFinalStep = 1e-9;
  /// ... or when both scaled residuals are below this (quadratic convergence makes one
  /// more step pointless) ...
  static constexpr double kConvergedResidual = 1e-14;
  /// ... and accepts the root only if both scaled residuals are below this.
  static constexpr double kResidualTolerance = 1e-11;
  static constexpr int kMaxIterations = 60;

  TwoLevelSystem(const ContactProblem& problem, NominalRadii radii);

  /// Newton from `guess` at creep-scaled pressure X, at most `max_iterations` steps
  /// (converged reports whether the residual tolerance is met when it stops).
  TwoLevelSolve solve(double X, const TwoLevelState& guess, int max_iterations = kMaxIterations) const;

  /// Follows the solution branch from a known solution `from` at X_from to X_to
  /// (continue_branch, at most `max_solves` Newton solves).
  TwoLevelSolve continue_to(const TwoLevelState& from, double X_from, double X_to,
                            int max_solves = kMaxContinuationSolves, int* solves = nullptr) const;

  /// The branch at X >= X*, started from the moment level 2 touches. With the delayed-phase
  /// radii (A1 = sqrt(5/pi) l, A2 = 2l/sqrt(pi)) the single-level solution at h = dh is an
  /// exact start; otherwise (or for dh -> 0) the isolated-punch small-load limit is.
  TwoLevelSolve solve_from_touchdown(double X) const;

  /// How a root (a1, a2) at X moves with the nominal radii: d(a1, z)/d(A1, A2) row-major,
  /// -J^-1 dr/dA by the implicit function theorem. The long-term guide keeps it to correct
  /// its guesses for the radii of immediate points.
  std::array<double, 4> root_radii_rates(double a1, double a2, double X) const;

  /// The system linearised at one (a1, a2), in (a1, z) and in the radii (A1, A2): scaled
  /// residuals r (dimensionless) and loads Q of eq (9.16), with their rates, each 2x2
  /// row-major (rows r0, r1 or Q1, Q2).
  struct Linearization {
    double r[2];
    double Q[2];
    double r_a[4];  ///< dr/d(a1, z)
    double Q_a[4];  ///< dQ/d(a1, z)
    double r_A[4];  ///< dr/d(A1, A2)
    double Q_A[4];  ///< dQ/d(A1, A2)
  };
  Linearization linearize(double a1, double a2, double X) const;

  const NominalRadii& radii() const { return radii_; }

 private:
  /// The system at one (a1, a2): scaled residuals r (dimensionless), their Jacobian
  /// J = dr/d(a1, z) row-major, the loads Q of eq (9.16) and dQ = dQ/d(a1, z) row-major.
  struct Evaluation {
    double r[2];
    double J[4];
    double Q[2];
    double dQ[4];
  };
  /// dr/d(A1, A2) and dQ/d(A1, A2), row-major; only linearize asks for them.
  struct RadiiRates {
    double r_A[4];
    double Q_A[4];
  };
  Evaluation evaluate(double a1, double a2, double X, RadiiRates* radii_rates = nullptr) const;

  ContactProblem problem_;
  NominalRadii radii_;
  double K_P_;
  double K_d_;
  int z_power_;  ///< a2 = z^(1/z_power_)
  double l2_;     ///< l / sqrt(2), the distance to the nearest punch of the other level
  double inv_l_;
  double inv_l2_;
  double inv_A1_;
  double inv_A2_;
};

}  // namespace punchsweep::model
