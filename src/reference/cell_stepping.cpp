#include "reference/cell_stepping.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "reference/contact_areas.hpp"
#include "reference/viscoelastic_stepper.hpp"

namespace punchsweep::reference {

namespace {

CellSnapshot measure(const Cell& cell, const std::vector<double>& touch, const ViscoelasticStepper& stepper, double t) {
  const PeriodicGrid& g = cell.grid;
  CellSnapshot s;
  s.t = t;
  s.level_load = level_loads(g, cell.level_weight, stepper.pressure());
  s.level_area = level_contact_areas(g, cell.level_weight, stepper.pressure(), stepper.creep_pressure());
  double area = 0.0;
  for (double a : s.level_area) area += a;
  s.area_fraction = area / (g.Lx * g.Ly);
  double touched = 0.0;
  for (double t_touch : touch) touched += t_touch <= t ? 1.0 : 0.0;
  s.sites_touched = touched / static_cast<double>(touch.size());
  return s;
}

}  // namespace

CellReference evaluate_cell_reference(const model::CellGeometry& geometry, const Cell& cell, double pbar0,
                                      const model::CreepLaw& creep, const model::LoadShape& loading,
                                      const CellReferenceOptions& options) {
  if (!(pbar0 > 0.0) || !(options.t_star_resolution > 0.0) || options.times.empty() ||
      !std::is_sorted(options.times.begin(), options.times.end()) || options.times.front() < 0.0) {
    throw std::invalid_argument("evaluate_cell_reference: pbar0 > 0, resolution > 0, times >= 0 increasing");
  }
  if (cell.tips.size() != geometry.sites.size()) throw std::invalid_argument("evaluate_cell_reference: the cell is not the geometry's");
  const std::size_t sites = geometry.sites.size();
  CellReference result;
  const auto log = [&](const ContactStatus& status) {
    ++result.solves;
    result.converged = result.converged && status.converged;
  };
  ViscoelasticStepper stepper(cell.grid, cell.profile, pbar0, creep, options.solver, loading);
  const std::vector<double> kinks = loading.kinks();
  const auto next_kink = [&](double t) {
    for (const double k : kinks) {
      if (k > t) return k;
    }
    return std::numeric_limits<double>::infinity();
  };
  double least_drop = std::numeric_limits<double>::infinity();
  for (const model::Site& site : geometry.sites) least_drop = std::min(least_drop, site.drop);
  result.site_touch.assign(sites, std::numeric_limits<double>::infinity());
  const auto pressed = [&](std::size_t k) { return cell.touched(k, stepper.pressure()); };
  // The sites untouched so far whose tips the present state presses.
  const auto newly_pressed = [&]() {
    std::vector<std::size_t> out;
    for (std::size_t k = 0; k < sites; ++k) {
      if (std::isinf(result.site_touch[k]) && pressed(k)) out.push_back(k);
    }
    return out;
  };
  log(stepper.start());
  for (std::size_t k = 0; k < sites; ++k) {
    if ((geometry.sites[k].drop == least_drop && cell.tip_exposed[k] != 0) || pressed(k)) result.site_touch[k] = 0.0;
  }
  StepSizer sizer(options.steps, creep, loading.rise_time());
  for (const double target : options.times) {
    while (stepper.time() < target) {
      options.stop.throw_if_requested();
      const double t_next = sizer.next(stepper.time(), std::min(target, next_kink(stepper.time())));
      ViscoelasticStepper::Checkpoint free_state = stepper.checkpoint();
      log(stepper.advance(t_next));
      ++result.steps;
      if (newly_pressed().empty()) {
        sizer.accepted();
        continue;
      }
      // Narrow the step to the first new touch: halve, keeping the latest state before it.
      double lo = free_state.t, hi = t_next;
      while (hi - lo > options.t_star_resolution) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        if (stepper.time() != lo) stepper.rewind(free_state);
        log(stepper.advance(mid));
        if (!newly_pressed().empty()) {
          hi = mid;
        } else {
          lo = mid;
          ++result.steps;
          free_state = stepper.checkpoint();
        }
      }
      if (stepper.time() == lo) log(stepper.advance(hi));
      for (const std::size_t k : newly_pressed()) result.site_touch[k] = 0.5 * (lo + hi);
      sizer.accepted();
    }
    result.series.push_back(measure(cell, result.site_touch, stepper, target));
  }
  // Each level: its first site's touch; one untouched by the last time is decided by the
  // long-term state (elastic at J(inf)) where J(inf) is finite.
  const int levels = geometry.levels();
  std::vector<char> long_term(sites, 0);
  const double J_inf = creep.creep_final();
  if (std::isfinite(J_inf) && std::any_of(result.site_touch.begin(), result.site_touch.end(), [](double t) { return std::isinf(t); })) {
    ContactSolver solver(cell.grid, options.solver);
    std::vector<double> p(stepper.pressure().begin(), stepper.pressure().end()), u(p.size());
    log(solver.solve(cell.profile, pbar0, J_inf, p, u));
    for (std::size_t k = 0; k < sites; ++k) long_term[k] = cell.touched(k, p);
  }
  const double rise = loading.rise_time();
  for (int level = 0; level < levels; ++level) {
    double first = std::numeric_limits<double>::infinity();
    bool ever = !std::isfinite(J_inf);
    for (std::size_t k = 0; k < sites; ++k) {
      if (geometry.sites[k].level != level) continue;
      first = std::min(first, result.site_touch[k]);
      ever = ever || long_term[k];
    }
    model::Regime regime = model::Regime::delayed;
    if (first == 0.0 || (rise > 0.0 && first <= rise)) {
      regime = model::Regime::immediate;
    } else if (std::isinf(first) && !ever) {
      regime = model::Regime::never;
    }
    result.level_regime.push_back(regime);
    result.level_t_star.push_back(first);
  }
  return result;
}

}  // namespace punchsweep::reference
