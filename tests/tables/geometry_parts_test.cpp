// A geometry's parts (model/surface/geometry_parts.hpp), every implementation held to one
// contract, and the two held to each other where both answer: the paper's two-level square
// lattice, by its localization (the periodic model's touchdown) and by load curves (the
// periodic tables' curve, and the cell's own boundary elements, another method).
#include <gtest/gtest.h>

#include "shipped_tables.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include "model/laws/creep_laws.hpp"
#include "model/laws/standard_linear_solid.hpp"
#include "model/load/creep_weighted_load.hpp"
#include "model/periodic/periodic_model.hpp"
#include "model/periodic/periodic_solution.hpp"
#include "model/point/point_axes.hpp"
#include "model/point/point_evaluation.hpp"
#include "model/problem/cell_geometry.hpp"
#include "model/surface/geometry_parts.hpp"
#include "model/surface/periodic_curve.hpp"
#include "reference/load_curve.hpp"
#include "reference/periodic_grid.hpp"

using namespace punchsweep;

namespace {

/// The contract every implementation keeps (docs/model.md, section 10): a level is
/// immediate where X(0+) >= X*, delayed at the t* where X(t*) = X* (to 1e-9 of X*), never
/// where X(inf) < X*; touches() at a load point is touches_at()'s row there.
void holds_the_contract(const model::GeometryParts& parts, const char* what) {
  const model::CreepLawSpec& sls = *model::find_creep_law("standard_linear_solid");
  const model::PointAxes axes(sls.parameters, false);
  const std::vector<double> pbar{1e-4, 3e-3, 0.02, 0.1}, T{1.2, 2.5, 6.0, 40.0};
  std::vector<const double*> columns(axes.size(), nullptr);
  columns[axes.find(model::Coordinate::pressure)] = pbar.data();
  columns[axes.law().front()] = T.data();
  const std::size_t L = static_cast<std::size_t>(parts.levels());
  std::vector<double> t_star(pbar.size() * L);
  std::vector<std::int8_t> regime(pbar.size() * L);
  parts.touches_at(sls, axes, columns, pbar.size(), t_star.data(), regime.data());
  for (std::size_t k = 0; k < pbar.size(); ++k) {
    const model::StandardLinearSolid creep(T[k]);
    const model::CreepWeightedLoad load(creep, pbar[k]);
    const std::vector<model::LevelTouch> touches = parts.touches(load);
    ASSERT_EQ(touches.size(), L) << what;
    EXPECT_EQ(touches[0].regime, model::Regime::immediate) << what << ": the tallest level touches at once";
    for (std::size_t level = 0; level < L; ++level) {
      const model::LevelTouch& touch = touches[level];
      const double X_star = parts.touchdowns()[level];
      EXPECT_EQ(touch.X_star, X_star) << what;
      EXPECT_EQ(static_cast<int>(touch.regime), regime[k * L + level]) << what << ", point " << k;
      if (std::isnan(touch.t_star)) {
        EXPECT_TRUE(std::isnan(t_star[k * L + level])) << what;
      } else {
        EXPECT_EQ(touch.t_star, t_star[k * L + level]) << what << ", point " << k;
      }
      switch (touch.regime) {
        case model::Regime::immediate:
          EXPECT_GE(load.initial(), X_star) << what;
          break;
        case model::Regime::delayed:
          EXPECT_LT(load.initial(), X_star) << what;
          EXPECT_NEAR(load(touch.t_star), X_star, 1e-9 * X_star) << what << ", level " << level << ", point " << k;
          break;
        case model::Regime::never:
          EXPECT_LT(load.final(), X_star) << what;
          break;
      }
    }
  }
}

}  // namespace

// Every implementation: the localization's on the paper's lattice, and load curves of the
// lattice (off the periodic tables) and of a hexagonal three-level cell (its boundary
// elements).
TEST(GeometryParts, every_implementation_keeps_the_reading_contract) {
  test::use_shipped_tables();
  const model::ContactProblem paper = test::periodic_lattice(1.5, 0.02, 2);
  holds_the_contract(model::LocalizationParts(paper), "localization, the paper's lattice");
  holds_the_contract(model::CurveParts(*model::periodic_load_curve(model::periodic_solution(2), paper)),
                     "curve of the periodic tables, the paper's lattice");
  const model::CellGeometry hexagonal = model::lattice_cell(model::LatticeKind::hexagonal, 1.2, model::Shape{2, 0.5}, {0.02, 0.05});
  const reference::PeriodicGrid grid = reference::lattice_grid(hexagonal, model::LatticeKind::hexagonal, 32);
  reference::LoadCurveOptions options;
  options.X_top = 0.5;
  const model::CurveParts cell(reference::build_load_curve(hexagonal, reference::make_cell(hexagonal, grid), options));
  ASSERT_EQ(cell.levels(), 3);
  holds_the_contract(cell, "curve of a hexagonal three-level cell");
}

// Where both answer (the paper's lattice, 40 random points: l log-uniform in [0.3, 3] R, s
// 1 to 3, dh between 0 and the tables' top), the localization's parts and the periodic
// tables' curve are the same periodic solution read two ways: the same X* to the last bit,
// so the same t* and regime as `point --localization periodic` (model::summarize_point) at
// every load point.
TEST(GeometryParts, the_localization_and_the_tables_curve_are_one_answer) {
  test::use_shipped_tables();
  std::mt19937_64 random(49);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const int s = 1 + trial % 3;
    const double l = 0.3 * std::pow(10.0, unit(random));
    model::ContactProblem p = test::periodic_lattice(l, 0.0, s);
    const model::PeriodicSolution& solution = model::periodic_solution(s);
    // dh up to the tables' top (in the lattice's own height unit, C (l/2)^s).
    p.dh = unit(random) * solution.delta_top() * model::PeriodicScales(p).h_unit;
    ASSERT_TRUE(model::periodic_curve_reaches(solution, p));
    const model::LocalizationParts localization(p);
    const model::CurveParts tables(*model::periodic_load_curve(solution, p));
    ASSERT_EQ(localization.touchdowns().size(), tables.touchdowns().size());
    EXPECT_EQ(localization.touchdowns()[1], tables.touchdowns()[1]) << "l " << l << ", dh " << p.dh << ", s " << s;
    for (const double pbar : {1e-4, 1e-2}) {
      const model::StandardLinearSolid creep(1.0 + 4.0 * unit(random));
      p.pbar0 = pbar;
      const model::PointSummary point = model::summarize_point(p, creep);
      const model::LevelTouch touch = localization.touches(model::CreepWeightedLoad(creep, pbar))[1];
      EXPECT_EQ(touch.regime, point.regime);
      EXPECT_EQ(touch.t_star, point.t_star.value_or(std::numeric_limits<double>::infinity()));
      ++compared;
    }
  }
  EXPECT_EQ(compared, 80);
}

// The cell's own boundary elements (another method) on the paper's lattice at three
// points: X* of level 1 within the cell curve's own convergence (twice its move from 64 to
// 128 nodes a pitch, and 1e-4 of itself) of the localization's.
TEST(GeometryParts, the_cells_curve_converges_to_the_localization) {
  test::use_shipped_tables();
  for (const auto& [l, dh, s] : {std::tuple{1.5, 0.02, 2}, std::tuple{0.75, 0.03, 2}, std::tuple{2.0, 0.2, 1}}) {
    const model::ContactProblem p = test::periodic_lattice(l, dh, s);
    const double expected = model::LocalizationParts(p).touchdowns()[1];
    const model::CellGeometry g = model::lattice_cell(model::LatticeKind::square, l, p.shape, {dh});
    std::vector<double> X;
    for (const int n : {64, 128}) {
      reference::LoadCurveOptions options;
      options.X_top = 2.0 * expected;
      const model::CurveParts cell(
          reference::build_load_curve(g, reference::make_cell(g, reference::lattice_grid(g, model::LatticeKind::square, n)), options));
      X.push_back(cell.touchdowns()[1]);
    }
    const double move = std::abs(X[1] - X[0]);
    std::printf("l %.3g, dh %.3g, s %d: X* localization %.9g, cell 64 %.9g, 128 %.9g (%.1e, move %.1e)\n", l, dh, s, expected,
                X[0], X[1], X[1] / expected - 1.0, move / expected);
    EXPECT_NEAR(X[1], expected, 2.0 * move + 1e-4 * expected);
  }
}
