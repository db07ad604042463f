// The general-geometry touchdown (reference/cell_touchdown.hpp) on the paper's two-level
// square lattice against the periodic model's touchdown (docs/model.md, section 14: its
// tables, built by the boundary elements on a finer grid and continued in load): the same
// X* within the direct solve's own grid change.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine/periodic_tables.hpp"
#include "model/localization/localization_model.hpp"
#include "model/periodic/periodic_solution.hpp"
#include "model/problem/cell_geometry.hpp"
#include "reference/cell_touchdown.hpp"
#include "reference/periodic_grid.hpp"

using namespace punchsweep;

TEST(CellTouchdown, the_two_level_square_cell_touches_where_the_periodic_model_says) {
  model::set_periodic_solution_source([](int s) { return engine::periodic_solution_for(s, std::nullopt); });
  for (const double dh : {0.01, 0.03, 0.06}) {
    model::ContactProblem problem{0.75, dh, 0.06, {2, 0.5}};
    problem.localization = model::parse_localization("periodic");
    const double model_X = model::touchdown(problem).X_star;
    const model::CellGeometry g = model::two_level_square(problem);
    double X[2];
    int k = 0;
    for (const int n : {64, 128}) {
      const reference::Cell cell =
          reference::make_cell(g, reference::PeriodicGrid::square(n, problem.l, reference::Symmetry::mirror));
      X[k++] = reference::level_touchdowns(g, cell, 10.0, 1e-8)[1];
    }
    const double grid_change = std::abs(X[1] - X[0]);
    std::printf("dh = %.2f: X* periodic model %.6g, direct n = 64 %.6g, n = 128 %.6g (grid change %.2e, off %.2e)\n",
                dh, model_X, X[0], X[1], grid_change / X[1], std::abs(X[1] - model_X) / model_X);
    EXPECT_LE(std::abs(X[1] - model_X), 2.0 * grid_change + 1e-4 * model_X) << "dh = " << dh;
  }
}
