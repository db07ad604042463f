// Each level's touchdown in a cell of any geometry (issue 38: the elastic load curve's
// first piece), from direct boundary-element solves on make_cell's grid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

#include "model/problem/cell_geometry.hpp"
#include "reference/cell_touchdown.hpp"
#include "reference/contact_solver.hpp"
#include "reference/periodic_grid.hpp"

using namespace punchsweep;
using namespace punchsweep::reference;

namespace {

// Three levels of spherical caps on the square lattice: the corner's, the centre's 0.01 R
// lower, the edges' midpoints' 0.03 R lower.
model::CellGeometry three_levels() {
  const model::Shape cap{2, 0.5};
  const double l = 0.75;
  return {l, l, {{0.0, 0.0, cap, 0.0, 0}, {0.5 * l, 0.5 * l, cap, 0.01, 1}, {0.5 * l, 0.0, cap, 0.03, 2},
                 {0.0, 0.5 * l, cap, 0.03, 2}}};
}

}  // namespace

TEST(CellTouchdown, three_levels_touch_in_order_and_the_loads_balance) {
  const model::CellGeometry g = three_levels();
  const Cell cell = make_cell(g, PeriodicGrid::square(64, g.Lx, Symmetry::mirror));
  const std::vector<double> X = level_touchdowns(g, cell, 1.0, 1e-7);
  ASSERT_EQ(X.size(), 3u);
  std::printf("touchdowns: level 1 at X = %.6g, level 2 at X = %.6g E0*\n", X[1], X[2]);
  EXPECT_EQ(X[0], 0.0);
  EXPECT_GT(X[1], 0.0);
  EXPECT_GT(X[2], X[1]);  // the lower level touches under more load
  ContactSolver solver(cell.grid);
  for (const double at : {0.5 * X[1], 0.5 * (X[1] + X[2]), 2.0 * X[2]}) {
    const CellState s = cell_state(g, cell, solver, at);
    ASSERT_TRUE(s.status.converged);
    // The levels' loads make the cell's: X Lx Ly.
    const double total = std::accumulate(s.level_load.begin(), s.level_load.end(), 0.0);
    EXPECT_NEAR(total, at * g.Lx * g.Ly, 1e-9 * at * g.Lx * g.Ly);
    // A level carries load only once it has touched (past its touchdown: more than a
    // thousandth of the cell's load; before it: none).
    for (int level = 1; level <= 2; ++level) {
      if (at < X[level]) {
        EXPECT_EQ(s.level_load[level], 0.0) << "level " << level << " at X = " << at;
      } else {
        EXPECT_GT(s.level_load[level], 1e-3 * total) << "level " << level << " at X = " << at;
      }
    }
  }
  // Just either side of each touchdown, h_L against the drop.
  for (int level = 1; level <= 2; ++level) {
    const double drop = g.sites[level == 1 ? 1 : 2].drop;
    EXPECT_LT(cell_state(g, cell, solver, X[level] * (1 - 1e-5)).h[level], drop);
    EXPECT_NEAR(cell_state(g, cell, solver, X[level] * (1 + 1e-5)).h[level], drop, 1e-9 * drop);
  }
  // A level that needs more than X_max says so.
  EXPECT_TRUE(std::isinf(level_touchdowns(g, cell, 0.5 * X[2], 1e-4)[2]));
}
