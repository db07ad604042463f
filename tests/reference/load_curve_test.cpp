// The elastic load curve of a periodic texture (reference/load_curve.hpp) and its reading
// (model/surface/load_curve.hpp), against closed forms (an isolated punch), the direct
// bisection of each level's touchdown (reference/cell_touchdown.hpp, another code path),
// and the curve's own invariants.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "model/problem/cell_geometry.hpp"
#include "model/problem/shape.hpp"
#include "model/surface/load_curve.hpp"
#include "reference/cell_touchdown.hpp"
#include "reference/load_curve.hpp"
#include "reference/periodic_grid.hpp"
#include "reference/transform_threads.hpp"

using namespace punchsweep;
using model::LatticeKind;

namespace {

model::LoadCurve curve_of(const model::CellGeometry& g, LatticeKind lattice, int n, double X_top) {
  reference::LoadCurveOptions options;
  options.X_top = X_top;
  return reference::build_load_curve(g, reference::make_cell(g, reference::lattice_grid(g, lattice, n)), options);
}

}  // namespace

// A cap far from its neighbours (a / l = 0.1) is the isolated punch: P = K_P a^(s+1)
// (Hertz, 4 a^3 / 3, for s = 2, C = 1/2), its area pi a^2. The lattice adds a displacement
// that is nearly uniform over the spot; the grid error falls with the spot's nodes.
// Measured: s = 2 off by 2.4e-2 at 6.4 node spacings across the radius, 5.9e-3 at 12.8
// (second order: Richardson's estimate of the rest, the lattice's correction, -1.5e-4);
// s = 3 by 2.3e-2 and 8.6e-3.
TEST(LoadCurve, a_lone_cap_has_the_isolated_punch_area) {
  for (const model::Shape shape : {model::Shape{2, 0.5}, model::Shape{3, 0.7}}) {
    const double l = 4.0, a = 0.4;
    const double X = model::load_coefficient(shape) * std::pow(a, shape.s + 1) / (l * l);
    const model::CellGeometry g = model::lattice_cell(LatticeKind::square, l, shape, {});
    double error[2];
    int k = 0;
    for (const int n : {64, 128}) {
      const model::LoadCurve c = curve_of(g, LatticeKind::square, n, 2.0 * X);
      const double area = c.at(X).level_area[0];
      error[k++] = area / (std::numbers::pi * a * a) - 1.0;
      std::printf("s = %d: a = %.2f R (%.1f spacings at n = %d): area %.6g against pi a^2 %.6g (%.2e)\n", shape.s, a,
                  a * n / l, n, area, std::numbers::pi * a * a, error[k - 1]);
    }
    EXPECT_LT(std::abs(error[1]), 1e-2) << "s = " << shape.s;
    EXPECT_LT(std::abs(error[1]), std::abs(error[0])) << "s = " << shape.s << ": the error falls with the grid";
  }
}

// Each level's touchdown on the curve (bisection on each site's gap within the march's
// bracket, warm-started) equals the direct bisection of cell_touchdown (from the uniform
// field, on the level's first site) on the same grid, for three levels on the square
// lattice and two and three on the hexagonal one; its change from one grid to the next is
// what the grid leaves.
TEST(LoadCurve, every_levels_touchdown_is_the_direct_solves) {
  struct Case {
    LatticeKind lattice;
    std::vector<double> drops;
    double l;
  };
  for (const Case& c : {Case{LatticeKind::square, {0.03, 0.05}, 0.75}, Case{LatticeKind::hexagonal, {0.05}, 1.2},
                        Case{LatticeKind::hexagonal, {0.05, 0.08}, 1.2}}) {
    const model::CellGeometry g = model::lattice_cell(c.lattice, c.l, model::Shape{2, 0.5}, c.drops);
    std::vector<double> coarse;
    for (const int n : {48, 96}) {
      const reference::Cell cell = reference::make_cell(g, reference::lattice_grid(g, c.lattice, n));
      reference::LoadCurveOptions options;
      options.X_top = 0.2;
      const model::LoadCurve curve = reference::build_load_curve(g, cell, options);
      const std::vector<double> direct = reference::level_touchdowns(g, cell, 0.2, 1e-8);
      for (int level = 1; level < g.levels(); ++level) {
        const double X = curve.level_touchdown[static_cast<std::size_t>(level)];
        std::printf("%s, %zu levels, n = %d: level %d touches at %.8g, direct %.8g", model::lattice_name(c.lattice).c_str(),
                    c.drops.size() + 1, n, level, X, direct[static_cast<std::size_t>(level)]);
        if (n == 96) std::printf(" (grid change %.1e)", std::abs(X / coarse[static_cast<std::size_t>(level - 1)] - 1.0));
        std::printf("\n");
        EXPECT_NEAR(X, direct[static_cast<std::size_t>(level)], 2e-6 * X) << "level " << level << ", n = " << n;
        if (n == 48) coarse.push_back(X);
        if (n == 96) {
          EXPECT_NEAR(X, coarse[static_cast<std::size_t>(level - 1)], 2e-2 * X);
        }
      }
      EXPECT_LT(curve.level_touchdown[1], curve.level_touchdown.back() * (1.0 + 1e-12));
    }
  }
}

// Invariants: loads sum to X Lx Ly at every sample; a level has no area before its
// touchdown; past full contact the areas are the levels' shares and extra load spreads by
// them; the sites' share touched counts the sites whose touchdown is passed.
TEST(LoadCurve, reads_keep_the_balance_and_the_contact_rules) {
  const model::CellGeometry g = model::lattice_cell(LatticeKind::hexagonal, 1.2, model::Shape{2, 0.5}, {0.05});
  const model::LoadCurve c = curve_of(g, LatticeKind::hexagonal, 48, std::numeric_limits<double>::infinity());
  ASSERT_EQ(model::load_curve_error(c), "");
  ASSERT_TRUE(std::isfinite(c.X_full));
  for (const model::LoadCurveSample& s : c.samples) {
    EXPECT_NEAR(s.level_load[0] + s.level_load[1], s.X * c.cell_area, 1e-9 * s.X * c.cell_area);
  }
  EXPECT_NEAR(c.level_share[0] + c.level_share[1], 1.0, 1e-12);
  const double X1 = c.level_touchdown[1];
  EXPECT_EQ(c.at(0.999 * X1).level_area[1], 0.0);
  EXPECT_GT(c.at(1.01 * X1).level_area[1], 0.0);
  EXPECT_DOUBLE_EQ(c.at(0.999 * X1).sites_touched, 2.0 / 6.0);  // the two tallest of six sites
  EXPECT_DOUBLE_EQ(c.at(1.001 * X1).sites_touched, 1.0);
  const model::CurveState full = c.at(2.0 * c.X_full);
  EXPECT_EQ(full.range, model::CurveRange::full_contact);
  EXPECT_NEAR(full.area_fraction, 1.0, 1e-12);
  EXPECT_NEAR(full.level_load[0] + full.level_load[1], 2.0 * c.X_full * c.cell_area, 1e-9 * c.X_full * c.cell_area);
  EXPECT_NEAR(full.level_load[1] - c.samples.back().level_load[1], c.X_full * c.level_share[1] * c.cell_area,
              1e-12 * c.X_full * c.cell_area);
  // Below the first sample the areas scale as the isolated punch's, X^(2/(s+1)).
  const model::CurveState low = c.at(0.125 * c.X_first());
  EXPECT_EQ(low.range, model::CurveRange::below_resolution);
  EXPECT_NEAR(low.level_area[0], c.samples.front().level_area[0] * std::pow(0.125, 2.0 / 3.0), 1e-12);
}

// The hexagonal lattice's cell: l x l sqrt(3), two tallest sites, the triangles' centres; even
// (its quarter solves it) with two levels; with three even in x alone (its half solves it:
// the upward and downward centres swap under the mirror in y).
TEST(LoadCurve, the_lattices_place_their_sites) {
  const model::CellGeometry two = model::lattice_cell(LatticeKind::hexagonal, 1.0, model::Shape{2, 0.5}, {0.1});
  EXPECT_EQ(two.sites.size(), 6u);
  EXPECT_DOUBLE_EQ(two.Ly, std::sqrt(3.0));
  EXPECT_TRUE(model::mirror_symmetric(two));
  EXPECT_EQ(model::geometry_error(two), "");
  // Every centre is l / sqrt(3) from its three nearest tallest sites.
  for (const model::Site& s : two.sites) {
    if (s.level == 0) continue;
    int near = 0;
    for (const model::Site& t : two.sites) {
      if (t.level != 0) continue;
      for (int dx = -1; dx <= 1; ++dx) {
        for (int dy = -1; dy <= 1; ++dy) {
          near += std::abs(std::hypot(s.x - t.x - dx * two.Lx, s.y - t.y - dy * two.Ly) - 1.0 / std::sqrt(3.0)) < 1e-12;
        }
      }
    }
    EXPECT_EQ(near, 3) << "site at (" << s.x << ", " << s.y << ")";
  }
  const model::CellGeometry three = model::lattice_cell(LatticeKind::hexagonal, 1.0, model::Shape{2, 0.5}, {0.1, 0.2});
  EXPECT_EQ(three.levels(), 3);
  EXPECT_FALSE(model::mirror_symmetric(three));  // its levels alternate along y
  EXPECT_TRUE(model::mirror_symmetric_x(three));
  EXPECT_EQ(reference::lattice_grid(three, LatticeKind::hexagonal, 64).symmetry, reference::Symmetry::mirror_x);
  EXPECT_EQ(reference::lattice_grid(three, LatticeKind::hexagonal, 64).ny % 6, 0);
  const model::CellGeometry square = model::lattice_cell(LatticeKind::square, 1.0, model::Shape{2, 0.5}, {0.1, 0.2});
  EXPECT_TRUE(model::mirror_symmetric(square));
  EXPECT_EQ(square.sites.size(), 4u);
  EXPECT_THROW(model::lattice_cell(LatticeKind::square, 1.0, model::Shape{2, 0.5}, {0.1, 0.2, 0.3}), std::invalid_argument);
}

// Full contact from the profile alone (reference::full_contact_load: X >= max S profile,
// S the half-space's stiffness) against the curve's X_full, which the march finds by
// bisecting contact solves in log X to the touchdown tolerance (1e-7 of X): another code
// path (the constrained conjugate gradient). On mirrored lattice grids (the cosine
// transform) and a scattered supercell's full grid (the FFT); and the progress the curve
// reports runs from its first load to that one.
TEST(LoadCurve, full_contact_from_the_profile_is_the_curves_full_contact) {
  const model::Shape shape{2, 0.5};
  struct Case {
    const char* name;
    model::CellGeometry geometry;
    reference::PeriodicGrid grid;
  };
  std::vector<Case> cases;
  {
    model::CellGeometry g = model::lattice_cell(LatticeKind::square, 1.5, shape, {0.05});
    cases.push_back({"square, two levels", g, reference::lattice_grid(g, LatticeKind::square, 48)});
  }
  {
    model::CellGeometry g = model::lattice_cell(LatticeKind::hexagonal, 1.2, shape, {0.05, 0.08});
    cases.push_back({"hexagonal, three levels", g, reference::lattice_grid(g, LatticeKind::hexagonal, 48)});
  }
  {
    model::HeightScatter scatter;
    scatter.kind = model::HeightScatter::Kind::normal;
    scatter.width = 0.01;
    scatter.seed = 3;
    const model::CellGeometry lattice = model::lattice_cell(LatticeKind::square, 1.0, shape, {0.03});
    model::CellGeometry g = model::supercell(lattice, 2, scatter);
    cases.push_back({"2 x 2 scattered supercell", g, reference::lattice_grid(g, LatticeKind::square, 24, 2)});
  }
  int mirrored = 0, full = 0;
  for (const Case& c : cases) {
    const reference::Cell cell = reference::make_cell(c.geometry, c.grid);
    const double predicted = reference::full_contact_load(cell);
    reference::LoadCurveOptions options;
    reference::LoadCurveProgress first, last;
    options.progress = [&](const reference::LoadCurveProgress& p) {
      if (p.solves == 1) first = p;
      last = p;
    };
    const model::LoadCurve curve = reference::build_load_curve(c.geometry, cell, options);
    std::printf("%s (%d x %d, %s): X_full %.10g by bisection, %.10g from the profile; %d solves\n", c.name, c.grid.nx,
                c.grid.ny, c.grid.mirrored() ? "mirrored" : "full", curve.X_full, predicted, last.solves);
    (c.grid.mirrored() ? mirrored : full) += 1;
    EXPECT_NEAR(predicted, curve.X_full, 2e-7 * curve.X_full) << c.name;
    EXPECT_EQ(first.X_full, predicted) << c.name;
    EXPECT_EQ(first.X_start, curve.X_first()) << c.name;
    EXPECT_EQ(first.fraction(), 0.0) << c.name;
    EXPECT_EQ(last.fraction(), 1.0) << c.name;  // the march passes full contact, then bisects back
    EXPECT_EQ(first.X_full_contact, predicted) << c.name;
    EXPECT_EQ(first.range_share(), 1.0) << c.name;
  }
  EXPECT_GE(mirrored, 1);  // both transforms held
  EXPECT_GE(full, 1);
}

// A curve built for a question that reads loads up to X_reach stops at its march's first
// sample past it (reference::march_end) and is the whole curve's beginning, bit for bit: the
// whole curve cut there (LoadCurve::up_to) has the same numbers, so every reading at or below
// X_reach is the whole curve's (the march goes one step at least); a level the cut curve has not reached reads +infinity (it
// never touches under such a load), one it has keeps the whole curve's X*. A hexagonal
// three-level cell at reaches below, between and above its levels' touchdowns.
TEST(LoadCurve, a_curve_to_a_reach_is_the_whole_curves_beginning) {
  const model::CellGeometry g = model::lattice_cell(LatticeKind::hexagonal, 1.2, model::Shape{2, 0.5}, {0.02, 0.05});
  const reference::Cell cell = reference::make_cell(g, reference::lattice_grid(g, LatticeKind::hexagonal, 32));
  const model::LoadCurve whole = reference::build_load_curve(g, cell, {});
  ASSERT_TRUE(std::isfinite(whole.X_full));
  const std::vector<double> X_star = whole.level_touchdown;
  std::printf("whole curve: %zu samples to full contact at X = %.6g; touchdowns %.6g %.6g\n", whole.samples.size(), whole.X_full,
              X_star[1], X_star[2]);
  const std::vector<double> reaches{0.5 * X_star[1], 0.5 * (X_star[1] + X_star[2]), 1.5 * X_star[2], 0.5 * whole.X_full};
  for (const double reach : reaches) {
    reference::LoadCurveOptions options;
    options.X_reach = reach;
    reference::LoadCurveProgress last;
    options.progress = [&](const reference::LoadCurveProgress& p) { last = p; };
    const model::LoadCurve cut = reference::build_load_curve(g, cell, options);
    // Its progress runs to its end, a share of the whole curve's range in log X.
    EXPECT_EQ(last.X_full, cut.X_last());
    EXPECT_EQ(last.X_full_contact, reference::full_contact_load(cell));
    EXPECT_EQ(last.fraction(), 1.0);
    EXPECT_NEAR(last.range_share(), std::log(cut.X_last() / cut.X_first()) / std::log(last.X_full_contact / cut.X_first()), 1e-15);
    EXPECT_LT(last.range_share(), 1.0);
    const double end = reference::march_end(whole.X_first(), options);
    std::printf("reach %.6g: %zu samples to X = %.6g (march end %.6g)\n", reach, cut.samples.size(), cut.X_last(), end);
    EXPECT_EQ(cut.X_last(), end);
    EXPECT_GE(cut.X_last(), reach);
    EXPECT_LE(cut.X_last(), std::max(reach, whole.X_first()) * std::pow(10.0, 1.0 / options.samples_per_decade));
    EXPECT_LT(cut.samples.size(), whole.samples.size());
    EXPECT_EQ(cut.tables(), whole.up_to(end).tables()) << "reach " << reach;
    for (std::size_t level = 1; level < X_star.size(); ++level) {
      if (X_star[level] <= cut.X_last()) {
        EXPECT_EQ(cut.level_touchdown[level], X_star[level]);
      } else {
        EXPECT_TRUE(std::isinf(cut.level_touchdown[level]));
      }
    }
    for (const double share : {0.1, 0.5, 0.9, 1.0}) {
      const model::CurveState a = cut.at(share * reach), b = whole.at(share * reach);
      EXPECT_EQ(a.level_area, b.level_area);
      EXPECT_EQ(a.level_load, b.level_load);
      EXPECT_EQ(a.sites_touched, b.sites_touched);
    }
    EXPECT_EQ(cut.at(1.01 * cut.X_last()).range, model::CurveRange::above_top);
  }
  // A curve stopped at one reach, continued from its front to the next and to full
  // contact, is the curve built for each at once, bit for bit.
  reference::CurveFront front;
  reference::LoadCurveOptions first;
  first.X_reach = reaches.front();
  model::LoadCurve grown = reference::build_load_curve(g, cell, first, &front);
  EXPECT_EQ(front.p.size(), cell.grid.size());
  for (std::size_t r = 1; r <= reaches.size(); ++r) {
    reference::LoadCurveOptions next;
    if (r < reaches.size()) next.X_reach = reaches[r];
    reference::CurveFront after;
    grown = reference::extend_load_curve(g, cell, std::move(grown), front, next, &after);
    EXPECT_EQ(grown.tables(), reference::build_load_curve(g, cell, next).tables()) << "extended to reach " << next.X_reach;
    front = std::move(after);
  }
  EXPECT_TRUE(front.p.empty());  // at full contact: nothing to go on from
  EXPECT_THROW(reference::extend_load_curve(g, cell, whole, front, {}), std::invalid_argument);
  // Past full contact the reach changes nothing.
  reference::LoadCurveOptions beyond;
  beyond.X_reach = 10.0 * whole.X_full;
  EXPECT_EQ(reference::build_load_curve(g, cell, beyond).tables(), whole.tables());
}

// The hexagonal lattice of three levels is even in x alone (its levels alternate along y):
// its grid stores the half 0 <= x <= Lx/2 (Symmetry::mirror_x), the same discrete problem
// on half the unknowns. Its curve against the whole grid's: each level's touchdown within
// the touchdown tolerance (1e-7 of X) and the solves' (1e-8), the areas and loads read at
// loads across the range within the refinement's tolerances (1e-3 of an area and half a
// node, 1e-4 of the load share) and the same full contact; a scattered supercell (no
// symmetry) and the two-level cell (its quarter) keep theirs.
TEST(LoadCurve, a_cell_even_in_x_alone_is_solved_on_its_half) {
  const model::CellGeometry g = model::lattice_cell(LatticeKind::hexagonal, 1.2, model::Shape{2, 0.5}, {0.03, 0.06});
  ASSERT_TRUE(model::mirror_symmetric_x(g));
  ASSERT_FALSE(model::mirror_symmetric(g));
  const reference::PeriodicGrid half = reference::lattice_grid(g, LatticeKind::hexagonal, 48);
  ASSERT_EQ(half.symmetry, reference::Symmetry::mirror_x);
  reference::PeriodicGrid whole = half;
  whole.symmetry = reference::Symmetry::none;
  const reference::Cell half_cell = reference::make_cell(g, half), whole_cell = reference::make_cell(g, whole);
  EXPECT_EQ(half_cell.profile.size() * 2, whole_cell.profile.size() + 2 * static_cast<std::size_t>(half.ny));
  const model::LoadCurve a = reference::build_load_curve(g, half_cell, {}), b = reference::build_load_curve(g, whole_cell, {});
  std::printf("half: %zu samples, whole: %zu; X_full %.10g and %.10g; touchdowns %.10g %.10g / %.10g %.10g\n", a.samples.size(),
              b.samples.size(), a.X_full, b.X_full, a.level_touchdown[1], a.level_touchdown[2], b.level_touchdown[1],
              b.level_touchdown[2]);
  for (std::size_t level = 1; level < 3; ++level) {
    EXPECT_NEAR(a.level_touchdown[level], b.level_touchdown[level], 2e-7 * b.level_touchdown[level]) << level;
  }
  EXPECT_NEAR(a.X_full, b.X_full, 2e-7 * b.X_full);
  const double node_area = half.cell_area();
  for (double X = 2.0 * b.X_first(); X < b.X_full; X *= 1.7) {
    const model::CurveState x = a.at(X), y = b.at(X);
    for (std::size_t level = 0; level < 3; ++level) {
      EXPECT_NEAR(x.level_area[level], y.level_area[level], 2e-3 * y.level_area[level] + node_area) << "X " << X << " level " << level;
      EXPECT_NEAR(x.level_load[level], y.level_load[level], 2e-4 * X * g.Lx * g.Ly) << "X " << X << " level " << level;
    }
    EXPECT_EQ(x.sites_touched, y.sites_touched) << "X " << X;
  }
  // The other cells keep their grids: the two-level cell its quarter, a scattered
  // supercell the whole.
  const model::CellGeometry two = model::lattice_cell(LatticeKind::hexagonal, 1.2, model::Shape{2, 0.5}, {0.03});
  EXPECT_EQ(reference::lattice_grid(two, LatticeKind::hexagonal, 48).symmetry, reference::Symmetry::mirror);
  model::HeightScatter scatter;
  scatter.kind = model::HeightScatter::Kind::normal;
  scatter.width = 0.005;
  const model::CellGeometry scattered = model::supercell(g, 2, scatter);
  EXPECT_EQ(reference::lattice_grid(scattered, LatticeKind::hexagonal, 24, 2).symmetry, reference::Symmetry::none);
}

// A curve built on two threads is the curve built on one, bit for bit, on the quarter (the
// cosine transform's blocks, each computed alone); a cache or map that reads it cannot tell.
// A two-level hexagonal cell on 208 nodes a pitch (a quarter above
// kThreadedValues), its first samples (kept few: two threads stall on a machine whose other
// core another test holds).
TEST(LoadCurve, two_threads_build_the_curve_of_one) {
  const int before = reference::transform_threads();
  const model::CellGeometry g = model::lattice_cell(LatticeKind::hexagonal, 1.2, model::Shape{2, 0.5}, {0.01});
  const reference::PeriodicGrid grid = reference::lattice_grid(g, LatticeKind::hexagonal, 208);
  ASSERT_EQ(grid.symmetry, reference::Symmetry::mirror);
  ASSERT_GE(static_cast<long>(grid.stored_nx()) * grid.stored_ny(), reference::kThreadedValues);
  const reference::Cell cell = reference::make_cell(g, grid);
  reference::LoadCurveOptions options;
  options.X_reach = 1e-4;
  std::vector<model::LoadCurve> curves;
  for (const int threads : {1, 2}) {
    reference::set_transform_threads(threads);
    curves.push_back(reference::build_load_curve(g, cell, options));
  }
  reference::set_transform_threads(before);
  std::printf("%zu samples to X = %.6g\n", curves[0].samples.size(), curves[0].X_last());
  ASSERT_GE(curves[0].samples.size(), 3u);
  EXPECT_EQ(curves[0].tables(), curves[1].tables());
  EXPECT_EQ(curves[0].level_touchdown, curves[1].level_touchdown);
}
