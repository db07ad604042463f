#pragma once
/// @file
/// Load-controlled normal contact of a rigid periodic surface with an elastic half-space,
/// by the constrained conjugate gradient of Polonsky & Keer (1999). Units: pressures in E0*,
/// lengths in R; the half-space is the E* = 1 one times a compliance factor.

#include <span>
#include <vector>

#include "reference/fft_influence.hpp"
#include "reference/periodic_grid.hpp"

namespace punchsweep::reference {

/// Numerical choices of the contact solve.
struct ContactSolverOptions {
  /// Stop when the complementarity residual (see ContactStatus::residual) is at most this.
  double tolerance = 1e-10;
  /// Give up (converged = false) after this many conjugate-gradient iterations.
  int max_iterations = 5000;
  /// Precondition the conjugate gradient by the half-space's stiffness (see ContactSolver).
  /// The same answer to the tolerance; at N = 256, 4-5 times fewer iterations (measured).
  bool precondition = true;
};

/// Outcome of one contact solve.
struct ContactStatus {
  /// Rigid approach delta, in R: the gap is profile + u - delta. It is measured from the
  /// zero-mean displacement (the k = 0 mode of a periodic half-space is not defined).
  double approach = 0.0;
  int iterations = 0;
  /// max( max over contact |gap|, max over the rest of the penetration -gap ) divided by
  /// the displacement range max u - min u: zero for the exact discrete solution.
  double residual = 0.0;
  bool converged = false;
};

/// The whole solution of a contact solve (the convenience form of ContactSolver::solve).
struct ContactSolution {
  std::vector<double> pressure;      ///< p >= 0 at every node, in E0*
  std::vector<double> displacement;  ///< u = compliance K p, zero mean, in R
  ContactStatus status;
};

/// Polonsky & Keer's constrained conjugate gradient (Wear 231 (1999) 206-219,
/// doi:10.1016/S0043-1648(99)00113-1) with the mean pressure prescribed: it minimises the
/// complementary energy p.(c K p)/2 + p.f over p >= 0 with mean(p) = pbar; the approach is
/// the multiplier of the mean-pressure constraint. On the converged contact set the gap
/// vanishes, elsewhere p = 0 and the gap is non-negative.
///
/// Preconditioned (options.precondition, the default): the search direction follows
/// z = P(S g) instead of the gap residual g, with S the inverse of the influence operator,
/// the half-space's stiffness E* |k| / 2 / compliance in Fourier space (one more transform
/// pair an iteration), and P the restriction to the contact set about its mean there (the
/// load constraint). This is the preconditioned conjugate gradient (Golub & Van Loan,
/// Matrix Computations, 4th ed., section 11.5) on the contact set: K restricted to a
/// contact set of diameter d has a condition number that grows as d/h, and S undoes most
/// of it, so the iterations stop growing with the grid (measured: 17 a solve against 78
/// at N = 256 along a viscoelastic point). The stopping test and the answer are those of
/// the plain iteration.
///
/// On a mirrored grid (Symmetry::mirror) it solves the same discrete problem on the stored
/// quarter: the sums over the cell are weighted by the nodes' multiplicities, so in exact
/// arithmetic every iterate is the quarter of the whole grid's.
///
/// One instance owns its influence operator and scratch arrays: not for concurrent use.
class ContactSolver {
 public:
  explicit ContactSolver(const PeriodicGrid& grid, ContactSolverOptions options = {});

  /// Solves for the pressure under mean pressure `mean_pressure` > 0 against the initial
  /// separation `profile` (any rigid offsets included), with displacement u = compliance K p
  /// (compliance > 0, in 1/E0*). `pressure` holds the first guess on entry (any non-negative
  /// field with a positive mean, e.g. the previous step's solution; otherwise the uniform
  /// field is used) and the solution on return; `displacement` receives u.
  ContactStatus solve(std::span<const double> profile, double mean_pressure, double compliance,
                      std::span<double> pressure, std::span<double> displacement);

  /// The same from the uniform first guess, returning the fields.
  ContactSolution solve(std::span<const double> profile, double mean_pressure,
                        double compliance = 1.0);

  const PeriodicGrid& grid() const { return influence_.grid(); }
  const ContactSolverOptions& options() const { return options_; }
  /// The influence operator (E* = 1) the solver uses, for callers that need K of another
  /// field on the same grid.
  PeriodicInfluence& influence() { return influence_; }

 private:
  ContactSolverOptions options_;
  PeriodicInfluence influence_;
  std::vector<double> gap_;
  std::vector<double> direction_;
  std::vector<double> response_;
  std::vector<double> weight_;
  std::vector<double> preconditioned_;  ///< z = S g on the contact set (options.precondition)  ///< each stored node's multiplicity (all 1 on a whole grid)
};

}  // namespace punchsweep::reference
