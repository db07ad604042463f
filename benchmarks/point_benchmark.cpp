// Speed of the per-point model (issue targets: classify < 1 us; full evaluation < 100 us).
// Run: build/benchmarks/point_benchmark [--benchmark_repetitions=5]
#include <benchmark/benchmark.h>

#include "model/point/point_evaluation.hpp"
#include "model/localization/localization_model.hpp"
#include "model/contact/regime.hpp"
#include "model/laws/standard_linear_solid.hpp"
#include "model/paper/elastic_two_level.hpp"
#include "model/paper/two_level.hpp"

using namespace punchsweep::model;

namespace {

// dh walks through a range with immediate, delayed and never points (pbar0 = 0.06,
// l = 0.75, T = 2.5: h(0) = 0.0538, h(inf) = 0.0842), so no result is reused.
double walking_dh(std::int64_t i) { return 0.03 + 0.08 * static_cast<double>(i % 1000) / 1000.0; }

void BM_ClassifyPoint(benchmark::State& state) {
  const StandardLinearSolid sls(2.5);
  ContactProblem p{0.75, 0.05, 0.06, Shape{2, 0.5}};
  std::int64_t i = 0;
  for (auto _ : state) {
    p.dh = walking_dh(i++);
    benchmark::DoNotOptimize(classify(p, sls));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ClassifyPoint);

// Regime, t*, h(0), h(inf), snapshots at 0, 0.5, 1, 2, 5 T_eps with P_i, long-term state.
void evaluate_benchmark(benchmark::State& state, double dh_lo, double dh_hi) {
  const StandardLinearSolid sls(2.5);
  ContactProblem p{0.75, dh_lo, 0.06, Shape{2, 0.5}};
  std::int64_t i = 0;
  for (auto _ : state) {
    p.dh = dh_lo + (dh_hi - dh_lo) * static_cast<double>(i++ % 100) / 100.0;
    benchmark::DoNotOptimize(evaluate_point(p, sls));
  }
  state.SetItemsProcessed(state.iterations());
}
void BM_EvaluatePoint_Immediate(benchmark::State& state) { evaluate_benchmark(state, 0.03, 0.053); }
void BM_EvaluatePoint_Delayed(benchmark::State& state) { evaluate_benchmark(state, 0.055, 0.084); }
void BM_EvaluatePoint_Never(benchmark::State& state) { evaluate_benchmark(state, 0.085, 0.12); }
BENCHMARK(BM_EvaluatePoint_Immediate)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EvaluatePoint_Delayed)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EvaluatePoint_Never)->Unit(benchmark::kMicrosecond);

void BM_ElasticTwoLevel(benchmark::State& state) {
  ContactProblem p{0.75, 0.05, 0.06, Shape{2, 0.5}};
  std::int64_t i = 0;
  for (auto _ : state) {
    p.dh = 0.02 + 0.03 * static_cast<double>(i++ % 100) / 100.0;
    benchmark::DoNotOptimize(solve_elastic_two_level(p, 1.0));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ElasticTwoLevel)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
