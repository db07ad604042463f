#pragma once

#include <vector>

#include "model/contact_problem.hpp"
#include "model/lattice.hpp"
#include "model/localization.hpp"
#include "model/spot_average.hpp"

namespace punchsweep::model {

/// The two-level state under a localization of the family of docs/model.md, section 11, at
/// creep-scaled pressure X (elastic at t = 0: X = pbar0): around a punch of level i every
/// punch of either level within the D = localization.shells nearest distinct distances is
/// kept (kept_neighbours; D = 2, point loads: the paper's eight, eqs 9.12-9.15), each as a point
/// load or spread over its own spot; the nominal pressure X acts beyond A_i with
/// pi A_i^2 X = the loads kept, itself included. With Q1 + Q2 = X l^2:
///   balance_i  Q_i = K_P a_i^(s+1) + sum_kept Q_j <w(a_i, .)>_j + 2X (A_i^2 asin(a_i/A_i) - a_i sqrt(A_i^2 - a_i^2))
///   depth      d_1 - d_2 = dh,  d_i = K_d a_i^s + sum_kept Q_j <1/(pi sqrt(.^2 - a_i^2))>_j - 2X sqrt(A_i^2 - a_i^2).
/// Solved by damped Newton (a finite-difference Jacobian) from a guess; level 2 must touch.
/// Units: lengths in R, X in E0*, Q in R^2 E0*.
class TwoLevelShells {
 public:
  TwoLevelShells(const ContactProblem& problem, Localization localization);

  struct State {
    double a1 = 0.0, a2 = 0.0, Q1 = 0.0, Q2 = 0.0, A1 = 0.0, A2 = 0.0;
    bool converged = false;  ///< residuals below 1e-12 of X l^2 with 0 < a2 < a1-side limits
  };
  /// The state at X from a guess (a1, a2), e.g. the paper's solution.
  State solve(double X, double a1, double a2) const;

 private:
  /// Residuals (balance 1, balance 2, load sum, depth) at z = (a1, a2, Q1, Q2), with A_i.
  std::vector<double> residuals(double X, const double* z, double* A1, double* A2) const;

  ContactProblem problem_;
  Localization localization_;
  double K_P_, K_d_;
  std::vector<DistanceShell> kept_[2];  ///< about a level-1 and a level-2 punch; distances in R
  SpotAverage spot_;
};

}  // namespace punchsweep::model
