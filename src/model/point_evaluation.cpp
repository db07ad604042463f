#include "model/point_evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <optional>
#include <sstream>

#include "model/lattice.hpp"
#include "model/single_level.hpp"

namespace punchsweep::model {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// Keeps the earliest reason a point cannot be trusted (model notes, section 7).
class ValidityTracker {
 public:
  ValidityTracker(PointResult& out, double l) : out_(out), l_(l) {}

  void check_state(double t, double a1, double a2) {
    const double widest = 2.0 * std::max(a1, a2);
    if (widest >= l_) {
      flag(Validity::same_level_overlap, t, widest, l_);
    } else if (a1 + a2 >= l_ / std::numbers::sqrt2) {
      flag(Validity::cross_level_overlap, t, a1 + a2, l_ / std::numbers::sqrt2);
    }
  }
  void no_solution(double t) { flag(Validity::no_solution, t, kNaN, kNaN); }

 private:
  void flag(Validity v, double t, double value, double limit) {
    if (out_.validity != Validity::valid) return;
    out_.validity = v;
    out_.invalid_at = t;
    out_.violation_value = value;
    out_.violation_limit = limit;
  }
  PointResult& out_;
  double l_;
};

double area_fraction(double a1, double a2, double l) {
  return std::numbers::pi * (a1 * a1 + a2 * a2) / (l * l);
}

}  // namespace

std::string PointResult::reason() const {
  if (validity == Validity::valid) return {};
  std::ostringstream out;
  out.precision(6);
  std::ostringstream time;
  time.precision(6);
  time << invalid_at;
  const std::string when = std::isinf(invalid_at) ? std::string("in the long-term state (t -> infinity)")
                                                  : "by t = " + time.str() + " T_eps";
  switch (validity) {
    case Validity::same_level_overlap:
      out << "spots of one level merge " << when << ": 2 a_i = " << violation_value
          << " R >= l = " << violation_limit << " R (localization needs separate spots)";
      break;
    case Validity::cross_level_overlap:
      out << "level-1 and level-2 spots merge " << when << ": a1 + a2 = " << violation_value
          << " R >= l/sqrt(2) = " << violation_limit << " R (localization needs separate spots)";
      break;
    case Validity::no_solution:
      out << "the two-level equations have no admissible solution " << when;
      break;
    case Validity::valid: break;
  }
  return out.str();
}

PointResult evaluate_point(const ContactProblem& problem, const CreepLaw& creep,
                           const EvaluationOptions& options) {
  PointResult out;
  ValidityTracker tracker(out, problem.l);
  const SingleLevel single(problem.l, problem.shape);
  const double pbar0 = problem.pbar0;
  const double level1_load = pbar0 * problem.l * problem.l;  // P1 while only level 1 touches

  const double X0 = pbar0 * creep.creep_initial();
  const double X_inf = pbar0 * creep.creep_final();
  out.h_0 = single.displacement_difference(single.contact_radius(X0), X0);
  const double a1_inf_single = single.contact_radius(X_inf);
  out.h_inf = std::isfinite(X_inf) ? single.displacement_difference(a1_inf_single, X_inf) : kInf;

  const Classification c = classify(problem, creep);
  out.regime = c.regime;
  if (c.regime != Regime::never) out.t_star = c.t_star;

  // The two-level phase starts at t_start from a known state, with frozen radii (eq 9.18).
  const Lattice lattice{problem.l};
  out.radii = NominalRadii{lattice.A1_single(), lattice.A_single()};
  const bool two_level = c.regime != Regime::never;
  double t_start = 0.0;
  double X_start = X0;
  TwoLevelState start;
  bool start_ok = true;
  if (c.regime == Regime::immediate) {
    const ElasticTwoLevel elastic = solve_elastic_two_level(problem, 1.0 / creep.creep_initial());
    out.radii = elastic.radii;
    start = elastic.state;
    start_ok = elastic.converged;
  } else if (c.regime == Regime::delayed) {
    t_start = c.t_star;
    X_start = pbar0 * c.J_star;
    start = TwoLevelState{c.a1_star, 0.0, problem.l * problem.l * X_start, 0.0};
  }
  const TwoLevelSystem system(problem, out.radii);
  if (two_level) {
    if (start_ok) tracker.check_state(t_start, start.a1, start.a2);
    else tracker.no_solution(t_start);
  }

  std::vector<std::size_t> order(options.times.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return options.times[i] < options.times[j]; });
  const double t_max = options.times.empty() ? 0.0 : options.times[order.back()];

  std::optional<LoadHistory> history;
  if (two_level && start_ok && t_max >= t_start) {
    // Along the history path, a secant predictor in (X, a1, a2^2) from the last two samples
    // halves the Newton work; a2^2 rather than a2 because a2 ~ sqrt(X - X*) at touchdown.
    TwoLevelState current = start;
    TwoLevelState previous = start;
    double X_current = X_start;
    double X_previous = X_start;
    history.emplace(creep, level1_load, t_start, t_max, options.quadrature,
                    [&](double tau, double* Q1, double* Q2) {
                      const double X = pbar0 * creep.creep(tau);
                      TwoLevelSolve r{current, false};
                      if (X_current > X_previous) {
                        const double w = (X - X_current) / (X_current - X_previous);
                        const double z = current.a2 * current.a2 +
                                         w * (current.a2 * current.a2 - previous.a2 * previous.a2);
                        const TwoLevelState guess{current.a1 + w * (current.a1 - previous.a1),
                                                  std::sqrt(std::max(z, 0.0)), 0.0, 0.0};
                        r = system.solve(X, guess);
                      }
                      if (!r.converged) r = system.continue_to(current, X_current, X);
                      if (!r.converged) return false;
                      previous = current;
                      X_previous = X_current;
                      current = r.state;
                      X_current = X;
                      *Q1 = current.Q1;
                      *Q2 = current.Q2;
                      return true;
                    });
    out.history_samples = history->samples();
  }

  out.series.resize(options.times.size());
  TwoLevelState current = start;
  double X_current = X_start;
  bool current_ok = start_ok;
  for (const std::size_t i : order) {
    Snapshot& snap = out.series[i];
    snap.t = options.times[i];
    const double X = pbar0 * creep.creep(snap.t);
    if (!two_level || snap.t < t_start) {
      snap.a1 = single.contact_radius(X);
      snap.a2 = 0.0;
      snap.P1 = level1_load;
      snap.P2 = 0.0;
    } else {
      TwoLevelSolve r{current, false};
      if (current_ok) r = system.continue_to(current, X_current, X);
      if (r.converged && history && history->ok()) {
        current = r.state;
        X_current = X;
        snap.a1 = current.a1;
        snap.a2 = current.a2;
        history->load(snap.t, current.Q1, current.Q2, &snap.P1, &snap.P2);
      } else {
        current_ok = false;
        tracker.no_solution(snap.t);
        snap.a1 = snap.a2 = snap.P1 = snap.P2 = kNaN;
      }
    }
    snap.area_fraction = area_fraction(snap.a1, snap.a2, problem.l);
    if (std::isfinite(snap.a1)) tracker.check_state(snap.t, snap.a1, snap.a2);
  }

  if (!two_level) {
    out.a1_inf = a1_inf_single;
    out.a2_inf = 0.0;
  } else {
    TwoLevelSolve r{current, false};
    if (current_ok && std::isfinite(X_inf)) r = system.continue_to(current, X_current, X_inf);
    if (r.converged) {
      out.a1_inf = r.state.a1;
      out.a2_inf = r.state.a2;
    } else {
      out.a1_inf = out.a2_inf = kNaN;
      tracker.no_solution(kInf);
    }
  }
  out.area_fraction_inf = area_fraction(out.a1_inf, out.a2_inf, problem.l);
  if (std::isfinite(out.a1_inf)) tracker.check_state(kInf, out.a1_inf, out.a2_inf);
  return out;
}

}  // namespace punchsweep::model
