// A periodic cell of any geometry on the boundary elements' grid (issue 38's geometry
// seam): the profile, each level's share of the cell and the tips, against direct
// evaluation of the sites' closed-form surfaces; the checks of a geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "model/problem/cell_geometry.hpp"
#include "reference/periodic_grid.hpp"

using namespace punchsweep;
using namespace punchsweep::reference;

namespace {

// Three levels on the square lattice: the tall punch at the corner, level 1 at the centre
// (0.04 R lower), level 2 at the edges' midpoints (0.07 R lower), spherical caps (s = 2) but
// level 2 a flatter s = 3; every tip at a mirror point.
model::CellGeometry three_levels(double l) {
  const model::Shape cap{2, 0.5}, flat{3, 0.8};
  return {l, l, {{0.0, 0.0, cap, 0.0, 0}, {0.5 * l, 0.5 * l, cap, 0.04, 1}, {0.5 * l, 0.0, flat, 0.07, 2},
                 {0.0, 0.5 * l, flat, 0.07, 2}}};
}

// A site's surface f(r) + drop at (x, y), r to its nearest periodic image: the closed form.
double surface(const model::CellGeometry& g, const model::Site& site, double x, double y) {
  const auto offset = [](double d, double L) { return d - L * std::round(d / L); };
  const double r = std::hypot(offset(x - site.x, g.Lx), offset(y - site.y, g.Ly));
  return site.shape.C * std::pow(r, site.shape.s) + site.drop;
}

// The level whose surface is lowest at (x, y).
int lowest_level(const model::CellGeometry& g, double x, double y) {
  double low = std::numeric_limits<double>::infinity();
  int level = -1;
  for (const model::Site& site : g.sites) {
    const double f = surface(g, site, x, y);
    if (f < low) std::tie(low, level) = std::pair{f, site.level};
  }
  return level;
}

}  // namespace

TEST(CellGeometry, profile_and_tips_are_the_sites_surfaces_at_the_nodes) {
  const model::CellGeometry g = three_levels(0.8);
  for (const Symmetry symmetry : {Symmetry::none, Symmetry::mirror}) {
    const Cell cell = make_cell(g, PeriodicGrid::square(32, g.Lx, symmetry));
    ASSERT_EQ(cell.level_weight.size(), 2u);
    ASSERT_EQ(cell.tips.size(), 4u);
    for (int i = 0; i < cell.grid.stored_nx(); ++i) {
      for (int j = 0; j < cell.grid.stored_ny(); ++j) {
        double low = std::numeric_limits<double>::infinity();
        for (const model::Site& site : g.sites) low = std::min(low, surface(g, site, cell.grid.x(i), cell.grid.y(j)));
        EXPECT_NEAR(cell.profile[cell.grid.index(i, j)], low, 1e-14) << i << " " << j;
      }
    }
    for (std::size_t k = 0; k < g.sites.size(); ++k) EXPECT_EQ(cell.profile[cell.tips[k]], g.sites[k].drop) << k;
    EXPECT_EQ(cell.tips[1], cell.grid.index(16, 16));
    EXPECT_EQ(cell.tips[2], cell.grid.index(16, 0));
  }
}

TEST(CellGeometry, each_levels_share_of_the_cell_is_where_its_surface_is_lowest) {
  // The shares summed over the cell against the area where each level's surface is the
  // lowest, counted on a 2048 x 2048 lattice of the cell's points (its own error, the
  // crossing lines' length times the lattice step, about 3e-4 of the cell); the whole grid
  // and the quarter (weighted by each node's images) alike.
  const model::CellGeometry g = three_levels(0.8);
  constexpr int kFine = 2048;
  std::vector<double> counted(3, 0.0);
  for (int a = 0; a < kFine; ++a) {
    for (int b = 0; b < kFine; ++b) {
      counted[lowest_level(g, (a + 0.5) * g.Lx / kFine, (b + 0.5) * g.Ly / kFine)] += 1.0 / (double(kFine) * kFine);
    }
  }
  EXPECT_GT(counted[1], 0.05);
  EXPECT_GT(counted[2], 0.05);
  for (const Symmetry symmetry : {Symmetry::none, Symmetry::mirror}) {
    const Cell cell = make_cell(g, PeriodicGrid::square(32, g.Lx, symmetry));
    for (int level = 1; level <= 2; ++level) {
      double share = 0.0;
      for (std::size_t k = 0; k < cell.grid.size(); ++k) share += cell.grid.multiplicity(k) * cell.level_weight[level - 1][k];
      share /= static_cast<double>(cell.grid.nodes());
      std::printf("level %d, %s grid: share %.6f, counted %.6f\n", level,
                  symmetry == Symmetry::mirror ? "quarter" : "whole", share, counted[level]);
      EXPECT_NEAR(share, counted[level], 1e-3) << "level " << level;
    }
    // Every node's shares lie in [0, 1] and leave level 0 a share >= 0; a node that is a
    // level's own is where that level's surface is lowest at the node.
    for (std::size_t k = 0; k < cell.grid.size(); ++k) {
      const double w1 = cell.level_weight[0][k], w2 = cell.level_weight[1][k];
      EXPECT_GE(w1, 0.0);
      EXPECT_GE(w2, 0.0);
      EXPECT_LE(w1 + w2, 1.0 + 1e-12) << k;
    }
    for (int i = 0; i < cell.grid.stored_nx(); ++i) {
      for (int j = 0; j < cell.grid.stored_ny(); ++j) {
        const int owner = lowest_level(g, cell.grid.x(i), cell.grid.y(j));
        const std::size_t k = cell.grid.index(i, j);
        if (owner >= 1) {
          EXPECT_TRUE(cell.level_node[owner - 1][k]) << i << " " << j;
        }
      }
    }
  }
}

TEST(CellGeometry, the_two_level_square_lattice_is_one_geometry) {
  const model::ContactProblem problem{0.75, 0.05, 0.06, {2, 0.5}};
  const model::CellGeometry g = model::two_level_square(problem);
  ASSERT_EQ(g.sites.size(), 2u);
  EXPECT_EQ(g.levels(), 2);
  EXPECT_EQ(g.sites[1].drop, problem.dh);
  EXPECT_EQ(g.sites[1].x, 0.375);
  const TwoLevelCell two = make_two_level_cell(problem, 32, Symmetry::mirror);
  const Cell cell = make_cell(g, PeriodicGrid::square(32, problem.l, Symmetry::mirror));
  EXPECT_EQ(two.profile, cell.profile);
  EXPECT_EQ(two.level2_weight, cell.level_weight[0]);
  EXPECT_EQ(two.tip2, cell.tips[1]);
}

TEST(CellGeometry, a_geometry_or_grid_the_cell_cannot_hold_is_refused_by_name) {
  model::CellGeometry g = three_levels(0.8);
  EXPECT_EQ(model::geometry_error(g), "");
  const auto error_of = [](model::CellGeometry bad) { return model::geometry_error(bad); };
  model::CellGeometry gap = g;
  gap.sites[1].level = 3;
  EXPECT_NE(error_of(gap).find("level 1 has no site"), std::string::npos) << error_of(gap);
  model::CellGeometry outside = g;
  outside.sites[2].x = 0.8;
  EXPECT_NE(error_of(outside).find("site 2: (0.80000000000000004, 0) R is outside the cell"), std::string::npos)
      << error_of(outside);
  model::CellGeometry negative = g;
  negative.sites[3].drop = -0.01;
  EXPECT_NE(error_of(negative).find("site 3: drop = -0.01"), std::string::npos) << error_of(negative);
  model::CellGeometry shape = g;
  shape.sites[0].shape.C = 0.0;
  EXPECT_NE(error_of(shape).find("site 0: C = 0 is outside its range"), std::string::npos) << error_of(shape);
  EXPECT_NE(error_of(model::CellGeometry{0.8, 0.8, {}}).find("no site"), std::string::npos);
  EXPECT_THROW(make_cell(gap, PeriodicGrid::square(32, 0.8)), std::invalid_argument);
  // A tip between nodes, and one off the mirror points of a quarter grid.
  model::CellGeometry between = g;
  between.sites[1].x = 0.41;
  EXPECT_THROW(make_cell(between, PeriodicGrid::square(32, 0.8)), std::invalid_argument);
  model::CellGeometry off_mirror = g;
  off_mirror.sites[1].x = 0.2;
  EXPECT_NO_THROW(make_cell(off_mirror, PeriodicGrid::square(32, 0.8)));
  EXPECT_THROW(make_cell(off_mirror, PeriodicGrid::square(32, 0.8, Symmetry::mirror)), std::invalid_argument);
  EXPECT_THROW(make_cell(g, PeriodicGrid::square(32, 0.9)), std::invalid_argument);  // not the geometry's cell
}
