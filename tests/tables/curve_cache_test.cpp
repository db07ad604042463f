// The load curves' cache (engine/curve_cache.hpp): a cached curve is read without making
// its cell, equals the curve built, and a measured map's cell keys it by its own heights.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "engine/curve_cache.hpp"
#include "model/problem/cell_geometry.hpp"
#include "reference/load_curve.hpp"
#include "reference/periodic_grid.hpp"

namespace {

// What the dry run reads: the cache holds the curve as far as asked, or nothing of it.
#define EXPECT_WHOLE(held) EXPECT_EQ((held).holds, engine::CachedCurve::Holds::whole)
#define EXPECT_NOTHING(held) EXPECT_EQ((held).holds, engine::CachedCurve::Holds::nothing)

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

/// The cell of a geometry on a grid, made where a curve is built, counting how often.
struct CountingCellMaker {
  const model::CellGeometry& geometry;
  const reference::PeriodicGrid& grid;
  int made = 0;
  std::optional<reference::Cell> cell;
  CountingCellMaker(const model::CellGeometry& g, const reference::PeriodicGrid& n) : geometry(g), grid(n) {}
  const reference::Cell& operator()() {
    ++made;
    cell = reference::make_cell(geometry, grid);
    return *cell;
  }
};

TEST(CurveCache, a_cached_curve_is_read_without_its_cell_and_equals_the_built_one) {
  const ScratchCache cache;
  const model::CellGeometry geometry = hexagonal_two_levels();
  const reference::PeriodicGrid grid = reference::lattice_grid(geometry, model::LatticeKind::hexagonal, 16, 1);
  const reference::LoadCurveOptions options;
  CountingCellMaker made(geometry, grid);
  const int& cells_made = made.made;
  EXPECT_NOTHING(engine::cached_curve(geometry, grid, options, nullptr));
  engine::CurveOrigin origin{};
  const model::LoadCurve built = engine::load_curve_for(geometry, grid, options, nullptr, std::ref(made), &origin);
  EXPECT_EQ(origin, engine::CurveOrigin::built);
  EXPECT_EQ(cells_made, 1);
  EXPECT_WHOLE(engine::cached_curve(geometry, grid, options, nullptr));

  const model::LoadCurve read = engine::load_curve_for(geometry, grid, options, nullptr, std::ref(made), &origin);
  EXPECT_EQ(origin, engine::CurveOrigin::cache);
  EXPECT_EQ(cells_made, 1) << "a cached curve was read by making its cell";
  EXPECT_EQ(read.tables(), built.tables());
  // And the same as one built afresh without a cache (the key holds what the curve needs).
  EXPECT_EQ(reference::build_load_curve(geometry, reference::make_cell(geometry, grid), options).tables(), built.tables());

  // Another grid or another drop is another curve.
  EXPECT_NOTHING(engine::cached_curve(geometry, reference::lattice_grid(geometry, model::LatticeKind::hexagonal, 20, 1),
                                       options, nullptr));
  model::CellGeometry deeper = geometry;
  for (model::Site& site : deeper.sites) site.drop *= site.level == 1 ? 1.5 : 1.0;
  EXPECT_NOTHING(engine::cached_curve(deeper, grid, options, nullptr));
}

TEST(CurveCache, a_measured_cell_keys_its_curve_by_its_heights) {
  const ScratchCache cache;
  const model::CellGeometry geometry = hexagonal_two_levels();
  const reference::PeriodicGrid grid = reference::lattice_grid(geometry, model::LatticeKind::hexagonal, 16, 1);
  const reference::LoadCurveOptions options;
  const reference::Cell measured = reference::make_cell(geometry, grid);
  const auto given = [&]() -> const reference::Cell& { return measured; };
  engine::load_curve_for(geometry, grid, options, &measured, given);
  EXPECT_WHOLE(engine::cached_curve(geometry, grid, options, &measured));
  // The same sites and grid with other heights between them: another curve.
  reference::Cell other = measured;
  other.profile[other.profile.size() / 2] += 1e-3;
  EXPECT_NOTHING(engine::cached_curve(geometry, grid, options, &other));
  // A measured cell's curve is not a made cell's (and the other way round).
  EXPECT_NOTHING(engine::cached_curve(geometry, grid, options, nullptr));
}

}  // namespace

namespace {

// The cache keys a curve without its reach: a saved curve that reaches as far serves a
// question of a smaller reach, cut where that question's march stops (the curve built for
// it, bit for bit); one that stops short is continued from its front (saved beside it) to
// the further reach, again the curve built for it, and saved in its place.
TEST(CurveCache, a_saved_curve_serves_every_reach_up_to_its_own) {
  const ScratchCache cache;
  const model::CellGeometry geometry = hexagonal_two_levels();
  const reference::PeriodicGrid grid = reference::lattice_grid(geometry, model::LatticeKind::hexagonal, 32, 1);
  CountingCellMaker made(geometry, grid);
  const int& cells_made = made.made;
  const reference::Cell fresh = reference::make_cell(geometry, grid);
  const model::LoadCurve whole = reference::build_load_curve(geometry, fresh, {});
  reference::LoadCurveOptions low, high;
  low.X_reach = 2.0 * whole.X_first();
  high.X_reach = 0.3 * whole.X_full;
  const model::LoadCurve built_low = reference::build_load_curve(geometry, fresh, low);
  const model::LoadCurve built_high = reference::build_load_curve(geometry, fresh, high);
  ASSERT_LT(built_low.samples.size(), built_high.samples.size());
  ASSERT_FALSE(std::isfinite(built_high.X_full));

  engine::CurveOrigin origin{};
  EXPECT_EQ(engine::load_curve_for(geometry, grid, low, nullptr, std::ref(made), &origin).tables(), built_low.tables());
  EXPECT_EQ(origin, engine::CurveOrigin::built);
  // Further than the saved one: continued from where it stopped (and saved); nearer: read
  // and cut.
  const engine::CachedCurve short_one = engine::cached_curve(geometry, grid, high, nullptr);
  EXPECT_EQ(short_one.holds, engine::CachedCurve::Holds::beginning);  // the dry run: "continued"
  EXPECT_EQ(short_one.X_last, built_low.X_last());
  EXPECT_EQ(short_one.X_first, whole.X_first());
  EXPECT_EQ(engine::load_curve_for(geometry, grid, high, nullptr, std::ref(made), &origin).tables(), built_high.tables());
  EXPECT_EQ(origin, engine::CurveOrigin::extended);
  EXPECT_EQ(cells_made, 2);
  EXPECT_WHOLE(engine::cached_curve(geometry, grid, low, nullptr));
  EXPECT_EQ(engine::load_curve_for(geometry, grid, low, nullptr, std::ref(made), &origin).tables(), built_low.tables());
  EXPECT_EQ(origin, engine::CurveOrigin::cache);
  EXPECT_EQ(cells_made, 2);
  // The whole curve saved serves any reach.
  EXPECT_EQ(engine::load_curve_for(geometry, grid, {}, nullptr, std::ref(made), &origin).tables(), whole.tables());
  EXPECT_EQ(origin, engine::CurveOrigin::extended);
  for (const reference::LoadCurveOptions* options : {&low, &high}) {
    EXPECT_EQ(engine::load_curve_for(geometry, grid, *options, nullptr, std::ref(made), &origin).tables(),
              (options == &low ? built_low : built_high).tables());
    EXPECT_EQ(origin, engine::CurveOrigin::cache);
  }
  EXPECT_EQ(cells_made, 3);
  // Without its front (a file lost) a short curve is built again, from the start.
  for (const auto& file : std::filesystem::directory_iterator(cache.path)) {
    if (file.path().extension() == ".tables" || file.path().extension() == ".front") std::filesystem::remove(file.path());
  }
  EXPECT_EQ(engine::load_curve_for(geometry, grid, low, nullptr, std::ref(made), &origin).tables(), built_low.tables());
  EXPECT_EQ(origin, engine::CurveOrigin::built);
  for (const auto& file : std::filesystem::directory_iterator(cache.path)) {
    if (file.path().extension() == ".front") std::filesystem::remove(file.path());
  }
  EXPECT_EQ(engine::cached_curve(geometry, grid, high, nullptr).holds, engine::CachedCurve::Holds::nothing);
  EXPECT_EQ(engine::load_curve_for(geometry, grid, high, nullptr, std::ref(made), &origin).tables(), built_high.tables());
  EXPECT_EQ(origin, engine::CurveOrigin::built);
}

}  // namespace
