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
