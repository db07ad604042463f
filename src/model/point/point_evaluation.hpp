#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/problem/contact_problem.hpp"
#include "model/laws/creep_law.hpp"
#include "model/paper/elastic_two_level.hpp"
#include "model/load/load_history.hpp"
#include "model/paper/long_term_guide.hpp"
#include "model/periodic/periodic_model.hpp"
#include "model/contact/regime.hpp"
#include "model/contact/two_level_branch.hpp"
#include "model/paper/two_level.hpp"
#include "model/point/sensitivity.hpp"
#include "model/point/validity.hpp"

namespace punchsweep::model {

/// Relative tolerance of the invariant P1 + P2 = pbar0 l^2 before a point is flagged
/// Validity::inaccurate. The load history meets it with orders of magnitude to spare
/// (tests/model/point_evaluation_test.cpp: 1e-10 for T from 1 to 1e6, t up to 1e9).
inline constexpr double kLoadsTolerance = 1e-8;

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

/// Everything about a point that does not depend on the snapshot times (what a regime
/// map stores). Each field is a pure function of the point: no warm start from another
/// point enters, so a sweep gives bit-identical numbers however it is cut into tiles.
struct PointSummary {
  Regime regime = Regime::never;
  std::optional<double> t_star;  ///< in T_eps; empty for never
  double h_0 = 0.0;              ///< h at t = 0 (single-level phase), in R
  double h_inf = 0.0;            ///< h as t -> infinity (single-level phase), in R
  /// Decided from the two-level start state and the long-term state: radii only grow
  /// (Sect. 9.4.2), so no state in between can break a rule those two keep.
  Validity validity = Validity::valid;
  double invalid_at = 0.0;       ///< time of the state that breaks it, in T_eps (inf = long term)
  double violation_value = 0.0;  ///< the offending 2 a_i or a1 + a2 there, in R
  double violation_limit = 0.0;  ///< l or l/sqrt(2) (times merge_margin), in R
  /// The share of touching at which spots count as merged: 1, or Localization::kMergeMargin
  /// under a model with distributed neighbours.
  double merge_margin = 1.0;
  double first_seen = 0.0;       ///< earliest computed time that shows a break, in T_eps
  /// For Validity::inaccurate: which invariant broke (violation_value and violation_limit
  /// hold its numbers, invalid_at its time).
  /// history_cost: the loads were not computed (LoadHistory::kMaxSamples, kMaxKernelPieces);
  /// violation_value holds the decades the law's times span.
  enum class Invariant : std::int8_t { none, loads_sum, not_finite, radii_order, history_cost } invariant = Invariant::none;
  NominalRadii radii;            ///< A1, A2 of the two-level phase (frozen, eq 9.18)
  double a1_inf = 0.0;           ///< long-term radii and area fraction (J = J(inf))
  double a2_inf = 0.0;
  double area_fraction_inf = 0.0;
  /// d t*/d dh, d t*/d pbar and d t*/d l (sensitivity.hpp), in T_eps per R, per E0*, per R:
  /// set by a map's full mode (t_star_derivatives_of); NaN otherwise, and where t* is not
  /// delayed or not smooth within the difference's step.
  double dt_star_ddh = std::numeric_limits<double>::quiet_NaN();
  double dt_star_dpbar = std::numeric_limits<double>::quiet_NaN();
  double dt_star_dl = std::numeric_limits<double>::quiet_NaN();
  /// The least and greatest t* over a box of tolerances, where one is given (the point
  /// command's --tolerance, a map's output.tolerance).
  std::optional<TStarRange> t_star_range;

  /// Start of the two-level phase (t_start = t*, or 0 when immediate).
  double t_start = 0.0;
  double X_start = 0.0;          ///< creep-weighted load X(t_start), in E0*
  TwoLevelState start;
  bool start_ok = true;

  /// How an iterative full solution behind this result fared (set for the periodic BEM
  /// reference by reference::as_point_result, over all its contact solves; the model's
  /// own results leave it as is): whether every solve met its tolerance, their
  /// conjugate-gradient iterations, and the largest final residual (relative to the
  /// displacement range).
  struct SolverReport {
    bool converged = true;
    double iterations = 0.0;
    double residual = 0.0;
  } solver;

  bool valid() const { return validity == Validity::valid; }
  /// One sentence telling why the result is flagged, with the numbers; "" when valid.
  std::string reason(std::string_view time_unit = "T_eps") const;
};

/// A point's summary plus its state at the requested times.
struct PointResult : PointSummary {
  std::vector<Snapshot> series;  ///< one per requested time, in the order requested
  int history_samples = 0;       ///< two-level solves spent on the load history
  /// d t*/dx along each real-valued parameter (sensitivity.hpp), where asked for (the point
  /// command and Python's point fill it; a map's full mode stores dh's, pbar's and the
  /// law's); empty otherwise.
  std::vector<TStarDerivative> t_star_derivatives;
  /// Physical advisories (advisory.hpp), where asked for (the point command, Python's
  /// point): their names ("" for none), the sentence, and the representative strain.
  std::string advisories;
  std::string advisory_reason;
  double strain = std::numeric_limits<double>::quiet_NaN();
};

/// The ingredients of a summary that depend on fewer coordinates than the point; a sweep
/// computes each once per distinct subset and passes them in.
struct SummaryParts {
  Classification classification;  ///< via touchdown(): per (l, s, C, dh), then cheap
  double h_0 = 0.0;                ///< per (l, s, C, pbar)
  double h_inf = 0.0;              ///< per (l, s, C, pbar, creep)
  double a1_inf_single = 0.0;      ///< single-level radius at J(inf): the same subset
  /// solve_elastic_start(), per (l, s, C, dh, pbar); required when classification.elastic_start
  const ElasticTwoLevel* elastic = nullptr;
  const LongTermGuide* guide = nullptr;      ///< per (l, s, C, dh); required under the paper's localization
  /// per (l, s, C, dh); required under the family's and the periodic model
  const TwoLevelBranch* branch = nullptr;
  /// The point's creep-weighted load, if the caller has it (else made here).
  const CreepWeightedLoad* load = nullptr;
};

/// The single-level phase at creep-weighted load X (eq 9.5): the level-1 radius a1(X) and
/// the level-2 tip gap h(X) (infinite for infinite X). A function of (l, s, C, the
/// localization) and X alone.
struct SingleLevelState {
  double a1 = 0.0;
  double h = 0.0;
};
SingleLevelState single_level_at(const ContactProblem& problem, double X);

/// h(0), h(inf) and the single-level radius at J(inf) (eq 9.5, 9.10): single_level_at at
/// X(0) and X(inf).
void single_level_ends(const ContactProblem& problem, const CreepLaw& creep, double* h_0,
                       double* h_inf, double* a1_inf_single);

/// The inverse of t*: the height difference dh whose second level touches at time t (in the
/// law's unit) under `problem`'s pressure and loading, `problem.dh` not read. Until it touches
/// only the first level carries the load, so the gap it closes by t, h(X(t)) (eq 9.5 at the
/// creep-weighted load), is the same for every dh: dh <= h(X(t)) touches by t. t = 0 gives
/// h_0 (touches at once), t = +inf h_inf (touches ever; +inf where creep has no end).
double dh_touching_at(const ContactProblem& problem, const CreepLaw& creep, double t);

/// What a point's summary needs that depends only on (l, s, C, dh) and the localization:
/// its touchdown, and its long-term guide (the paper's model) or its two-level branch (the
/// family's, the periodic model's). A sweep or a batch of points builds it once per such subset.
struct DhParts {
  Touchdown touchdown;
  std::shared_ptr<const LongTermGuide> guide;
  /// The two-level branch: the periodic model's held here (a scattered point builds one of
  /// its own, and its allocation and release cost classify 4% of its time), the family's
  /// shared.
  std::optional<PeriodicBranch> periodic;
  std::shared_ptr<const TwoLevelBranch> shells;
  const TwoLevelBranch* branch() const {
    if (periodic) return &*periodic;
    return shells.get();
  }
};
DhParts dh_parts(const ContactProblem& problem);  ///< pbar0 and the loading are not read

/// What it needs per (l, s, C, pbar0, creep law, loading): the single-level ends.
struct SingleLevelEnds {
  double h_0 = 0.0;
  double h_inf = 0.0;
  double a1_inf_single = 0.0;
};
SingleLevelEnds single_level_ends(const ContactProblem& problem, const CreepLaw& creep);

/// The summary from its shared parts: the classification by the creep-weighted load, the
/// elastic start where the point needs it (kept in *elastic, which may already hold the one
/// of this (l, s, C, dh, pbar0): it is the same for every creep law, at modulus 1/J(0) = 1),
/// then summarize_point(problem, creep, SummaryParts).
PointSummary summarize_point(const ContactProblem& problem, const CreepLaw& creep, const DhParts& dh,
                             const SingleLevelEnds& ends, std::optional<ElasticTwoLevel>* elastic = nullptr);

/// The elastic two-level state at t = 0+ (eqs 9.12-9.15): modulus 1/J(0) under the nominal
/// pressure applied at once, pbar(0+) = pbar0 phi(0+). `guide` (the paper's) and `branch`
/// (the family's; built here if null) may be null.
ElasticTwoLevel solve_elastic_start(const ContactProblem& problem, const CreepLaw& creep, const LongTermGuide* guide,
                                    const TwoLevelBranch* branch = nullptr);

/// The summary from its parts (`elastic` must be set when classification.elastic_start).
PointSummary summarize_point(const ContactProblem& problem, const CreepLaw& creep,
                             const SummaryParts& parts);

/// The summary, computing every part.
PointSummary summarize_point(const ContactProblem& problem, const CreepLaw& creep);

/// Evaluates one point: its summary and the state at every requested time. Never throws
/// for a problem that passes problem_error(); a point whose equations have no admissible
/// solution comes back flagged no_solution with NaN only in what could not be computed, and
/// a point whose numbers break an invariant (P1 + P2 = pbar0 l^2 to kLoadsTolerance, finite
/// values, 0 <= a2 <= a1) comes back flagged inaccurate.
PointResult evaluate_point(const ContactProblem& problem, const CreepLaw& creep,
                           const EvaluationOptions& options = {});

/// The same, from a summary already computed by summarize_point() for this point; under a
/// localization of the family its two-level branch (built here if null).
PointResult evaluate_point(const ContactProblem& problem, const CreepLaw& creep,
                           const EvaluationOptions& options, const PointSummary& summary,
                           const TwoLevelBranch* branch = nullptr);

}  // namespace punchsweep::model
