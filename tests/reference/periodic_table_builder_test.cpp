// The periodic model's tables (docs/model.md, section 14): the scaling that makes one table
// per s serve every (l, C), the table's own bookkeeping, and its interpolation against direct
// boundary-element solves between its samples.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "model/problem/contact_problem.hpp"
#include "model/periodic/periodic_table.hpp"
#include "reference/contact_solver.hpp"
#include "reference/periodic_grid.hpp"
#include "reference/periodic_table_builder.hpp"
#include "reference/reference_point.hpp"

using namespace punchsweep;
using namespace punchsweep::reference;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A small table, built once for the file (n = 64: about a second).
const model::PeriodicTable& small_table() {
  static const model::PeriodicTable table = [] {
    PeriodicTableOptions o;
    o.n = 64;
    o.single_samples = 49;
    o.deltas = 17;
    o.r_samples = 17;
    return build_periodic_table(2, o);
  }();
  return table;
}

}  // namespace

// Section 12.2: with xi = X / (C l^(s-1)) and delta = dh / (C l^s), the elastic solution of
// the cell (l, C) at load X has h / (C l^s), a_i / l and Q_i / (C l^(s+1)) equal to the
// scaled cell's (l = 1, C = 1) at (xi, delta), on the same grid: the discrete problems are
// the same up to the two scale factors.
TEST(PeriodicScaling, one_scaled_solution_serves_every_pitch_and_shape_constant) {
  for (const int s : {1, 2, 3}) {
    for (const auto& [l, C] : {std::pair{0.75, 0.5}, std::pair{1.0, 0.5}, std::pair{0.6, 1.3}}) {
      const double X = 0.04, dh = 0.3 * C * std::pow(l, s);
      const model::ContactProblem problem{l, dh, X, {s, C}};
      const TwoLevelCell cell = make_two_level_cell(problem, 64, Symmetry::mirror);
      ContactSolver solver(cell.grid);
      std::vector<double> p(cell.grid.size(), 0.0), u(cell.grid.size());
      ASSERT_TRUE(solver.solve(cell.profile, X, 1.0, p, u).converged);
      const ReferenceSnapshot real = measure_state(cell, p, p, u, 0.0);
      const model::PeriodicState scaled =
          solve_scaled(s, X / (C * std::pow(l, s - 1)), dh / (C * std::pow(l, s)), 64);
      EXPECT_NEAR(real.a1 / l, scaled.a1, 1e-12) << "s " << s << " l " << l << " C " << C;
      EXPECT_NEAR(real.a2 / l, scaled.a2, 1e-12);
      const double Q = C * std::pow(l, s + 1);
      EXPECT_NEAR(real.P1 / Q, scaled.Q1, 1e-9 * scaled.Q1);
      EXPECT_NEAR(real.P2 / Q, scaled.Q2, 1e-9 * scaled.Q1);
    }
  }
}

TEST(PeriodicTable, bookkeeping_round_trips_and_balances_the_load) {
  const model::PeriodicTable& t = small_table();
  const std::optional<model::PeriodicTable> back = model::PeriodicTable::from_tables(t.tables());
  ASSERT_TRUE(back);
  EXPECT_EQ(back->tables(), t.tables());
  // Q1 + Q2 = xi: the cell's load balance, exactly as the table returns it.
  for (const double xi : {0.01, 0.3, 1.7, 9.0}) {
    for (const double delta : {0.0, 0.1, 0.4}) {
      const std::optional<double> star = t.touchdown(delta);
      ASSERT_TRUE(star);
      if (xi < *star) continue;
      const model::PeriodicState s = t.two_level(xi, delta);
      EXPECT_DOUBLE_EQ(s.Q1 + s.Q2, xi);
      EXPECT_TRUE(s.in_range);
      EXPECT_GE(s.a1, s.a2 * (1.0 - 1e-12));  // equal at delta = 0, to round-off
    }
  }
  // Level 2 hides under level 1 from delta = 2^(-s/2) on: it never touches.
  EXPECT_EQ(*t.touchdown(0.5), kInf);
  EXPECT_FALSE(t.two_level(1.0, 0.498).in_range);  // above delta_top = 0.99 / 2
  // Edited rows fail the bookkeeping: a touchdown that is not the single level's.
  std::vector<double> numbers = t.tables();
  model::PeriodicTable edited = t;
  edited.xi_star[3] *= 1.0 + 1e-9;
  EXPECT_FALSE(model::PeriodicTable::from_tables(edited.tables()));
  numbers[1] = 0.5;  // s
  EXPECT_FALSE(model::PeriodicTable::from_tables(numbers));
  numbers = t.tables();
  numbers.pop_back();
  EXPECT_FALSE(model::PeriodicTable::from_tables(numbers));
}

// Beyond the load at which every node touches the areas stay and the extra load spreads
// evenly: Q2 grows by the level-2 share of the cell per unit xi.
TEST(PeriodicTable, full_contact_spreads_extra_load_by_the_shares) {
  const model::PeriodicTable& t = small_table();
  const double delta = 0.1;
  const model::PeriodicState a = t.two_level(20.0, delta), b = t.two_level(30.0, delta);
  EXPECT_EQ(a.a1, b.a1);
  EXPECT_EQ(a.a2, b.a2);
  const double share = (b.Q2 - a.Q2) / 10.0;
  EXPECT_NEAR(std::numbers::pi * b.a2 * b.a2, share, 1e-3);
  EXPECT_NEAR(std::numbers::pi * (b.a1 * b.a1 + b.a2 * b.a2), 1.0, 1e-3);
}

// Between the samples, against direct solves on the table's own grid, at this small table's
// coarse grid and sampling (the shipped tables: tests/tables): h to 5e-4, the loads to 3e-3
// of xi and the radii to three grid spacings (a spot's rim moves by whole nodes).
TEST(PeriodicTable, interpolation_meets_direct_solves_between_samples) {
  const model::PeriodicTable& t = small_table();
  std::mt19937_64 random(23);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 8; ++trial) {
    const double xi = std::exp(std::log(0.01) + unit(random) * std::log(300.0));
    const model::PeriodicState table = t.single(xi), direct = solve_scaled(2, xi, kInf, t.n);
    EXPECT_NEAR(table.h, direct.h, 5e-4 * direct.h) << "xi " << xi;
    EXPECT_NEAR(table.a1, direct.a1, 3.0 / t.n) << "xi " << xi;
  }
  for (int trial = 0; trial < 8; ++trial) {
    const double delta = unit(random) * t.delta_top;
    const double star = *t.touchdown(delta);
    const double xi = star + std::pow(unit(random), 3) * 2.0;
    const model::PeriodicState table = t.two_level(xi, delta), direct = solve_scaled(2, xi, delta, t.n);
    EXPECT_NEAR(table.Q2, direct.Q2, 3e-3 * xi) << "xi " << xi << " delta " << delta;
    EXPECT_NEAR(table.a1, direct.a1, 3.0 / t.n) << "xi " << xi << " delta " << delta;
    EXPECT_NEAR(table.a2, direct.a2, 3.0 / t.n) << "xi " << xi << " delta " << delta;
  }
}
