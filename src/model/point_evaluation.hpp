#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/contact_problem.hpp"
#include "model/creep_law.hpp"
#include "model/load_history.hpp"
#include "model/regime.hpp"
#include "model/two_level.hpp"
#include "model/validity.hpp"

namespace punchsweep::model {

/// The contact state at one snapshot time.
struct Snapshot {
  double t = 0.0;              ///< in T_eps
  double a1 = 0.0;             ///< level-1 contact radius, in R
  double a2 = 0.0;             ///< level-2 contact radius, in R (0 before touchdown)
  double P1 = 0.0;             ///< load on one level-1 punch, in R^2 E0*
  double P2 = 0.0;             ///< load on one level-2 punch, in R^2 E0*
  double area_fraction = 0.0;  ///< lambda = pi (a1^2 + a2^2) / l^2, eq (9.20)
};

/// What to compute besides the regime.
struct EvaluationOptions {
  std::vector<double> times{0.0, 0.5, 1.0, 2.0, 5.0};  ///< snapshot times, in T_eps, >= 0
  HistoryQuadrature quadrature{};
};

/// Everything the paper computes for one parameter point.
struct PointResult {
  Regime regime = Regime::never;
  std::optional<double> t_star;  ///< in T_eps; empty for never
  double h_0 = 0.0;              ///< h at t = 0 (single-level phase), in R
  double h_inf = 0.0;            ///< h as t -> infinity (single-level phase), in R
  Validity validity = Validity::valid;
  double invalid_at = 0.0;       ///< first computed time violating it, in T_eps (inf = long term)
  double violation_value = 0.0;  ///< the offending 2 a_i or a1 + a2, in R
  double violation_limit = 0.0;  ///< l or l/sqrt(2), in R
  NominalRadii radii;            ///< A1, A2 of the two-level phase (frozen, eq 9.18)
  double a1_inf = 0.0;           ///< long-term radii and area fraction (J = J(inf))
  double a2_inf = 0.0;
  double area_fraction_inf = 0.0;
  std::vector<Snapshot> series;  ///< one per requested time, in the order requested
  int history_samples = 0;       ///< two-level solves spent on the load history

  bool valid() const { return validity == Validity::valid; }
  /// One sentence telling why the result is flagged, with the numbers; "" when valid.
  std::string reason() const;
};

/// Evaluates one point: regime and t*, h(0), h(inf), the frozen radii, the state at every
/// requested time, the long-term state, and validity. Never throws for a problem that
/// passes problem_error(); a point whose equations have no admissible solution comes back
/// flagged no_solution with NaN only in the quantities that could not be computed.
PointResult evaluate_point(const ContactProblem& problem, const CreepLaw& creep,
                           const EvaluationOptions& options = {});

}  // namespace punchsweep::model
