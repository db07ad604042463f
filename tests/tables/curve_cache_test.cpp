// The load curves' cache (engine/curve_cache.hpp): a cached curve is read without making
// its cell, equals the curve built, and a measured map's cell keys it by its own heights.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "engine/curve_cache.hpp"
#include "model/problem/cell_geometry.hpp"
#include "reference/load_curve.hpp"
#include "reference/periodic_grid.hpp"

namespace {

using namespace punchsweep;

/// PUNCHSWEEP_CACHE set to a private scratch folder for the test's life (then as it was).
struct ScratchCache {
  std::filesystem::path path;
  std::string before;
  bool had = false;
  ScratchCache() {
    path = std::filesystem::temp_directory_path() /
           ("punchsweep-curves-" + std::to_string(::getpid()) + "-" + std::to_string(std::random_device{}()));
    if (const char* set = std::getenv("PUNCHSWEEP_CACHE")) {
      had = true;
      before = set;
    }
    ::setenv("PUNCHSWEEP_CACHE", path.c_str(), 1);
  }
  ~ScratchCache() {
    if (had) {
      ::setenv("PUNCHSWEEP_CACHE", before.c_str(), 1);
    } else {
      ::unsetenv("PUNCHSWEEP_CACHE");
    }
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

model::CellGeometry hexagonal_two_levels() {
  model::Shape shape;
  shape.s = 2.0;
  shape.C = 0.5;
  return model::lattice_cell(model::LatticeKind::hexagonal, 1.2, shape, {0.05});
}

TEST(CurveCache, a_cached_curve_is_read_without_its_cell_and_equals_the_built_one) {
  const ScratchCache cache;
  const model::CellGeometry geometry = hexagonal_two_levels();
  const reference::PeriodicGrid grid = reference::lattice_grid(geometry, model::LatticeKind::hexagonal, 16, 1);
  const reference::LoadCurveOptions options;
  int cells_made = 0;
  std::optional<reference::Cell> cell;
  const auto made = [&]() -> const reference::Cell& {
    ++cells_made;
    cell = reference::make_cell(geometry, grid);
    return *cell;
  };
  EXPECT_FALSE(engine::curve_is_cached(geometry, grid, options, nullptr));
  engine::CurveOrigin origin{};
  const model::LoadCurve built = engine::load_curve_for(geometry, grid, options, nullptr, made, &origin);
  EXPECT_EQ(origin, engine::CurveOrigin::built);
  EXPECT_EQ(cells_made, 1);
  EXPECT_TRUE(engine::curve_is_cached(geometry, grid, options, nullptr));

  const model::LoadCurve read = engine::load_curve_for(geometry, grid, options, nullptr, made, &origin);
  EXPECT_EQ(origin, engine::CurveOrigin::cache);
  EXPECT_EQ(cells_made, 1) << "a cached curve was read by making its cell";
  EXPECT_EQ(read.tables(), built.tables());
  // And the same as one built afresh without a cache (the key holds what the curve needs).
  EXPECT_EQ(reference::build_load_curve(geometry, reference::make_cell(geometry, grid), options).tables(), built.tables());

  // Another grid or another drop is another curve.
  EXPECT_FALSE(engine::curve_is_cached(geometry, reference::lattice_grid(geometry, model::LatticeKind::hexagonal, 20, 1),
                                       options, nullptr));
  model::CellGeometry deeper = geometry;
  for (model::Site& site : deeper.sites) site.drop *= site.level == 1 ? 1.5 : 1.0;
  EXPECT_FALSE(engine::curve_is_cached(deeper, grid, options, nullptr));
}

TEST(CurveCache, a_measured_cell_keys_its_curve_by_its_heights) {
  const ScratchCache cache;
  const model::CellGeometry geometry = hexagonal_two_levels();
  const reference::PeriodicGrid grid = reference::lattice_grid(geometry, model::LatticeKind::hexagonal, 16, 1);
  const reference::LoadCurveOptions options;
  const reference::Cell measured = reference::make_cell(geometry, grid);
  const auto given = [&]() -> const reference::Cell& { return measured; };
  engine::load_curve_for(geometry, grid, options, &measured, given);
  EXPECT_TRUE(engine::curve_is_cached(geometry, grid, options, &measured));
  // The same sites and grid with other heights between them: another curve.
  reference::Cell other = measured;
  other.profile[other.profile.size() / 2] += 1e-3;
  EXPECT_FALSE(engine::curve_is_cached(geometry, grid, options, &other));
  // A measured cell's curve is not a made cell's (and the other way round).
  EXPECT_FALSE(engine::curve_is_cached(geometry, grid, options, nullptr));
}

}  // namespace
