#include "reference/reference_point.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "reference/contact_areas.hpp"
#include "reference/step_sizer.hpp"
#include "reference/viscoelastic_stepper.hpp"

namespace punchsweep::reference {

namespace {

/// Gap at the level-2 tip, dh + u(M) - delta: where level 2 touches first (there both the
/// profile and, in the single-level phase, the displacement are least).
double tip2_gap(const TwoLevelCell& cell, const ViscoelasticStepper& stepper) {
  return cell.profile[cell.tip2] + stepper.displacement()[cell.tip2] - stepper.approach();
}

/// Bookkeeping of the solves of one point.
struct SolveLog {
  ReferenceResult* result;
  void operator()(const ContactStatus& status) const {
    ++result->solves;
    result->cg_iterations += status.iterations;
    result->max_residual = std::max(result->max_residual, status.residual);
    result->converged = result->converged && status.converged;
  }
};

}  // namespace

std::string options_error(const ReferenceOptions& options) {
  std::ostringstream out;
  if (const std::string e = two_level_grid_error(options.n); !e.empty()) return e;
  for (const double t : options.times) {
    if (!(std::isfinite(t) && t >= 0.0)) {
      out << "snapshot time " << t << " is outside its range: finite and >= 0";
      return out.str();
    }
  }
  const StepControl& s = options.steps;
  if (!(std::isfinite(s.first_step) && s.first_step > 0.0 && std::isfinite(s.growth) &&
        s.growth >= 1.0 && std::isfinite(s.max_step) && s.max_step >= s.first_step)) {
    out << "steps (first " << s.first_step << ", growth " << s.growth << ", max " << s.max_step
        << ") are outside their range: first > 0, growth >= 1, max >= first";
    return out.str();
  }
  if (!(options.t_star_resolution > 0.0)) {
    out << "t_star_resolution = " << options.t_star_resolution << " is outside its range: > 0";
    return out.str();
  }
  if (!(options.solver.tolerance > 0.0) || options.solver.max_iterations < 1) {
    out << "solver tolerance " << options.solver.tolerance << " / max_iterations "
        << options.solver.max_iterations << " are outside their range: > 0 / >= 1";
    return out.str();
  }
  return {};
}

ContactAreas contact_areas(const TwoLevelCell& cell, std::span<const double> p, std::span<const double> rims) {
  const std::vector<double> areas = level_contact_areas(cell.grid, {cell.level2_weight}, p, rims);
  return {areas[0], areas[1]};
}

ReferenceSnapshot measure_state(const TwoLevelCell& cell, std::span<const double> p,
                                std::span<const double> rims, std::span<const double> u, double t) {
  ReferenceSnapshot s;
  s.t = t;
  const std::vector<double> loads = level_loads(cell.grid, {cell.level2_weight}, p);
  s.P1 = loads[0];
  s.P2 = loads[1];
  const ContactAreas areas = contact_areas(cell, p, rims);
  s.area1 = areas.level1;
  s.area2 = areas.level2;
  s.a1 = std::sqrt(s.area1 / std::numbers::pi);
  s.a2 = std::sqrt(s.area2 / std::numbers::pi);
  s.area_fraction = (s.area1 + s.area2) / (cell.grid.Lx * cell.grid.Ly);
  s.h = u[cell.tip1] - u[cell.tip2];
  return s;
}

bool level2_loaded(const TwoLevelCell& cell, std::span<const double> p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (cell.level2_node[i] && p[i] > 0.0) return true;
  }
  return false;
}

void scale_steps_to_law(const model::CreepLaw& creep, ReferenceOptions* options) {
  double shortest = creep.creep_time_scale();
  double longest = shortest;
  if (const std::optional<model::RetardationSeries> series = creep.retardation_series()) {
    for (const model::RetardationSeries::Term& term : series->terms) {
      shortest = std::min(shortest, term.lambda);
      longest = std::max(longest, term.lambda);
    }
  }
  const StepControl defaults{};
  options->steps.first_step = defaults.first_step * shortest;
  options->steps.max_step = defaults.max_step * longest;
  options->t_star_resolution = ReferenceOptions{}.t_star_resolution * shortest;
}

ReferenceResult evaluate_reference_point(const model::ContactProblem& problem,
                                         const model::CreepLaw& creep,
                                         const ReferenceOptions& options) {
  if (const std::string e = model::problem_error(problem); !e.empty())
    throw std::invalid_argument(e);
  if (const std::string e = options_error(options); !e.empty()) throw std::invalid_argument(e);

  const TwoLevelCell cell = make_two_level_cell(problem, options.n, options.symmetry);
  ReferenceResult result;
  result.spacing = cell.grid.hx();
  const SolveLog log{&result};

  std::vector<double> targets = options.times;
  std::sort(targets.begin(), targets.end());
  targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
  std::vector<ReferenceSnapshot> at_target;
  at_target.reserve(targets.size());

  ViscoelasticStepper stepper(cell.grid, cell.profile, problem.pbar0, creep, options.solver, problem.loading);
  // A ramp or table is linear between its kinks: the steps land on them.
  const std::vector<double> kinks = problem.loading.kinks();
  const auto next_kink = [&](double t) {
    for (const double k : kinks) {
      if (k > t) return k;
    }
    return std::numeric_limits<double>::infinity();
  };
  log(stepper.start());
  bool touched = level2_loaded(cell, stepper.pressure());
  if (touched) {
    result.regime = model::Regime::immediate;
    result.t_star = 0.0;
    result.t_star_upper = 0.0;
  }
  // The last two states with level 2 free, (t, tip gap): their secant extrapolates t*
  // (a parabola through three aimed the trials no better, measured).
  double t_a = 0.0, g_a = 0.0;
  double t_b = 0.0, g_b = tip2_gap(cell, stepper);
  bool have_a = false;
  auto remember_free_state = [&]() {
    t_a = t_b;
    g_a = g_b;
    have_a = true;
    t_b = stepper.time();
    g_b = tip2_gap(cell, stepper);
  };
  const auto secant_ready = [&]() { return have_a && g_a > g_b && t_b > t_a; };
  const auto aim = [&]() { return t_b + g_b * (t_b - t_a) / (g_a - g_b); };  // the secant's zero

  StepSizer sizer(options.steps, creep, problem.loading.rise_time());
  for (const double target : targets) {
    while (stepper.time() < target) {
      options.stop.throw_if_requested();
      const double t_next = sizer.next(stepper.time(), std::min(target, next_kink(stepper.time())));
      if (touched) {
        log(stepper.advance(t_next));
        ++result.steps;
        sizer.accepted();
        continue;
      }
      ViscoelasticStepper::Checkpoint free_state = stepper.checkpoint();
      log(stepper.advance(t_next));
      ++result.steps;
      if (!level2_loaded(cell, stepper.pressure())) {
        remember_free_state();
        sizer.accepted();
        continue;
      }
      // The step first loads level 2: narrow it, keeping the states with level 2 free. A
      // trial aims just short of the touchdown that the tip gap extrapolates to, until the
      // latest free state is that close, then just past it, so that the bracket usually
      // closes on a loaded state (nothing to take again); an aim that misses its side
      // makes the next trial the midpoint.
      double lo = free_state.t;
      double hi = t_next;
      const double offset = 0.45 * options.t_star_resolution;
      bool halve = false;
      while (hi - lo > options.t_star_resolution) {
        double trial = 0.5 * (lo + hi);
        bool aim_above = true;  // a midpoint's outcome is no miss either way
        if (!halve && secant_ready()) {
          const double predicted = aim();
          aim_above = predicted - offset - lo <= 0.1 * options.t_star_resolution;
          const double margin = std::min(0.1 * options.t_star_resolution, 0.25 * (hi - lo));
          trial = std::clamp(predicted + (aim_above ? offset : -offset), lo + margin, hi - margin);
        }
        // A resolution below the rounding of t (a law whose shortest time is 1e-14 s, t*
        // near 1e-5 s) leaves no time strictly inside the bracket: it is as narrow as the
        // times can be.
        if (!(trial > lo && trial < hi)) break;
        if (stepper.time() != lo) stepper.rewind(free_state);
        log(stepper.advance(trial));
        const bool loaded = level2_loaded(cell, stepper.pressure());
        halve = !halve && loaded != aim_above;  // the aim missed its side
        if (loaded) {
          hi = trial;
        } else {
          lo = trial;
          ++result.steps;
          remember_free_state();
          free_state = stepper.checkpoint();
        }
      }
      // A state at hi was reached from the latest free state in one step: keep it. Only
      // when the last trial left level 2 free is the step to hi taken again.
      if (stepper.time() == lo) log(stepper.advance(hi));
      touched = level2_loaded(cell, stepper.pressure());
      if (touched) {
        result.t_star_lower = lo;
        result.t_star_upper = hi;
        double t_star = 0.5 * (lo + hi);
        if (secant_ready()) t_star = aim();  // secant on the tip gap
        result.t_star = std::clamp(t_star, lo, hi);
        // As the model says it (model/contact/regime.hpp): touching while the load still rises
        // is immediate, during the hold delayed.
        const double rise = problem.loading.rise_time();
        result.regime = rise > 0.0 && *result.t_star <= rise ? model::Regime::immediate : model::Regime::delayed;
      } else {
        remember_free_state();
      }
      sizer.accepted();
    }
    at_target.push_back(
        measure_state(cell, stepper.pressure(), stepper.creep_pressure(), stepper.displacement(), target));
  }

  if (!touched) {
    result.t_star_lower = stepper.time();
    // Beyond the horizon: the long-term contact set is the elastic one at J(inf).
    const double J_inf = creep.creep_final();
    if (std::isfinite(J_inf)) {
      ContactSolver solver(cell.grid, options.solver);
      std::vector<double> p(stepper.pressure().begin(), stepper.pressure().end());
      std::vector<double> u(p.size());
      log(solver.solve(cell.profile, problem.pbar0, J_inf, p, u));
      result.regime = level2_loaded(cell, p) ? model::Regime::delayed : model::Regime::never;
    } else {
      result.regime = model::Regime::delayed;
    }
  }

  result.series.reserve(options.times.size());
  for (const double t : options.times) {
    const auto it = std::lower_bound(targets.begin(), targets.end(), t);
    result.series.push_back(at_target[static_cast<std::size_t>(it - targets.begin())]);
  }
  return result;
}

double elastic_touchdown_compliance(const model::ContactProblem& problem, int n, double J_lo,
                                    double J_hi, double width,
                                    const ContactSolverOptions& options) {
  const TwoLevelCell cell = make_two_level_cell(problem, n);
  ContactSolver solver(cell.grid, options);
  std::vector<double> p(cell.grid.size(), problem.pbar0);
  std::vector<double> u(cell.grid.size());
  auto loaded_at = [&](double J) {
    std::fill(p.begin(), p.end(), problem.pbar0);
    solver.solve(cell.profile, problem.pbar0, J, p, u);
    return level2_loaded(cell, p);
  };
  if (loaded_at(J_lo)) return J_lo;
  if (!loaded_at(J_hi)) return std::numeric_limits<double>::infinity();
  while (J_hi - J_lo > width) {
    const double mid = 0.5 * (J_lo + J_hi);
    if (loaded_at(mid))
      J_hi = mid;
    else
      J_lo = mid;
  }
  return 0.5 * (J_lo + J_hi);
}

model::PointResult as_point_result(const ReferenceResult& result) {
  model::PointResult point;
  point.regime = result.regime;
  point.t_star = result.t_star;
  point.solver = {result.converged, static_cast<double>(result.cg_iterations), result.max_residual};
  point.series.reserve(result.series.size());
  for (const ReferenceSnapshot& snap : result.series) {
    point.series.push_back(model::Snapshot{snap.t, snap.a1, snap.a2, snap.P1, snap.P2, snap.area_fraction});
  }
  return point;
}

}  // namespace punchsweep::reference
