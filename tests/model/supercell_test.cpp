// Scattered supercells (model/problem/cell_geometry.hpp): the draws' distribution, their
// reproducibility, and the supercell's layout.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "model/problem/cell_geometry.hpp"

using namespace punchsweep;

TEST(Supercell, draws_have_the_stated_distribution_and_repeat_with_their_seed) {
  model::HeightScatter normal;
  normal.kind = model::HeightScatter::Kind::normal;
  normal.width = 0.3;
  normal.seed = 42;
  const std::size_t n = 20000;
  const std::vector<double> a = model::scatter_draws(normal, n);
  double mean = 0.0, square = 0.0, within = 0.0;
  for (double v : a) {
    mean += v / n;
    square += v * v / n;
    within += std::abs(v) <= normal.width ? 1.0 / n : 0.0;
  }
  // Mean within 4 standard errors; SD within 4 of its standard error (sigma / sqrt(2n));
  // the share within one SD is 68.27% (erf(1/sqrt(2))), within 4 of its standard error.
  EXPECT_NEAR(mean, 0.0, 4.0 * normal.width / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(square - mean * mean), normal.width, 4.0 * normal.width / std::sqrt(2.0 * n));
  EXPECT_NEAR(within, std::erf(1.0 / std::sqrt(2.0)), 4.0 * std::sqrt(0.6827 * 0.3173 / n));
  EXPECT_EQ(model::scatter_draws(normal, n), a);  // the same seed, the same caps
  normal.seed = 43;
  EXPECT_NE(model::scatter_draws(normal, n), a);

  model::HeightScatter uniform{model::HeightScatter::Kind::uniform, 0.5, {}, 1};
  const std::vector<double> u = model::scatter_draws(uniform, n);
  EXPECT_LE(*std::max_element(u.begin(), u.end()), 0.5);
  EXPECT_GE(*std::min_element(u.begin(), u.end()), -0.5);
  double u_mean = 0.0, u_square = 0.0;
  for (double v : u) {
    u_mean += v / n;
    u_square += v * v / n;
  }
  EXPECT_NEAR(u_square, 0.25 / 3.0, 4.0 * 0.25 * std::sqrt(4.0 / 45.0 / n));  // var of U(-w, w): w^2/3

  model::HeightScatter list{model::HeightScatter::Kind::list, 0.0, {0.1, -0.2}, 1};
  EXPECT_EQ(model::scatter_draws(list, 2), list.values);
  EXPECT_THROW(model::scatter_draws(list, 3), std::invalid_argument);
  EXPECT_EQ(model::scatter_draws(model::HeightScatter{}, 3), std::vector<double>(3, 0.0));
}

TEST(Supercell, copies_the_cell_and_takes_drops_from_the_tallest_cap) {
  const model::CellGeometry cell = model::lattice_cell(model::LatticeKind::square, 2.0, model::Shape{2, 0.5}, {0.1});
  model::HeightScatter list{model::HeightScatter::Kind::list, 0.0, {}, 1};
  for (int k = 0; k < 18; ++k) list.values.push_back(0.01 * (k % 5) - 0.02);  // 2 sites x 3 x 3 copies
  const model::CellGeometry g = model::supercell(cell, 3, list);
  EXPECT_EQ(g.sites.size(), 18u);
  EXPECT_DOUBLE_EQ(g.Lx, 6.0);
  EXPECT_EQ(model::geometry_error(g), "");
  double least = 1.0;
  for (const model::Site& s : g.sites) least = std::min(least, s.drop);
  EXPECT_EQ(least, 0.0);
  // Copy (i, j) of site k sits at its position plus (i, j) pitches, its drop raised by its draw
  // and then all taken from the tallest (the least of drop + draw, -0.02 here).
  EXPECT_DOUBLE_EQ(g.sites[4].x, 1.0 * 2.0);  // site 0, copy (1, 1)
  EXPECT_DOUBLE_EQ(g.sites[4].y, 1.0 * 2.0);
  EXPECT_NEAR(g.sites[4].drop, 0.0 + list.values[4] + 0.02, 1e-15);
  EXPECT_NEAR(g.sites[9].drop, 0.1 + list.values[9] + 0.02, 1e-15);  // site 1, copy (0, 0)
  EXPECT_DOUBLE_EQ(g.sites[9].x, 1.0);
  EXPECT_EQ(g.sites[9].level, 1);
  EXPECT_FALSE(model::mirror_symmetric(g));
}

TEST(Supercell, a_curvature_scatter_changes_each_caps_C_and_leaves_the_heights_drawn) {
  // Heights drawn alone, and with a curvature scatter after them from the same generator:
  // the same drops; each cap's C is C (1 + d), d the generator's next draws after the
  // heights' (so the first 18 normal draws of seed 7 are the heights', at width 0.01, and the
  // next 18, at width 0.1, the curvatures').
  const model::CellGeometry cell = model::lattice_cell(model::LatticeKind::square, 2.0, model::Shape{2, 0.5}, {0.1});
  const model::HeightScatter heights{model::HeightScatter::Kind::normal, 0.01, {}, 7};
  const model::HeightScatter curvature{model::HeightScatter::Kind::normal, 0.1, {}, 7};
  const model::CellGeometry alone = model::supercell(cell, 3, heights);
  const model::CellGeometry both = model::supercell(cell, 3, heights, curvature);
  model::HeightScatter unit = heights;
  unit.width = 1.0;
  const std::vector<double> z = model::scatter_draws(unit, 36);  // standard normal draws of seed 7
  ASSERT_EQ(both.sites.size(), 18u);
  for (std::size_t k = 0; k < 18; ++k) {
    EXPECT_EQ(both.sites[k].drop, alone.sites[k].drop);
    EXPECT_EQ(alone.sites[k].shape.C, 0.5);
    EXPECT_NEAR(both.sites[k].shape.C, 0.5 * (1.0 + 0.1 * z[18 + k]), 1e-15) << k;
  }
  // A list: its changes, cap by cap; a change of -1 or below is refused by the cap.
  model::HeightScatter list{model::HeightScatter::Kind::list, 0.0, std::vector<double>(18, 0.0), 1};
  list.values[5] = 0.25;
  const model::CellGeometry one = model::supercell(cell, 3, {}, list);
  EXPECT_DOUBLE_EQ(one.sites[5].shape.C, 0.625);
  EXPECT_DOUBLE_EQ(one.sites[4].shape.C, 0.5);
  list.values[5] = -1.0;
  EXPECT_THROW(model::supercell(cell, 3, {}, list), std::invalid_argument);
}

TEST(Supercell, the_tallest_of_n_caps_has_the_closed_forms_of_its_order_statistic) {
  // One cap, normal: its own quantiles (the 95% point 1.6448536269514722 SD). Two caps,
  // uniform on [-w, w]: P(max <= x) = ((x + w) / 2w)^2, so x = w (2 sqrt(q) - 1).
  const model::HeightScatter normal{model::HeightScatter::Kind::normal, 0.2, {}, 1};
  EXPECT_NEAR(model::tallest_rise_quantile(normal, {0.0}, {1.0}, 0.95), 0.2 * 1.6448536269514722, 1e-11);
  EXPECT_NEAR(model::tallest_rise_quantile(normal, {0.0}, {1.0}, 0.5), 0.0, 1e-11);
  const model::HeightScatter uniform{model::HeightScatter::Kind::uniform, 0.5, {}, 1};
  for (const double q : {0.05, 0.5, 0.95}) {
    EXPECT_NEAR(model::tallest_rise_quantile(uniform, {0.0}, {2.0}, q), 0.5 * (2.0 * std::sqrt(q) - 1.0), 1e-11);
  }
  // 1000 caps, normal: the median solves Phi(x)^1000 = 1/2, x = 3.1975894953840083 SD
  // (Phi^-1(0.5^(1/1000)), by scipy.stats.norm.ppf).
  EXPECT_NEAR(model::tallest_rise_quantile(normal, {0.0}, {1000.0}, 0.5), 0.2 * 3.1975894953840083, 1e-9);
  EXPECT_THROW(model::tallest_rise_quantile(model::HeightScatter{}, {0.0}, {1.0}, 0.5), std::invalid_argument);
  EXPECT_THROW(model::tallest_rise_quantile(normal, {0.0}, {1.0}, 1.0), std::invalid_argument);
}
