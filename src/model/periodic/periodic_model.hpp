#pragma once
/// @file
/// The `periodic` model (docs/model.md, section 14): the elastic state of the whole periodic
/// cell, read from its tables (periodic_solution.hpp) at the creep-weighted load X(t), in the
/// faces the localization models have (the single-level phase, the two-level branch), so
/// that the classification, the load history and the relaxation integrals are the same code.

#include <optional>

#include "model/problem/contact_problem.hpp"
#include "model/periodic/periodic_solution.hpp"
#include "model/contact/regime.hpp"
#include "model/contact/two_level_branch.hpp"

namespace punchsweep::model {

/// The problem's scales: xi = X / X_unit, delta = dh / h_unit, Q = Q~ Q_unit (section 14.2).
struct PeriodicScales {
  double X_unit = 1.0;  ///< C l^(s-1), in E0*
  double h_unit = 1.0;  ///< C l^s, in R
  double Q_unit = 1.0;  ///< C l^(s+1), in R^2 E0*
  double l = 1.0;
  explicit PeriodicScales(const ContactProblem& problem);
};

/// The single-level phase from the tables, with the face of SingleLevel.
class PeriodicSingleLevel {
 public:
  PeriodicSingleLevel(const ContactProblem& problem);

  /// Equivalent radius of the level-1 contact at X (the whole cell's once every node
  /// touches; l / sqrt(pi) for X = +infinity).
  double contact_radius(double X) const;
  /// h at X (the first argument, the radius, is not needed: the table is in X).
  double displacement_difference(double /*a1*/, double X) const;
  /// Both from one reading of the curve (h infinite for infinite X): what a point's
  /// single-level states need, at half the cost of the two calls.
  struct State {
    double a1 = 0.0;
    double h = 0.0;
  };
  State state(double X) const;
  /// Where level 2 touches: h(X*) = dh; X* = +infinity when the level-2 surface hides under
  /// level 1 (dh >= C (l/sqrt(2))^s).
  Touchdown touchdown(double dh) const;

 private:
  const PeriodicSolution* table_;
  PeriodicScales scales_;
};

/// The two-level phase from the tables: the state is the elastic one at X (section 14.1).
/// Not converged where the tables do not reach (delta above their top, Validity::outside_table).
class PeriodicBranch final : public TwoLevelBranch {
 public:
  PeriodicBranch(const ContactProblem& problem, const Touchdown& touch);

  TwoLevelSolve at(double X) const override;
  NominalRadii radii(const TwoLevelState&, double) const override { return {}; }
  double X_star() const override { return X_star_; }

  /// Whether the pressure grows at every node of the cell along loads X_a .. X_b (the
  /// tables' record; the condition for the viscoelastic pressure to stay >= 0).
  bool pressure_monotone(double X_a, double X_b) const;
  /// Whether the tables reach this branch's states (delta <= their top, or level 2 never
  /// touches).
  bool covered() const;

 private:
  const PeriodicSolution* table_;
  PeriodicScales scales_;
  PeriodicSolution::Row row_;  ///< the tables' row of this dh
  double X_star_ = 0.0;
};

}  // namespace punchsweep::model
