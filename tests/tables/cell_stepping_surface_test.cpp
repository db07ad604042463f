// `surface`'s reading of the load curve (model/surface, docs/model.md section 17) against the
// time-stepping reference of the same cell (reference/cell_stepping.hpp), which assumes
// nothing of the contact's history: three levels on the square lattice and two and three
// on the hexagonal one, on two grids each.
//
// Measured: each level's t* equal to the stepping's (t* to 1e-4) within 4.2e-5, while the
// grid moves the stepping's own t* by up to 7.9e-3 from n = 48 to 96 (the hexagonal
// three-level cell's level 2, a sliver of a spot); areas within 1% and half a node's area
// (a level-2 spot of 6 nodes at n = 48 is 1.5e-4 off, 0.6 of a node); the loads within 1.8e-4 of the nominal load, 8.3e-5
// with the stepping's steps 4 times finer in J (its O(dt^2) error), the rest the curve's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "model/laws/standard_linear_solid.hpp"
#include "model/load/creep_weighted_load.hpp"
#include "model/problem/cell_geometry.hpp"
#include "model/surface/surface_history.hpp"
#include "reference/cell_stepping.hpp"
#include "reference/load_curve.hpp"
#include "reference/periodic_grid.hpp"

using namespace punchsweep;
using model::LatticeKind;

TEST(CellStepping, surface_touch_times_and_areas_are_the_time_steppings) {
  struct Case {
    LatticeKind lattice;
    double l;
    std::vector<double> drops;
    double pbar;
  };
  const model::StandardLinearSolid creep(4.0);
  const std::vector<double> times{0.0, 0.5, 1.0, 2.0, 4.0, 8.0};
  double worst_load = 0.0;
  for (const Case& c : {Case{LatticeKind::square, 0.75, {0.03, 0.035}, 0.012},
                        Case{LatticeKind::hexagonal, 1.2, {0.07}, 0.015},
                        Case{LatticeKind::hexagonal, 1.2, {0.06, 0.09}, 0.015}}) {
    const model::CellGeometry g = model::lattice_cell(c.lattice, c.l, model::Shape{2, 0.5}, c.drops);
    const model::CreepWeightedLoad load(creep, c.pbar);
    std::vector<reference::CellReference> stepped;
    for (const int n : {48, 96}) {
      const reference::Cell cell = reference::make_cell(g, reference::lattice_grid(g, c.lattice, n));
      reference::LoadCurveOptions curve_options;
      curve_options.X_top = 1.05 * load.final();
      const model::LoadCurve curve = reference::build_load_curve(g, cell, curve_options);
      const model::SurfaceHistory surface = model::surface_history(curve, load, times);
      reference::CellReferenceOptions options;
      options.times = times;
      options.t_star_resolution = 1e-4;
      stepped.push_back(reference::evaluate_cell_reference(g, cell, c.pbar, creep, {}, options));
      const reference::CellReference& ref = stepped.back();
      ASSERT_TRUE(ref.converged);
      for (int level = 1; level < g.levels(); ++level) {
        const std::size_t L = static_cast<std::size_t>(level);
        const double t_surface = surface.levels[L].t_star, t_ref = ref.level_t_star[L];
        std::printf("%s, %zu levels, n = %d: level %d %s t* %.6g, stepped %s %.6g\n", model::lattice_name(c.lattice).c_str(),
                    c.drops.size() + 1, n, level, std::string(model::regime_name(surface.levels[L].regime)).c_str(), t_surface,
                    std::string(model::regime_name(ref.level_regime[L])).c_str(), t_ref);
        EXPECT_EQ(surface.levels[L].regime, ref.level_regime[L]) << "level " << level << ", n = " << n;
        if (std::isfinite(t_ref)) {
          EXPECT_NEAR(t_surface, t_ref, 2e-4 * t_ref + options.t_star_resolution) << "level " << level;
        }
      }
      for (std::size_t k = 0; k < times.size(); ++k) {
        const model::SurfaceSnapshot& s = surface.snapshots[k];
        const reference::CellSnapshot& r = ref.series[k];
        EXPECT_NEAR(s.state.sites_touched, r.sites_touched, 1e-12) << "t = " << times[k];
        std::printf("  t = %g: loads", times[k]);
        for (std::size_t level = 0; level < r.level_load.size(); ++level) {
          std::printf(" %.6g/%.6g", s.level_load[level], r.level_load[level]);
        }
        std::printf("\n");
        const double nominal = c.pbar * g.Lx * g.Ly;
        for (std::size_t level = 0; level < r.level_load.size(); ++level) {
          worst_load = std::max(worst_load, std::abs(s.level_load[level] - r.level_load[level]) / nominal);
          EXPECT_NEAR(s.level_load[level], r.level_load[level], 3e-4 * nominal) << "t = " << times[k] << ", level " << level;
        }
        // 1% of the area, and half a node's (the curve's own refinement allowance: a new
        // spot of a few nodes is read between samples to that).
        const double half_node = 0.5 * g.Lx * g.Ly / (static_cast<double>(cell.grid.nx) * cell.grid.ny);
        for (std::size_t level = 0; level < r.level_area.size(); ++level) {
          EXPECT_NEAR(s.state.level_area[level], r.level_area[level], 1e-2 * r.level_area[level] + half_node)
              << "t = " << times[k] << ", level " << level << ", n = " << n;
        }
      }
    }
    for (int level = 1; level < g.levels(); ++level) {
      const std::size_t L = static_cast<std::size_t>(level);
      std::printf("  level %d: the stepping's t* moves %.2e from n = 48 to 96\n", level,
                  std::abs(stepped[1].level_t_star[L] / stepped[0].level_t_star[L] - 1.0));
    }
  }
  std::printf("worst load difference %.2e of the nominal load\n", worst_load);
}

// An 8 x 8 supercell of one level whose caps' heights scatter (normal, SD 0.01 R): the
// share of caps in contact in time from the curve (each cap's own touchdown) against the
// time stepping's count of pressed tips, on the same grid (16 nodes per pitch). Measured:
// 36 of 64 caps touch at once, 61 by t = 10 T_eps, 3 never; each cap's touch time within
// 4.0e-5 of the stepping's (to 1e-4), the share in contact equal at all 11 times, the area
// fraction within 0.3%.
TEST(CellStepping, a_scattered_supercells_caps_touch_when_the_stepping_says) {
  const model::StandardLinearSolid creep(4.0);
  const double pbar = 0.002;
  const model::CreepWeightedLoad load(creep, pbar);
  model::HeightScatter scatter;
  scatter.kind = model::HeightScatter::Kind::normal;
  scatter.width = 0.01;
  scatter.seed = 7;
  const model::CellGeometry lattice = model::lattice_cell(LatticeKind::square, 0.75, model::Shape{2, 0.5}, {});
  const model::CellGeometry g = model::supercell(lattice, 8, scatter);
  ASSERT_EQ(g.sites.size(), 64u);
  const reference::Cell cell = reference::make_cell(g, reference::lattice_grid(g, LatticeKind::square, 16, 8));
  reference::LoadCurveOptions curve_options;
  curve_options.X_top = 1.05 * load.final();
  const model::LoadCurve curve = reference::build_load_curve(g, cell, curve_options);
  const std::vector<double> times{0.0, 0.1, 0.2, 0.4, 0.7, 1.0, 1.5, 2.0, 3.0, 5.0, 10.0};
  const model::SurfaceHistory surface = model::surface_history(curve, load, times);
  reference::CellReferenceOptions options;
  options.times = times;
  options.t_star_resolution = 1e-4;
  const reference::CellReference ref = reference::evaluate_cell_reference(g, cell, pbar, creep, {}, options);
  ASSERT_TRUE(ref.converged);
  int compared = 0;
  double worst = 0.0;
  for (std::size_t k = 0; k < g.sites.size(); ++k) {
    const double t_ref = ref.site_touch[k];
    const double X_star = curve.site_touchdown[k];
    const double t_curve = X_star <= load.initial() ? 0.0 : std::isfinite(X_star) && X_star < load.final() ? load.time_at_response(X_star / pbar) : std::numeric_limits<double>::infinity();
    if (std::isinf(t_ref) || std::isinf(t_curve)) {
      EXPECT_EQ(std::isinf(t_ref), std::isinf(t_curve) || t_curve > times.back()) << "cap " << k;
      continue;
    }
    ++compared;
    worst = std::max(worst, std::abs(t_curve - t_ref));
    EXPECT_NEAR(t_curve, t_ref, 2e-4 * t_ref + options.t_star_resolution) << "cap " << k;
  }
  std::printf("%d of 64 caps touch by t = %g; their touch times within %.1e of the stepping's\n", compared, times.back(), worst);
  for (std::size_t k = 0; k < times.size(); ++k) {
    std::printf("  t = %g: caps in contact %.4f (stepping %.4f), area fraction %.5f (%.5f)\n", times[k],
                surface.snapshots[k].state.sites_touched, ref.series[k].sites_touched, surface.snapshots[k].state.area_fraction,
                ref.series[k].area_fraction);
    EXPECT_DOUBLE_EQ(surface.snapshots[k].state.sites_touched, ref.series[k].sites_touched) << "t = " << times[k];
    EXPECT_NEAR(surface.snapshots[k].state.area_fraction, ref.series[k].area_fraction, 1e-2 * ref.series[k].area_fraction);
  }
  EXPECT_GT(compared, 10);
}
