// The drop a level closes at a load (reference/level_closure.hpp), against the load curve
// of the same geometry (reference/load_curve.hpp, another code path: a march in load with a
// bisection of each site's touchdown by its tip's pressure): at a level's touchdown load
// X*, the closure of that level is the level's own drop.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "model/problem/cell_geometry.hpp"
#include "model/problem/shape.hpp"
#include "reference/level_closure.hpp"
#include "reference/load_curve.hpp"
#include "reference/periodic_grid.hpp"

using namespace punchsweep;
using model::LatticeKind;

namespace {

struct Case {
  LatticeKind lattice;
  double l;
  std::vector<double> drops;
};

// 2 x 2 supercells of a square two-level and a hexagonal three-level lattice, each cap's
// height scattered (normal, 0.004 R, seed 3), on 32 nodes a pitch, with their load curves
// to full contact.
const std::vector<Case> kScattered{Case{LatticeKind::square, 3.0, {0.02}},
                                   Case{LatticeKind::hexagonal, 200.0 / 60.0, {2.0 / 60.0, 5.0 / 60.0}}};
struct Scattered {
  model::CellGeometry geometry;
  reference::PeriodicGrid grid;
  model::LoadCurve curve;
};
Scattered scattered(const Case& c) {
  model::HeightScatter scatter;
  scatter.kind = model::HeightScatter::Kind::normal;
  scatter.width = 0.004;
  scatter.seed = 3;
  const int K = 2;
  Scattered out;
  out.geometry = model::supercell(model::lattice_cell(c.lattice, c.l, model::Shape{2, 0.5}, c.drops), K, scatter);
  out.grid = reference::lattice_grid(out.geometry, c.lattice, 32, K);
  reference::LoadCurveOptions options;
  options.X_top = 1.0;
  out.curve = reference::build_load_curve(out.geometry, reference::make_cell(out.geometry, out.grid), options);
  return out;
}

}  // namespace

// Square and hexagonal lattices of two and three levels (drops from 0.005 to 0.05 R, the
// study's 2 and 5 um under 60 um caps among them): each level's closure at its touchdown on
// the curve is its drop. The curve finds X* to 1e-7 of itself and the closure grows about
// as X^(2/3) (Hertz's approach) and never faster than X, so 1e-6 of the drop bounds what the
// two methods may differ by; both solve to 1e-10 of the displacement range.
TEST(LevelClosure, closes_each_level_at_its_touchdown_on_the_curve) {
  const model::Shape shape{2, 0.5};
  const int n = 32;
  for (const Case& c : {Case{LatticeKind::square, 3.0, {0.02}}, Case{LatticeKind::hexagonal, 200.0 / 60.0, {2.0 / 60.0}},
                        Case{LatticeKind::hexagonal, 200.0 / 60.0, {2.0 / 60.0, 5.0 / 60.0}},
                        Case{LatticeKind::square, 2.5, {0.005, 0.05}}}) {
    const model::CellGeometry g = model::lattice_cell(c.lattice, c.l, shape, c.drops);
    const reference::PeriodicGrid grid = reference::lattice_grid(g, c.lattice, n);
    reference::LoadCurveOptions options;
    options.X_top = 1.0;
    const model::LoadCurve curve = reference::build_load_curve(g, reference::make_cell(g, grid), options);
    for (int level = 1; level < g.levels(); ++level) {
      const double X = curve.level_touchdown[static_cast<std::size_t>(level)];
      ASSERT_TRUE(std::isfinite(X)) << "level " << level << " touches on the curve";
      reference::LevelClosure closure(g, level, grid);
      const reference::LevelClosed closed = closure.at(X);
      const double drop = c.drops[static_cast<std::size_t>(level - 1)];
      std::printf("%s l = %.4g, level %d of %d: X* = %.9g, closure %.9g against drop %.9g (%.1e)\n",
                  model::lattice_name(c.lattice).c_str(), c.l, level, g.levels(), X, closed.drop, drop, closed.drop / drop - 1.0);
      EXPECT_FALSE(closed.every_drop);
      EXPECT_NEAR(closed.drop, drop, 1e-6 * drop) << "level " << level;
      // Just short of X* the level has not closed its drop; just past, it has.
      EXPECT_LT(closure.at(X * (1.0 - 1e-4)).drop, drop);
      EXPECT_GT(closure.at(X * (1.0 + 1e-4)).drop, drop);
    }
  }
}

// A level whose caps lie at different drops moves as one: on a 2 x 2 supercell of the
// square lattice with scattered heights (and a hexagonal three-level one), the closure at
// the curve's touchdown of the level's first cap is the drop of the level's tallest cap, for
// each level (the level's other caps keep their offsets below it).
TEST(LevelClosure, moves_a_scattered_level_as_one) {
  for (const Case& c : kScattered) {
    const Scattered made = scattered(c);
    const model::CellGeometry& g = made.geometry;
    const reference::PeriodicGrid& grid = made.grid;
    const model::LoadCurve& curve = made.curve;
    for (int level = 1; level < g.levels(); ++level) {
      double least = 1e300, most = 0.0;
      for (const model::Site& site : g.sites) {
        if (site.level != level) continue;
        least = std::min(least, site.drop);
        most = std::max(most, site.drop);
      }
      ASSERT_GT(most - least, 1e-3 * least) << "the level's caps scatter";
      const double X = curve.level_touchdown[static_cast<std::size_t>(level)];
      ASSERT_TRUE(std::isfinite(X));
      reference::LevelClosure closure(g, level, grid);
      const reference::LevelClosed closed = closure.at(X);
      std::printf("%s K = 2, level %d: X* = %.9g, closure %.9g against the level's tallest cap %.9g (%.1e)\n",
                  model::lattice_name(c.lattice).c_str(), level, X, closed.drop, least, closed.drop / least - 1.0);
      EXPECT_FALSE(closed.every_drop);
      EXPECT_NEAR(closed.drop, least, 1e-6 * least) << "level " << level;
      EXPECT_LT(closure.at(X * (1.0 - 1e-4)).drop, least);
      EXPECT_GT(closure.at(X * (1.0 + 1e-4)).drop, least);
    }
  }
}

// A share of a scattered level's caps: on the same supercells, the curve's k-th least
// touchdown of the level's caps (k = 2 to all of them) is the load at which k of them have
// touched, and there the closure of k caps (a bisection over the drop, a contact solve a
// trial) is the drop of the level's tallest cap. The curve finds each X* to 1e-7 of itself,
// and the k-th cap's closure moves about as the first's with the load (the caps before it
// carry part of it: measured here d ln drop / d ln X at most about 1), so 2e-6 of the drop
// bounds what the two may differ by; 1e-4 of X either side the k-th cap is short of the
// drop or past it. Fewer than one or more caps than the level has are refused.
TEST(LevelClosure, closes_a_share_of_a_scattered_levels_caps) {
  for (const Case& c : kScattered) {
    const Scattered made = scattered(c);
    const model::CellGeometry& g = made.geometry;
    const reference::PeriodicGrid& grid = made.grid;
    const model::LoadCurve& curve = made.curve;
    for (int level = 1; level < g.levels(); ++level) {
      std::vector<double> touchdowns;
      double least = 1e300;
      for (std::size_t k = 0; k < g.sites.size(); ++k) {
        if (g.sites[k].level != level) continue;
        touchdowns.push_back(curve.site_touchdown[k]);
        least = std::min(least, g.sites[k].drop);
      }
      std::sort(touchdowns.begin(), touchdowns.end());
      reference::LevelClosure closure(g, level, grid);
      ASSERT_EQ(closure.caps(), touchdowns.size());
      for (std::size_t caps = 2; caps <= touchdowns.size(); ++caps) {
        const double X = touchdowns[caps - 1];
        ASSERT_TRUE(std::isfinite(X)) << "cap " << caps << " of level " << level << " touches on the curve";
        const reference::LevelClosed closed = closure.at(X, caps);
        std::printf("%s K = 2, level %d, %zu of %zu caps: X = %.9g, closure %.9g against the level's tallest cap %.9g "
                    "(%.1e) in %d solves\n",
                    model::lattice_name(c.lattice).c_str(), level, caps, touchdowns.size(), X, closed.drop, least,
                    closed.drop / least - 1.0, closed.solves);
        EXPECT_FALSE(closed.every_drop);
        EXPECT_NEAR(closed.drop, least, 2e-6 * least) << "level " << level << ", " << caps << " caps";
        EXPECT_LT(closure.at(X * (1.0 - 1e-4), caps).drop, least);
        EXPECT_GT(closure.at(X * (1.0 + 1e-4), caps).drop, least);
      }
      EXPECT_THROW(closure.at(0.01, 0), std::invalid_argument);
      EXPECT_THROW(closure.at(0.01, touchdowns.size() + 1), std::invalid_argument);
    }
  }
}

// A share of another level's caps (LevelClosure::counting): on the hexagonal three-level
// supercell, the curve's k-th least touchdown of level 2's caps (k = 1 to all) is the load
// at which k of them have touched with level 1 where it is (in contact by then), and there
// the least drop of level 1's tallest cap at which k of level 2's caps have touched is level
// 1's own. The two methods differ by what the curve's 1e-7 of X* moves that drop: the
// drop's own slope in X, measured from the closures 1e-4 of X either side (which must lie
// past and short of level 1's drop: more load, less sinking needed), times 1e-3, twice over,
// and 1e-8 of the drop for the solves. Level 0 (the reference) and counts outside 1 to the
// level's caps are refused.
TEST(LevelClosure, closes_a_share_of_another_levels_caps) {
  int checked = 0;
  for (const Case& c : kScattered) {
    const Scattered made = scattered(c);
    const model::CellGeometry& g = made.geometry;
    if (g.levels() < 3) continue;
    const model::LoadCurve& curve = made.curve;
    {
      const int level = 1, other = 2;
      std::vector<double> touchdowns;
      double least = 1e300;
      for (std::size_t k = 0; k < g.sites.size(); ++k) {
        if (g.sites[k].level == other) touchdowns.push_back(curve.site_touchdown[k]);
        if (g.sites[k].level == level) least = std::min(least, g.sites[k].drop);
      }
      std::sort(touchdowns.begin(), touchdowns.end());
      reference::LevelClosure closure(g, level, made.grid);
      for (std::size_t caps = 1; caps <= touchdowns.size(); ++caps) {
        const double X = touchdowns[caps - 1];
        ASSERT_TRUE(std::isfinite(X)) << "cap " << caps << " of level " << other << " touches on the curve";
        const reference::LevelClosed closed = closure.counting(X, caps, other);
        const double past = closure.counting(X * (1.0 + 1e-4), caps, other).drop;
        const double short_of = closure.counting(X * (1.0 - 1e-4), caps, other).drop;
        const double bound = 2.0 * 1e-3 * 0.5 * (short_of - past) + 1e-8 * least;
        std::printf("hexagonal K = 2, level %d's drop, %zu of level %d's %zu caps: X = %.9g, closure %.9g against "
                    "the level's tallest cap %.9g (%.1e; bound %.1e) in %d solves\n",
                    level, caps, other, touchdowns.size(), X, closed.drop, least, closed.drop / least - 1.0,
                    bound / least, closed.solves);
        EXPECT_TRUE(closed.rising);
        EXPECT_NEAR(closed.drop, least, bound) << "level " << level << ", " << caps << " caps of level " << other;
        EXPECT_LT(past, least);
        EXPECT_GT(short_of, least);
        ++checked;
      }
      EXPECT_THROW(closure.counting(0.01, 0, other), std::invalid_argument);
      EXPECT_THROW(closure.counting(0.01, touchdowns.size() + 1, other), std::invalid_argument);
      EXPECT_THROW(closure.counting(0.01, 1, 0), std::invalid_argument);
    }
    // Level 2's drop, counting level 1's caps: at the curve's k-th touchdown of level 1,
    // level 2 (deeper) has not touched, and level 1's count is the same at any drop of level
    // 2 until it rises into contact and takes load off level 1: the least drop at which k of
    // level 1's caps have touched is where level 2 starts to carry, above its own. The curve
    // of the supercell with level 2 moved there (each cap keeping its offset) has level 1's
    // k-th touchdown at the same X: a cap in contact carries load as the 3/2 power of its
    // depth, so X moves little with that drop, and the curve finds X* to 1e-7 (1e-5 here).
    reference::LevelClosure closure(g, 2, made.grid);
    std::vector<double> level_1;
    double least_2 = 1e300;
    for (std::size_t k = 0; k < g.sites.size(); ++k) {
      if (g.sites[k].level == 1) level_1.push_back(curve.site_touchdown[k]);
      if (g.sites[k].level == 2) least_2 = std::min(least_2, g.sites[k].drop);
    }
    std::sort(level_1.begin(), level_1.end());
    for (const std::size_t caps : {std::size_t{1}, std::size_t{4}, level_1.size()}) {
      const double X = level_1[caps - 1];
      const reference::LevelClosed closed = closure.counting(X, caps, 1);
      ASSERT_TRUE(closed.rising && std::isfinite(closed.drop));
      EXPECT_LT(closed.drop, least_2);
      model::CellGeometry moved = g;
      for (model::Site& site : moved.sites) {
        if (site.level == 2) site.drop = closed.drop + (site.drop - least_2);
      }
      reference::LoadCurveOptions options;
      options.X_top = 1.0;
      const model::LoadCurve again = reference::build_load_curve(moved, reference::make_cell(moved, made.grid), options);
      std::vector<double> touched;
      for (std::size_t k = 0; k < moved.sites.size(); ++k) {
        if (moved.sites[k].level == 1) touched.push_back(again.site_touchdown[k]);
      }
      std::sort(touched.begin(), touched.end());
      std::printf("hexagonal K = 2, level 2's drop, %zu of level 1's caps at X = %.9g: level 2 at %.9g (its own %.9g); "
                  "the curve there has level 1's %zu-th touchdown at %.9g (%.1e)\n",
                  caps, X, closed.drop, least_2, caps, touched[caps - 1], touched[caps - 1] / X - 1.0);
      EXPECT_NEAR(touched[caps - 1], X, 1e-5 * X) << caps << " caps";
      ++checked;
    }
  }
  EXPECT_EQ(checked, 8 + 3);
}

// Past full contact of the other levels, every node is pressed: the level touches at any
// drop it can have, and the closure says so with the deepest (where the tall caps' own
// surfaces reach its tips: on the square lattice's centre, two tall caps' C r^2 at r = l/sqrt(2)
// in R, so l^2/4 for C = 1/2).
TEST(LevelClosure, says_every_drop_past_full_contact) {
  const model::Shape shape{2, 0.5};
  const double l = 2.0;
  const model::CellGeometry g = model::lattice_cell(LatticeKind::square, l, shape, {0.1});
  reference::LevelClosure closure(g, 1, reference::lattice_grid(g, LatticeKind::square, 16));
  EXPECT_NEAR(closure.deepest(), l * l / 4.0, 1e-12);
  const reference::LevelClosed closed = closure.at(10.0);
  EXPECT_TRUE(closed.every_drop);
  EXPECT_EQ(closed.drop, closure.deepest());
  EXPECT_EQ(closure.at(0.0).drop, 0.0);
  EXPECT_THROW(reference::LevelClosure(g, 0, reference::lattice_grid(g, LatticeKind::square, 16)), std::invalid_argument);
  EXPECT_THROW(reference::LevelClosure(g, 2, reference::lattice_grid(g, LatticeKind::square, 16)), std::invalid_argument);
}
