// Speed of `punchsweep surface` (docs/model.md, section 17): one elastic load curve per
// geometry, then a material x temperature x pressure sweep read off it (issue 38's target:
// a 256 x 256 cell's curve in seconds; 1e5 points at table-read speed).
// Run: build/benchmarks/surface_benchmark [--benchmark_repetitions=3]
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "model/laws/standard_linear_solid.hpp"
#include "model/load/creep_weighted_load.hpp"
#include "model/problem/cell_geometry.hpp"
#include "model/surface/surface_history.hpp"
#include "reference/load_curve.hpp"
#include "reference/periodic_grid.hpp"

using namespace punchsweep;
using model::LatticeKind;

namespace {

struct Texture {
  model::CellGeometry geometry;
  reference::PeriodicGrid grid;
  const char* label;
};

// 0: the paper's two-level square lattice, 256 nodes per pitch (its quarter solved);
// 1: the same on the whole 256 x 256 grid; 2: hexagonal three levels, 128 per pitch
// (128 x 222, whole: it is not even); 3: an 8 x 8 supercell of one level, SD 0.01 R, 32 per
// pitch (256 x 256, whole).
Texture texture(int which) {
  const model::Shape shape{2, 0.5};
  if (which <= 1) {
    const model::CellGeometry g = model::lattice_cell(LatticeKind::square, 0.75, shape, {0.03});
    reference::PeriodicGrid grid = reference::lattice_grid(g, LatticeKind::square, 256);
    if (which == 1) grid.symmetry = reference::Symmetry::none;
    return {g, grid, which == 0 ? "square 2 levels, 256 x 256 (quarter)" : "square 2 levels, 256 x 256 (whole)"};
  }
  if (which == 2) {
    const model::CellGeometry g = model::lattice_cell(LatticeKind::hexagonal, 1.2, shape, {0.06, 0.09});
    return {g, reference::lattice_grid(g, LatticeKind::hexagonal, 128), "hexagonal 3 levels, 128 x 222 (whole)"};
  }
  model::HeightScatter scatter{model::HeightScatter::Kind::normal, 0.01, {}, 7};
  const model::CellGeometry g =
      model::supercell(model::lattice_cell(LatticeKind::square, 0.75, shape, {}), 8, scatter);
  return {g, reference::lattice_grid(g, LatticeKind::square, 32, 8), "8 x 8 scattered supercell, 256 x 256 (whole)"};
}

// One load curve to 1.05 X(inf) of the standard linear solid T = 4 at pbar = 0.012 (0.05 E0*).
void BM_LoadCurve(benchmark::State& state) {
  const Texture t = texture(static_cast<int>(state.range(0)));
  const reference::Cell cell = reference::make_cell(t.geometry, t.grid);
  reference::LoadCurveOptions options;
  options.X_top = 0.05;
  int solves = 0;
  options.progress = [&](const reference::LoadCurveProgress& p) { solves = p.solves; };
  std::size_t samples = 0;
  for (auto _ : state) {
    const model::LoadCurve curve = reference::build_load_curve(t.geometry, cell, options);
    samples = curve.samples.size();
  }
  state.counters["solves"] = solves;
  state.counters["samples"] = static_cast<double>(samples);
  state.SetLabel(t.label);
}
BENCHMARK(BM_LoadCurve)->DenseRange(0, 3)->Iterations(1)->Unit(benchmark::kSecond);

// After the curve: each level's regime and t* at 1e5 points, creep ratio T in [1.5, 10] x
// pressure pbar in [1e-3, 0.05] E0* (a material x temperature x pressure sweep: T stands for
// the temperature's shift of one law), from the touchdown loads alone.
void BM_LevelTouches(benchmark::State& state) {
  const model::CellGeometry g = model::lattice_cell(LatticeKind::hexagonal, 1.2, model::Shape{2, 0.5}, {0.06, 0.09});
  reference::LoadCurveOptions options;
  options.X_top = 0.5;
  const model::LoadCurve curve =
      reference::build_load_curve(g, reference::make_cell(g, reference::lattice_grid(g, LatticeKind::hexagonal, 48)), options);
  constexpr int kSide = 316;  // 316^2 ~ 1e5 points
  double checksum = 0.0;
  for (auto _ : state) {
    for (int i = 0; i < kSide; ++i) {
      const model::StandardLinearSolid creep(1.5 + 8.5 * i / (kSide - 1));
      for (int j = 0; j < kSide; ++j) {
        const model::CreepWeightedLoad load(creep, 1e-3 * std::pow(50.0, static_cast<double>(j) / (kSide - 1)));
        for (const model::LevelTouch& touch : model::level_touches(curve, load)) checksum += touch.t_star < 1e300 ? touch.t_star : 0.0;
      }
    }
  }
  benchmark::DoNotOptimize(checksum);
  state.counters["points/s"] = benchmark::Counter(static_cast<double>(state.iterations()) * kSide * kSide, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_LevelTouches)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
