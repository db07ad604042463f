#include "model/surface/periodic_curve.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "model/numerics/integer_power.hpp"
#include "model/periodic/periodic_model.hpp"

namespace punchsweep::model {

namespace {

/// Level 2 touches within the tables' top, or never: they answer the lattice.
bool reaches(const PeriodicSolution& solution, double delta, double xi_star) {
  return !std::isfinite(xi_star) || delta <= solution.delta_top();
}

}  // namespace

bool periodic_curve_reaches(const PeriodicSolution& solution, const ContactProblem& problem) {
  const double delta = problem.dh / PeriodicScales(problem).h_unit;
  return reaches(solution, delta, solution.touchdown(delta));
}

std::optional<LoadCurve> periodic_load_curve(const PeriodicSolution& solution, const ContactProblem& problem) {
  const int s = problem.shape.s;
  const PeriodicScales scales(problem);
  const double delta = problem.dh / scales.h_unit;
  const double xi_star = solution.touchdown(delta);
  if (!reaches(solution, delta, xi_star)) return std::nullopt;
  const PeriodicSolution::Row row = solution.row(delta, xi_star);
  const bool touches = std::isfinite(xi_star);

  const double l2 = problem.l * problem.l;
  LoadCurve c;
  c.cell_area = l2;
  c.nx = c.ny = solution.tables().n;
  c.site_level = {0, 1};
  c.site_touchdown = {0.0, xi_star * scales.X_unit};
  c.level_touchdown = c.site_touchdown;
  c.s_tallest = s;
  c.X_resolved = 0.0;
  // A radius in l to an area in R^2.
  const auto area = [&](double a) { return std::numbers::pi * a * a * l2; };
  const auto add = [&](double xi, double area0, double area1, double Q1, double Q2) {
    c.samples.push_back({xi * scales.X_unit, {Q1, Q2}, {area0, area1}});
  };
  const auto add_single = [&](double xi) { add(xi, area(solution.single(xi).a1), 0.0, l2 * xi * scales.X_unit, 0.0); };
  const auto add_two = [&](double xi) {
    const PeriodicState state = solution.two_level(xi, row);
    // As the periodic model's branch: one height carries half each; Q1 the balance.
    const double Q2 = delta == 0.0 ? 0.5 * l2 * xi * scales.X_unit : scales.Q_unit * state.Q2;
    add(xi, area(state.a1), area(state.a2), l2 * xi * scales.X_unit - Q2, Q2);
  };

  // The single level, log-spaced up to the touchdown (or to the single level's full contact).
  const double xi_single_end = touches ? xi_star : solution.tables().xi_full_single();
  if (xi_single_end > kPeriodicCurveFirst) {
    const int count = static_cast<int>(std::ceil(std::log10(xi_single_end / kPeriodicCurveFirst) * kPeriodicCurvePerDecade));
    for (int k = 0; k < count; ++k) {
      add_single(kPeriodicCurveFirst * std::pow(xi_single_end / kPeriodicCurveFirst, static_cast<double>(k) / count));
    }
  }
  if (!touches) {
    add_single(xi_single_end);
    c.level_share = {1.0, 0.0};
  } else {
    // The two levels from the touchdown to the tables' full contact: log-spaced in xi - xi*
    // (the spots' first growth, over as many decades as the loads reach) and uniform in the
    // rows' variable (xi - xi*)^(1/(s+1)), as the tables are.
    const double top = ipow(row.table.w_full, s + 1);
    std::vector<double> excess;
    const int count = static_cast<int>(std::ceil(std::log10(top / kPeriodicCurveFirst) * kPeriodicCurvePerDecade));
    for (int k = 0; k <= count; ++k) excess.push_back(kPeriodicCurveFirst * std::pow(top / kPeriodicCurveFirst, static_cast<double>(k) / count));
    for (int k = 1; k <= kPeriodicCurveTwoLevel; ++k) excess.push_back(ipow(row.table.w_full * k / kPeriodicCurveTwoLevel, s + 1));
    std::sort(excess.begin(), excess.end());
    if (xi_star > 0.0) add_two(xi_star);
    for (const double e : excess) {
      if (c.samples.empty() || xi_star + e > c.samples.back().X / scales.X_unit) add_two(xi_star + e);
    }
    c.level_share = {1.0 - row.table.share2, row.table.share2};
  }
  c.X_full = c.samples.back().X;
  // Beyond its last sample the curve is full contact: the areas the levels' shares.
  c.samples.back().level_area = {c.level_share[0] * l2, c.level_share[1] * l2};
  for (std::size_t k = 0; k + 1 < c.samples.size(); ++k) {
    c.pressure_monotone.push_back(
        solution.pressure_monotone(c.samples[k].X / scales.X_unit, c.samples[k + 1].X / scales.X_unit, row) ? 1 : 0);
  }
  return c;
}

}  // namespace punchsweep::model
