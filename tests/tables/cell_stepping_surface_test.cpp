// `surface`'s reading of the load curve (model/surface, docs/model.md section 17) against the
// time-stepping reference of the same cell (reference/cell_stepping.hpp), which assumes
// nothing of the contact's history: three levels on the square lattice and two and three
// on the hexagonal one, on two grids each.
//
// Measured: each level's t* equal to the stepping's (t* to 1e-4) within 4.2e-5, while the
// grid moves the stepping's own t* by up to 7.9e-3 from n = 48 to 96 (the hexagonal
// three-level cell's level 2, a sliver of a spot); areas within 1% (a level-2 spot of a few nodes
// included); the loads within 1.8e-4 of the nominal load, 8.3e-5
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
        for (std::size_t level = 0; level < r.level_area.size(); ++level) {
          EXPECT_NEAR(s.state.level_area[level], r.level_area[level], 1e-2 * r.level_area[level] + 1e-12)
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
