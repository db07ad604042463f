// Speed of the periodic boundary-element reference solver (targets: one elastic solve at
// 256 x 256 under 0.1 s on one core; a full viscoelastic point to t = 5 T_eps under 10 s;
// issue 13: 10 times faster a point at N = 256, benchmarks/reference_speedup.sh). FFTW
// plans are made before timing (once per grid size, as in a sweep).
// Run: build/benchmarks/reference_benchmark [--benchmark_repetitions=5]
#include <benchmark/benchmark.h>

#include <vector>

#include "model/problem/contact_problem.hpp"
#include "model/laws/standard_linear_solid.hpp"
#include "reference/contact_solver.hpp"
#include "reference/fft_influence.hpp"
#include "reference/periodic_grid.hpp"
#include "reference/reference_point.hpp"

using namespace punchsweep;
using namespace punchsweep::reference;

namespace {

// The paper's point (l = 0.75, pbar0 = 0.06, s = 2, C = 1/2, T = 2.5).
model::ContactProblem paper_point(double dh) { return {0.75, dh, 0.06, {2, 0.5}}; }

// One apply of the influence operator, on the whole grid (variant 0) and on the stored
// quarter of a mirrored grid (variant 1: a two-level cell's fields).
void BM_InfluenceApply(benchmark::State& state) {
  const bool mirrored = state.range(1) == 1;
  const PeriodicGrid g = PeriodicGrid::square(static_cast<int>(state.range(0)), 1.0,
                                              mirrored ? Symmetry::mirror : Symmetry::none);
  PeriodicInfluence K(g);
  std::vector<double> p(g.size(), 1.0), u(g.size());
  p[0] = 2.0;
  state.SetLabel(mirrored ? "quarter cell (cosine transform)" : "whole cell");
  for (auto _ : state) {
    K.apply(p, u);
    benchmark::DoNotOptimize(u.data());
  }
}
BENCHMARK(BM_InfluenceApply)->ArgsProduct({{128, 256, 512, 1024}, {0, 1}})->Unit(benchmark::kMicrosecond);

/// One elastic contact solve from the uniform first guess to the default tolerance (1e-10).
void elastic_solve(benchmark::State& state, const PeriodicGrid& g, const std::vector<double>& f,
                   double pbar, ContactSolverOptions options = {}) {
  ContactSolver solver(g, options);
  ContactStatus status;
  for (auto _ : state) {
    const ContactSolution s = solver.solve(f, pbar);
    status = s.status;
    benchmark::DoNotOptimize(s.pressure.data());
  }
  state.counters["cg_iterations"] = status.iterations;
  state.counters["residual"] = status.residual;
}

// The two-level cell of the paper's point at t = 0 (both levels touch, dh = 0.05), as the
// reference point solves it: the quarter cell, preconditioned (variant 1), beside the whole
// cell with the plain iteration (variant 0, the algorithm before issue 13).
void BM_ElasticSolve_TwoLevel(benchmark::State& state) {
  const bool current = state.range(1) == 1;
  const TwoLevelCell cell = make_two_level_cell(paper_point(0.05), static_cast<int>(state.range(0)),
                                                current ? Symmetry::mirror : Symmetry::none);
  ContactSolverOptions options;
  options.precondition = current;
  state.SetLabel(current ? "quarter cell, preconditioned" : "whole cell, plain CG");
  elastic_solve(state, cell.grid, cell.profile, 0.06, options);
}
BENCHMARK(BM_ElasticSolve_TwoLevel)
    ->ArgsProduct({{128, 256, 512, 1024}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// A Hertz spot (a = L/8) in an L = 2 cell.
void BM_ElasticSolve_Hertz(benchmark::State& state) {
  const PeriodicGrid g = PeriodicGrid::square(static_cast<int>(state.range(0)), 2.0);
  const double load = 4.0 / 3.0 * 0.25 * 0.25 * 0.25;
  elastic_solve(state, g, punch_profile(g, {2, 0.5}, 0.0, 0.0), load / 4.0);
}
BENCHMARK(BM_ElasticSolve_Hertz)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

// A full point: delayed regime (dh = 0.075, t* = 0.874 refined to 1e-3), snapshots at
// 0, 0.5, 1, 2, 5, default options (benchmarks/reference_speedup.sh sets it beside an
// older engine).
void BM_ViscoelasticPoint(benchmark::State& state) {
  const model::StandardLinearSolid sls(2.5);
  ReferenceOptions options;
  options.n = static_cast<int>(state.range(0));
  ReferenceResult r;
  for (auto _ : state) {
    r = evaluate_reference_point(paper_point(0.075), sls, options);
    benchmark::DoNotOptimize(r.series.data());
  }
  state.counters["steps"] = r.steps;
  state.counters["solves"] = r.solves;
  state.counters["cg_iterations"] = static_cast<double>(r.cg_iterations);
  state.counters["t_star"] = r.t_star.value_or(-1.0);
}
BENCHMARK(BM_ViscoelasticPoint)->Arg(64)->Arg(128)->Arg(256)->Arg(512)->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
