#include "model/point/point_evaluation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <sstream>

#include "model/numerics/lattice.hpp"
#include "model/periodic/periodic_model.hpp"
#include "model/shells/shells_branch.hpp"
#include "model/localization/localization_model.hpp"

namespace punchsweep::model {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
/// A branch that stops within this share of the merge margin stopped because its spots merge.
constexpr double kMergeNear = 1e-3;

/// Which rule of docs/model.md, section 7 a state breaks, if any.
struct Violation {
  Validity code = Validity::valid;
  double value = 0.0;
  double limit = 0.0;
};

/// `margin`: the share of touching at which spots count as merged (Localization::merge_margin).
Violation check_state(double a1, double a2, double l, double margin = 1.0) {
  const double widest = 2.0 * std::max(a1, a2);
  if (widest >= margin * l) return {Validity::same_level_overlap, widest, margin * l};
  if (a1 + a2 >= margin * l / std::numbers::sqrt2) {
    return {Validity::cross_level_overlap, a1 + a2, margin * l / std::numbers::sqrt2};
  }
  return {};
}

void flag(PointSummary& out, const Violation& v, double t) {
  out.validity = v.code;
  out.violation_value = v.value;
  out.violation_limit = v.limit;
  out.invalid_at = t;
  out.first_seen = t;
}

/// Flags a broken invariant (Validity::inaccurate): which, its numbers, and when.
void flag_inaccurate(PointSummary& out, PointSummary::Invariant which, double value, double limit, double t) {
  flag(out, {Validity::inaccurate, value, limit}, t);
  out.invariant = which;
}

/// The radii invariant 0 <= a2 <= a1 (level 2 is the lower level).
bool radii_ordered(double a1, double a2) { return a2 >= 0.0 && a2 <= a1; }

double area_fraction(double a1, double a2, double l) {
  return std::numbers::pi * (a1 * a1 + a2 * a2) / (l * l);
}

/// A level's load below this share of the nominal load counts as negative under the periodic
/// model: well above the tables' interpolation noise (Q2 to about 1e-7 of the load just
/// after touchdown, where it starts from zero), well below a receding contact's.
constexpr double kPeriodicNegativeLoad = 1e-5;

/// The periodic model's own rules (docs/model.md, section 14): its two-level states must lie
/// in its tables, and the contact must not recede along the point's loads (each node's
/// elastic pressure grows with X, the tables' record). They replace any other flag: the
/// model has no other limit (merged spots are part of its solution).
void flag_periodic(PointSummary& out, const PeriodicBranch& branch, double X_inf) {
  if (out.regime != Regime::never && !branch.covered()) {
    flag(out, {Validity::outside_table, kNaN, kNaN}, out.t_start);
  } else if (!branch.pressure_monotone(0.0, X_inf)) {
    flag(out, {Validity::unloading, kNaN, kNaN}, 0.0);
  }
}

}  // namespace

std::string PointSummary::reason(std::string_view time_unit) const {
  if (validity == Validity::valid) return {};
  std::ostringstream out;
  out.precision(6);
  const auto when = [time_unit](double t) {
    std::ostringstream text;
    text.precision(6);
    if (std::isinf(t)) text << "in the long-term state (t -> infinity)";
    else text << "at t = " << t << " " << time_unit;
    return text.str();
  };
  // "l = " for the paper's rule, "0.98 l = " under the refined model's merge margin, and
  // why the rule is there.
  const auto margin_text = [this](std::string_view limit) {
    std::ostringstream text;
    if (merge_margin < 1.0) text << merge_margin << " ";
    text << limit << " = ";
    return text.str();
  };
  const std::string separate_spots =
      merge_margin < 1.0 ? " R (localization needs separate spots; the refined model's ring averages hold only with "
                           "gaps of at least 2%)"
                         : " R (localization needs separate spots)";
  switch (validity) {
    case Validity::same_level_overlap:
      if (std::isinf(violation_value)) {
        out << "creep is unlimited (J(inf) = infinity): the spots grow without bound until they merge, so the "
               "localization does not hold in the long term (t* and the states before the spots reach l/2 do)";
        break;
      }
      out << "spots of one level merge " << when(invalid_at) << ": 2 a_i = " << violation_value << " R >= "
          << margin_text("l") << violation_limit << separate_spots;
      break;
    case Validity::cross_level_overlap:
      out << "level-1 and level-2 spots merge " << when(invalid_at) << ": a1 + a2 = " << violation_value << " R >= "
          << margin_text("l/sqrt(2)") << violation_limit << separate_spots;
      break;
    case Validity::no_solution:
      out << "the two-level equations have no admissible solution " << when(invalid_at);
      break;
    case Validity::inaccurate:
      switch (invariant) {
        case Invariant::loads_sum:
          out << "the loads break P1 + P2 = pbar l^2 " << when(invalid_at) << ": P1 + P2 = " << violation_value
              << ", pbar l^2 = " << violation_limit << " R^2 E0* (relative error "
              << std::abs(violation_value - violation_limit) / violation_limit << " > " << kLoadsTolerance << ")";
          break;
        case Invariant::not_finite:
          if (std::isinf(invalid_at)) {
            out << "a summary value (h_0, h_inf, t* or the long-term state) is not finite";
          } else {
            out << "a value of the state is not finite " << when(invalid_at);
          }
          out << " (the point lies beyond what double precision resolves)";
          break;
        case Invariant::history_cost:
          out << "the loads P1, P2 " << when(invalid_at) << " are not computed: the material's creep and relaxation "
              << "times span " << violation_value << " decades up to that time, more than the load-history quadrature "
              << "resolves (regime, t*, h and the radii are unaffected)";
          break;
        case Invariant::radii_order:
          out << "the radii break 0 <= a2 <= a1 " << when(invalid_at) << ": a1 = " << violation_limit
              << " R, a2 = " << violation_value << " R";
          break;
        case Invariant::none:
          break;
      }
      break;
    case Validity::outside_table:
      out << "the periodic model's tables do not reach this point's two-level states: dh / (C l^s) is above the "
             "tables' top, " << PeriodicTable::kTopShare << " (1/sqrt(2))^s, where the level-2 spot is a sliver of "
             "the cell (the regime and t* are exact; `punchsweep reference` answers the rest)";
      break;
    case Validity::unloading:
      out << "the contact may recede along this point's loads (an elastic pressure of the cell falls as X grows, "
             "or a level's load turns negative " << when(invalid_at) << "): the periodic model needs a contact set "
             "that only grows; the time-stepping `punchsweep reference` answers such points";
      break;
    case Validity::valid: break;
  }
  if (first_seen < invalid_at) out << "; already broken " << when(first_seen);
  return out.str();
}

SingleLevelState single_level_at(const ContactProblem& problem, double X) {
  SingleLevelState state;
  visit_single_level(problem, [&](const auto& single) {
    if constexpr (requires { single.state(X); }) {
      const auto both = single.state(X);  // the periodic tables: one reading
      state.a1 = both.a1;
      state.h = both.h;
    } else {
      state.a1 = single.contact_radius(X);
      state.h = std::isfinite(X) ? single.displacement_difference(state.a1, X) : kInf;
    }
  });
  return state;
}

void single_level_ends(const ContactProblem& problem, const CreepLaw& creep, double* h_0,
                       double* h_inf, double* a1_inf_single) {
  const CreepWeightedLoad load(creep, problem.pbar0, problem.loading);
  *h_0 = single_level_at(problem, load.initial()).h;
  const SingleLevelState end = single_level_at(problem, load.final());
  *a1_inf_single = end.a1;
  *h_inf = end.h;
}

double dh_touching_at(const ContactProblem& problem, const CreepLaw& creep, double t) {
  const CreepWeightedLoad load(creep, problem.pbar0, problem.loading);
  return single_level_at(problem, load.by(t)).h;
}

PointSummary summarize_point(const ContactProblem& problem, const CreepLaw& creep,
                             const SummaryParts& parts) {
  PointSummary out;
  const Classification& c = parts.classification;
  out.regime = c.regime;
  if (c.regime != Regime::never) out.t_star = c.t_star;
  out.h_0 = parts.h_0;
  out.h_inf = parts.h_inf;
  const double l = problem.l;
  const double margin = problem.localization.merge_margin();
  out.merge_margin = margin;
  const std::optional<CreepWeightedLoad> own_load =
      parts.load != nullptr ? std::nullopt : std::optional<CreepWeightedLoad>(std::in_place, creep, problem.pbar0, problem.loading);
  const CreepWeightedLoad& load = parts.load != nullptr ? *parts.load : *own_load;
  const double X_inf = load.final();

  // The two-level phase starts from a known state, with frozen radii (eq 9.18).
  const Lattice lattice{l};
  out.radii = NominalRadii{lattice.A1_single(), lattice.A_single()};
  out.X_start = load.initial();
  if (c.regime == Regime::never) {
    out.a1_inf = parts.a1_inf_single;
    out.a2_inf = 0.0;
    out.start = TwoLevelState{0.0, 0.0, 0.0, 0.0};
    const Violation v = check_state(out.a1_inf, 0.0, l, margin);
    if (v.code != Validity::valid) flag(out, v, kInf);
  } else {
    if (c.elastic_start) {
      out.radii = parts.elastic->radii;
      out.start = parts.elastic->state;
      out.start_ok = parts.elastic->converged;
    } else {
      out.t_start = c.t_star;
      out.X_start = c.X_star;
      out.start = TwoLevelState{c.a1_star, 0.0, l * l * c.X_star, 0.0};
      if (!problem.localization.is_paper()) out.radii = parts.branch->radii(out.start, c.X_star);
    }
    // Newton from the guide's guess (else by continuation from the start), whatever times a
    // caller samples: the long-term state is the same function of the point in a regime map
    // and in `punchsweep point`.
    TwoLevelSolve r{out.start, false};
    const bool periodic = problem.localization.periodic;
    if (out.start_ok && (std::isfinite(X_inf) || periodic)) {
      if (problem.localization.is_paper()) {
        const TwoLevelSystem system(problem, out.radii);
        if (const std::optional<TwoLevelState> guess = parts.guide->guess(X_inf, out.radii)) {
          r = system.solve(X_inf, *guess);
        }
        if (!r.converged) r = system.continue_to(out.start, out.X_start, X_inf);
      } else {
        // The family's radii follow the loads: its state is its branch's at X(inf).
        r = parts.branch->at(X_inf);
      }
    }
    out.a1_inf = r.converged ? r.state.a1 : kNaN;
    out.a2_inf = r.converged ? r.state.a2 : kNaN;
    const Violation at_start = check_state(out.start.a1, out.start.a2, l, margin);
    // Where a solve of the family fails, its branch ends where its spots merge (its states
    // keep the margin) or it has no solution: the last state it reached shows which.
    const auto stopped = [&](const TwoLevelState& last) {
      Violation v = check_state(last.a1, last.a2, l, margin * (1.0 - kMergeNear));
      v.limit /= 1.0 - kMergeNear;
      return margin < 1.0 && v.code != Validity::valid ? v : Violation{Validity::no_solution, kNaN, kNaN};
    };
    if (!out.start_ok) {
      flag(out, stopped(out.start), out.t_start);
    } else if (at_start.code != Validity::valid) {
      flag(out, at_start, out.t_start);
    } else if (!std::isfinite(X_inf) && !periodic) {
      // Unlimited creep: X grows without bound, and with it the spots, until they merge.
      flag(out, {Validity::same_level_overlap, kInf, l}, kInf);
    } else if (!r.converged) {
      flag(out, stopped(r.state), kInf);
    } else {
      const Violation v = check_state(out.a1_inf, out.a2_inf, l, margin);
      if (v.code != Validity::valid) flag(out, v, kInf);
    }
  }
  out.area_fraction_inf = area_fraction(out.a1_inf, out.a2_inf, l);
  if (problem.localization.periodic) flag_periodic(out, static_cast<const PeriodicBranch&>(*parts.branch), X_inf);
  // Whatever the flags say, no number that is not finite is ever called valid.
  if (out.valid()) {
    const bool finite = std::isfinite(out.h_0) && (std::isfinite(out.h_inf) || !std::isfinite(X_inf)) &&
                        std::isfinite(out.a1_inf) && std::isfinite(out.a2_inf) &&
                        std::isfinite(out.area_fraction_inf) && (!out.t_star || std::isfinite(*out.t_star));
    if (!finite) {
      flag_inaccurate(out, PointSummary::Invariant::not_finite, kNaN, kNaN, kInf);
    } else if (!radii_ordered(out.a1_inf, out.a2_inf)) {
      flag_inaccurate(out, PointSummary::Invariant::radii_order, out.a2_inf, out.a1_inf, kInf);
    }
  }
  return out;
}

ElasticTwoLevel solve_elastic_start(const ContactProblem& problem, const CreepLaw& creep, const LongTermGuide* guide,
                                    const TwoLevelBranch* branch) {
  if (problem.loading.is_step()) return solve_elastic(problem, 1.0 / creep.creep_initial(), guide, branch);
  ContactProblem at_once = problem;
  at_once.pbar0 = problem.pbar0 * problem.loading.jump();
  at_once.loading = LoadShape{};
  return solve_elastic(at_once, 1.0 / creep.creep_initial(), guide, branch);
}

DhParts dh_parts(const ContactProblem& problem) {
  DhParts parts;
  parts.touchdown = touchdown(problem);
  if (problem.localization.is_paper()) {
    parts.guide = std::make_shared<const LongTermGuide>(problem);
  } else if (problem.localization.periodic) {
    parts.periodic.emplace(problem, parts.touchdown);
  } else {
    parts.shells = make_branch(problem, parts.touchdown);
  }
  return parts;
}

SingleLevelEnds single_level_ends(const ContactProblem& problem, const CreepLaw& creep) {
  SingleLevelEnds ends;
  single_level_ends(problem, creep, &ends.h_0, &ends.h_inf, &ends.a1_inf_single);
  return ends;
}

PointSummary summarize_point(const ContactProblem& problem, const CreepLaw& creep, const DhParts& dh,
                             const SingleLevelEnds& ends, std::optional<ElasticTwoLevel>* elastic) {
  SummaryParts parts;
  parts.guide = dh.guide.get();
  parts.branch = dh.branch();
  const CreepWeightedLoad load(creep, problem.pbar0, problem.loading);
  parts.load = &load;
  parts.classification = classify(dh.touchdown, load);
  parts.h_0 = ends.h_0;
  parts.h_inf = ends.h_inf;
  parts.a1_inf_single = ends.a1_inf_single;
  std::optional<ElasticTwoLevel> own;
  std::optional<ElasticTwoLevel>& start = elastic != nullptr ? *elastic : own;
  if (parts.classification.elastic_start) {
    if (!start) start = solve_elastic_start(problem, creep, parts.guide, parts.branch);
    parts.elastic = &*start;
  }
  return summarize_point(problem, creep, parts);
}

PointSummary summarize_point(const ContactProblem& problem, const CreepLaw& creep) {
  return summarize_point(problem, creep, dh_parts(problem), single_level_ends(problem, creep));
}

PointResult evaluate_point(const ContactProblem& problem, const CreepLaw& creep,
                           const EvaluationOptions& options) {
  const DhParts dh = dh_parts(problem);
  return evaluate_point(problem, creep, options, summarize_point(problem, creep, dh, single_level_ends(problem, creep)),
                        dh.branch());
}

namespace {

/// The series of evaluate_point, with the two-level `system` of the problem's localization
/// (TwoLevelSystem at the frozen radii, or the family's ShellsBranch) and its single-level phase.
template <class System, class Single>
PointResult evaluate_series(const ContactProblem& problem, const CreepLaw& creep, const EvaluationOptions& options,
                            const PointSummary& summary, const System& system, const Single& single) {
  PointResult out;
  static_cast<PointSummary&>(out) = summary;
  const CreepWeightedLoad load(creep, problem.pbar0, problem.loading);
  const double level1_load = problem.pbar0 * problem.l * problem.l;  // L: Q1 = L g before touchdown
  const bool two_level = out.regime != Regime::never;
  const double t_start = out.t_start;

  std::vector<std::size_t> order(options.times.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return options.times[i] < options.times[j]; });
  const double t_max = options.times.empty() ? 0.0 : options.times[order.back()];

  std::optional<LoadHistory> history;
  bool history_skipped = false;
  if (two_level && out.start_ok && t_max >= t_start) {
    const LoadHistory::Cost cost = LoadHistory::cost(load, t_start, t_max, options.quadrature);
    history_skipped = cost.samples > LoadHistory::kMaxSamples || cost.kernel_pieces > LoadHistory::kMaxKernelPieces;
    if (history_skipped && out.valid()) {
      const double shortest = std::min(creep.creep_time_scale(), creep.relaxation_time_scale());
      flag_inaccurate(out, PointSummary::Invariant::history_cost, std::log10(std::max(t_max, 1.0 * shortest) / shortest),
                      0.0, t_start);
    }
  }
  if (two_level && out.start_ok && t_max >= t_start && !history_skipped) {
    // Along the history path a predictor in (X, a1, a2^2) from the last samples, quadratic
    // through three (secant through two at the start), leaves about one Newton evaluation
    // a sample; a2^2 rather than a2 because a2 ~ sqrt(X - X*) at touchdown. Samples at an
    // unchanged X (the load settled) do not enter it.
    std::array<TwoLevelState, 3> last{out.start, out.start, out.start};  // newest first
    std::array<double, 3> X_last{out.X_start, out.X_start, out.X_start};
    int known = 1;  // distinct X among last, at most 3
    history.emplace(load, level1_load, t_start, t_max, options.quadrature,
                    [&](double tau, double* Q1, double* Q2) {
                      const double X = load(tau);
                      TwoLevelSolve r{last[0], false};
                      if (known >= 2) {
                        // Lagrange weights of the known points at X.
                        std::array<double, 3> w{};
                        for (int i = 0; i < known; ++i) {
                          w[i] = 1.0;
                          for (int j = 0; j < known; ++j) {
                            if (j != i) w[i] *= (X - X_last[j]) / (X_last[i] - X_last[j]);
                          }
                        }
                        double a1 = 0.0;
                        double z = 0.0;
                        for (int i = 0; i < known; ++i) {
                          a1 += w[i] * last[i].a1;
                          z += w[i] * last[i].a2 * last[i].a2;
                        }
                        r = system.solve(X, TwoLevelState{a1, std::sqrt(std::max(z, 0.0)), 0.0, 0.0});
                      }
                      if (!r.converged) r = system.continue_to(last[0], X_last[0], X);
                      if (!r.converged) return false;
                      if (X > X_last[0]) {
                        last = {r.state, last[0], last[1]};
                        X_last = {X, X_last[0], X_last[1]};
                        known = std::min(known + 1, 3);
                      } else {
                        last[0] = r.state;
                      }
                      *Q1 = r.state.Q1;
                      *Q2 = r.state.Q2;
                      return true;
                    });
    out.history_samples = history->samples();
  }

  out.series.resize(options.times.size());
  TwoLevelState current = out.start;
  double X_current = out.X_start;
  bool current_ok = out.start_ok;
  for (const std::size_t i : order) {
    Snapshot& snap = out.series[i];
    snap.t = options.times[i];
    const double X = load(snap.t);
    // P1 + P2 = pbar(t) l^2: the nominal load on one cell at t.
    const double nominal_load = load.nominal_pressure(snap.t) * problem.l * problem.l;
    if (!two_level || snap.t < t_start) {
      snap.a1 = single.contact_radius(X);
      snap.a2 = 0.0;
      snap.P1 = nominal_load;
      snap.P2 = 0.0;
    } else {
      TwoLevelSolve r{current, false};
      if (current_ok) r = system.continue_to(current, X_current, X);
      if (r.converged && history_skipped) {
        current = r.state;
        X_current = X;
        snap.a1 = current.a1;
        snap.a2 = current.a2;
        snap.P1 = snap.P2 = kNaN;  // flagged history_cost above
      } else if (r.converged && history && history->ok()) {
        current = r.state;
        X_current = X;
        snap.a1 = current.a1;
        snap.a2 = current.a2;
        // For a narrow relaxation kernel the load history samples Q again just before t,
        // starting from the state at t.
        const TwoLevelState at_t = current;
        const auto near = [&](double tau, double* Q1, double* Q2) {
          const double X_tau = load(tau);
          TwoLevelSolve s = system.solve(X_tau, at_t);
          if (!s.converged) s = system.continue_to(at_t, X, X_tau);
          *Q1 = s.state.Q1;
          *Q2 = s.state.Q2;
          return s.converged;
        };
        if (!history->load(snap.t, current.Q1, current.Q2, &snap.P1, &snap.P2, near)) {
          if (out.valid()) flag(out, {Validity::no_solution, kNaN, kNaN}, snap.t);
          snap.P1 = snap.P2 = kNaN;
        }
      } else {
        current_ok = false;
        if (out.valid()) flag(out, {Validity::no_solution, kNaN, kNaN}, snap.t);
        snap.a1 = snap.a2 = snap.P1 = snap.P2 = kNaN;
      }
    }
    snap.area_fraction = area_fraction(snap.a1, snap.a2, problem.l);
    // The snapshot's invariants (docs/model.md, section 5): loads that sum to the nominal
    // load, finite values, 0 <= a2 <= a1.
    if (out.valid()) {
      const double sum = snap.P1 + snap.P2;
      if (!(std::isfinite(snap.a1) && std::isfinite(snap.a2) && std::isfinite(snap.P1) && std::isfinite(snap.P2))) {
        flag_inaccurate(out, PointSummary::Invariant::not_finite, kNaN, kNaN, snap.t);
      } else if (!(std::abs(sum - nominal_load) <= kLoadsTolerance * nominal_load)) {
        flag_inaccurate(out, PointSummary::Invariant::loads_sum, sum, nominal_load, snap.t);
      } else if (!radii_ordered(snap.a1, snap.a2)) {
        flag_inaccurate(out, PointSummary::Invariant::radii_order, snap.a2, snap.a1, snap.t);
      } else if (problem.localization.periodic && std::min(snap.P1, snap.P2) < -kPeriodicNegativeLoad * nominal_load) {
        flag(out, {Validity::unloading, std::min(snap.P1, snap.P2), 0.0}, snap.t);
      }
    }
    // The summary decided validity; a snapshot only tells how early a break is visible.
    if (!out.valid() && snap.t < out.first_seen && std::isfinite(snap.a1) &&
        check_state(snap.a1, snap.a2, problem.l, out.merge_margin).code != Validity::valid) {
      out.first_seen = snap.t;
    }
  }
  return out;
}

}  // namespace

PointResult evaluate_point(const ContactProblem& problem, const CreepLaw& creep, const EvaluationOptions& options,
                           const PointSummary& summary, const TwoLevelBranch* branch) {
  return visit_single_level(problem, [&](const auto& single) {
    if (problem.localization.is_paper()) {
      return evaluate_series(problem, creep, options, summary, TwoLevelSystem(problem, summary.radii), single);
    }
    if (branch != nullptr) return evaluate_series(problem, creep, options, summary, *branch, single);
    return evaluate_series(problem, creep, options, summary, *make_branch(problem, touchdown(problem)), single);
  });
}

}  // namespace punchsweep::model
