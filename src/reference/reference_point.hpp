#pragma once
/// @file
/// One parameter point of the two-level punch system evaluated by the periodic
/// boundary-element reference solver: the same outputs as model::evaluate_point, from the
/// full contact problem on a grid instead of the localization method. Units as in
/// model/numerics/units.hpp: lengths in R, pressures in E0*, loads in R^2 E0*, time in T_eps.

#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "model/problem/contact_problem.hpp"
#include "model/laws/creep_law.hpp"
#include "model/point/point_evaluation.hpp"
#include "model/contact/regime.hpp"
#include "model/numerics/stop_request.hpp"
#include "reference/contact_solver.hpp"
#include "reference/periodic_grid.hpp"
#include "reference/step_sizer.hpp"

namespace punchsweep::reference {

/// The steps and t* resolution for `creep`, scaled with its retardation times lambda: first
/// step 0.02 lambda_min, at most 2 lambda_max, t* to 1e-3 lambda_min (for the standard
/// linear solid, lambda = 1 T_eps: the defaults). A law without a retardation series uses
/// its creep time scale for both.
struct ReferenceOptions;
void scale_steps_to_law(const model::CreepLaw& creep, ReferenceOptions* options);

/// What the solver is, for a map's identity: a map made by another solver (another
/// discretisation in time, or the whole cell with the plain iteration) would mix answers
/// that agree only to the solver's accuracy, so it does not resume.
inline constexpr std::string_view kSolverRevision =
    "2 (quarter cell, preconditioned conjugate gradient, steps of 5% growth of J)";

/// Numerical choices of a reference point.
struct ReferenceOptions {
  int n = 128;  ///< n x n grid on the l x l cell; even, >= kMinTwoLevelNodes
  /// mirror: solve on the quarter cell, the same discrete problem at a quarter of the
  /// unknowns (the cell is even in x and y); none: the whole cell (for cross-checks).
  Symmetry symmetry = Symmetry::mirror;
  std::vector<double> times{0.0, 0.5, 1.0, 2.0, 5.0};  ///< snapshot times, in T_eps, >= 0
  StepControl steps{};
  ContactSolverOptions solver{};
  /// The step in which level 2 first carries load is narrowed until it is at most this
  /// long (in T_eps); t* is then located inside that bracket. The trial times aim just
  /// either side of the touchdown that the level-2 tip gap extrapolates to (a secant on the
  /// last two states with level 2 free), falling back to halving when an aim misses, so a
  /// bracket usually takes two or three solves.
  double t_star_resolution = 1e-3;
  /// Not a numerical choice: checked between time steps, so that a sweep's stop signal
  /// ends a long point within a step (model::Stopped is thrown).
  model::StopRequest stop{};
};

/// Empty when the options are usable, else a sentence naming the first bad field.
std::string options_error(const ReferenceOptions& options);

/// The contact state at one snapshot time, measured on the grid.
struct ReferenceSnapshot {
  double t = 0.0;      ///< in T_eps
  double area1 = 0.0;  ///< contact area of one level-1 punch (contact_areas), in R^2
  double area2 = 0.0;  ///< contact area of one level-2 punch, in R^2
  double a1 = 0.0;     ///< equivalent radius sqrt(area1 / pi), in R
  double a2 = 0.0;     ///< equivalent radius sqrt(area2 / pi), in R
  double P1 = 0.0;     ///< pressure integrated over the level-1 punch's nodes, in R^2 E0*
  double P2 = 0.0;     ///< the same over the level-2 punch; P1 + P2 = pbar0 l^2
  double area_fraction = 0.0;  ///< (area1 + area2) / l^2
  double h = 0.0;              ///< u(O) - u(M): displacement difference of the two tips, in R
};

/// The outcome of a reference point.
struct ReferenceResult {
  /// immediate: level 2 carries load at t = 0; delayed: later (t* found by the stepping, or
  /// after the last snapshot time when t_star is empty); never: not even in the long-term
  /// state (elastic at J(inf), the extended correspondence principle), only for finite J(inf).
  model::Regime regime = model::Regime::never;
  /// First time level 2 carries load, in T_eps: 0 for immediate; inside
  /// [t_star_lower, t_star_upper] by linear extrapolation of the level-2 tip gap; empty for
  /// never and for delayed beyond the last snapshot time.
  std::optional<double> t_star;
  double t_star_lower = 0.0;  ///< last time computed with level 2 free (bracket of t*)
  double t_star_upper =
      std::numeric_limits<double>::infinity();  ///< first time with load on level 2
  std::vector<ReferenceSnapshot> series;        ///< one per requested time, in the order requested
  int steps = 0;                                ///< accepted time steps
  int solves = 0;             ///< contact solves, refinements and the long-term state included
  long cg_iterations = 0;     ///< conjugate-gradient iterations over all solves
  double max_residual = 0.0;  ///< largest final residual of any solve
  bool converged = true;      ///< every solve met the tolerance
  double spacing = 0.0;       ///< grid spacing l / n, in R
};

/// The reference's answer in the model's terms: its regime, t*, its solver's report
/// (converged, CG iterations, largest residual) and, per snapshot, t, a1, a2, P1, P2 and
/// the area fraction (what map::kQuantities reads for the bem_* variables).
model::PointResult as_point_result(const ReferenceResult& result);

/// The contact areas of the two levels of a cell, in R^2.
struct ContactAreas {
  double level1 = 0.0;
  double level2 = 0.0;
};

/// The contact areas of the two levels of the contact set {p > 0}: level_contact_areas
/// (reference/contact_areas.hpp) with the cell's level-2 share.
ContactAreas contact_areas(const TwoLevelCell& cell, std::span<const double> p, std::span<const double> rims);

/// Measures a contact state of a two-level cell: pressure p, the field that locates the
/// rims (contact_areas) and displacement u on its grid, at time t.
ReferenceSnapshot measure_state(const TwoLevelCell& cell, std::span<const double> p,
                                std::span<const double> rims, std::span<const double> u, double t);

/// Whether level 2 carries load: some node of its own (level2_node, ties included) is pressed.
bool level2_loaded(const TwoLevelCell& cell, std::span<const double> p);

/// Evaluates one point: a time-stepped viscoelastic contact solve under the constant
/// nominal pressure pbar0 on the two-level cell, with the outputs at every requested time.
/// Throws std::invalid_argument when problem_error() or options_error() is not empty; a
/// solve that misses its tolerance is reported through `converged` and `max_residual`.
ReferenceResult evaluate_reference_point(const model::ContactProblem& problem,
                                         const model::CreepLaw& creep,
                                         const ReferenceOptions& options = {});

/// The compliance J* at which level 2 first carries load in the elastic two-level problem
/// with displacement J K p, by bisection on [J_lo, J_hi] to width `width` (elastic solves
/// at mean pressure pbar0). Under constant nominal pressure the contact set only grows, so
/// by the extended correspondence principle the viscoelastic contact set at time t is the
/// elastic one at J(t) and t* = J^-1(J*): an independent check of the stepping's t*.
/// Returns J_lo when level 2 is loaded there and +infinity when it is free at J_hi.
double elastic_touchdown_compliance(const model::ContactProblem& problem, int n, double J_lo,
                                    double J_hi, double width,
                                    const ContactSolverOptions& solver = {});

}  // namespace punchsweep::reference
