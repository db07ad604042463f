#pragma once

#include <optional>

#include "model/problem/contact_problem.hpp"
#include "model/paper/two_level.hpp"

namespace punchsweep::model {

/// Result of the elastic two-level problem, eqs (9.12)-(9.15), where A_i are unknowns too.
struct ElasticTwoLevel {
  TwoLevelState state;  ///< Q_i = P_i / E here
  NominalRadii radii;
  bool converged = false;
  bool level2_touches = false;  ///< false when pbar/E is too low for level 2 to touch
};

class LongTermGuide;

/// Newton on (a1, z, A1, A2) at once for the elastic problem at X = pbar/E (level 2
/// touching): the two-level residuals at radii A, and eq (9.13) as
/// (pi X A_i^2 - 5 Q_i - 4 Q_j) / (l^2 X) = 0. Started from the guide's state at the
/// touchdown radii (which lie a few percent of l off), it converges quadratically in about
/// four linearisations, where iterating eq (9.13) around Newton took about eight
/// evaluations. Empty if Newton fails.
std::optional<ElasticTwoLevel> solve_elastic_jointly(const ContactProblem& problem, double X,
                                                     const TwoLevelState& start, NominalRadii radii);

/// Elastic two-level contact for modulus E (in E0*), eqs (9.12)-(9.15): the radii A_i
/// follow pi A_i^2 pbar = 5 P_i + 4 P_j (eq 9.13). With a `guide`, solve_elastic_jointly
/// from its state; without one, or if that fails, by fixed-point iteration of eq 9.13
/// around the Newton solve (|dA| < 1e-13 l, at most 200 sweeps; A depends weakly on a),
/// started from the guide's state or else by following the branch from touchdown.
ElasticTwoLevel solve_elastic_two_level(const ContactProblem& problem, double E,
                                        const LongTermGuide* guide = nullptr);

}  // namespace punchsweep::model
