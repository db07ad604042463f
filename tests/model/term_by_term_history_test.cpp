// A law given as a relaxation series has its load histories integrated term by term
// (LoadHistory; docs/model.md, section 12.7): the terms that relax within the smooth
// history before t by Gauss-Laguerre sums over the interpolant, the others as a kernel,
// and one panel once the load has settled. Judge: the same law with its series hidden,
// whose histories integrate E' as a whole over panels that never stop (the method the
// brute force of wide_spectrum_test.cpp also checks).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "model/laws/kelvin_series.hpp"
#include "model/problem/load_shape.hpp"
#include "model/point/point_evaluation.hpp"
#include "model/laws/prony_series.hpp"
#include "model/test_series_hidden.hpp"
#include "model/laws/time_shift.hpp"

using namespace punchsweep::model;
using punchsweep::model::testing::SeriesHidden;

namespace {

// A silicone-like spectrum: 10 terms, relaxation times 5e-8 to 0.5 (as a shipped material).
PronySeries ten_terms() {
  return PronySeries(1.196, {0.477, 0.328, 0.221, 0.157, 0.113, 0.127, 0.114, 0.077, 0.059, 0.043},
                     {4.99e-8, 4.83e-7, 3.55e-6, 1.72e-5, 6.04e-5, 2.28e-4, 1.33e-3, 9.07e-3, 6.42e-2, 4.89e-1});
}

void expect_same_loads(const CreepLaw& law, const ContactProblem& p, const std::vector<double>& times,
                       double tolerance) {
  const SeriesHidden hidden(law);
  const PointResult by_terms = evaluate_point(p, law, {times, {}});
  const PointResult whole = evaluate_point(p, hidden, {times, {}});
  ASSERT_EQ(by_terms.regime, whole.regime) << law.describe();
  ASSERT_EQ(by_terms.valid(), whole.valid()) << by_terms.reason();
  const double L = p.pbar0 * p.l * p.l;
  for (std::size_t i = 0; i < times.size(); ++i) {
    EXPECT_EQ(by_terms.series[i].a1, whole.series[i].a1);
    ASSERT_TRUE(std::isfinite(by_terms.series[i].P1) && std::isfinite(by_terms.series[i].P2)) << "t = " << times[i];
    EXPECT_NEAR(by_terms.series[i].P1, whole.series[i].P1, tolerance * L)
        << law.describe() << ", dh = " << p.dh << ", t = " << times[i];
    EXPECT_NEAR(by_terms.series[i].P2, whole.series[i].P2, tolerance * L)
        << law.describe() << ", dh = " << p.dh << ", t = " << times[i];
  }
}

ContactProblem problem(double dh) {
  ContactProblem p;
  p.l = 0.75;
  p.pbar0 = 0.02;
  p.dh = dh;
  return p;
}

// Times from inside the spectrum to 100 s, past its settling (40 lambda_max, about 25 s).
const std::vector<double> kTimes{0.0, 1e-7, 1e-5, 1e-3, 0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 30.0, 100.0};

}  // namespace

TEST(TermByTermHistory, equals_the_whole_kernel_for_a_ten_term_prony_series) {
  const PronySeries law = ten_terms();
  for (const double dh : {0.0, 0.005, 0.02}) expect_same_loads(law, problem(dh), kTimes, 1e-11);
}

TEST(TermByTermHistory, equals_the_whole_kernel_for_a_shifted_series) {
  // A WLF-like shift of 1e-6: every term fast against the output times (Gauss-Laguerre
  // alone), and of 10: slow terms left for the kernel.
  for (const double a_T : {1e-6, 10.0}) {
    const TimeShiftedLaw law(std::make_unique<PronySeries>(ten_terms()), a_T);
    expect_same_loads(law, problem(0.005), kTimes, 1e-11);
  }
}

TEST(TermByTermHistory, equals_the_whole_kernel_with_a_dashpot) {
  // Unlimited creep: E(inf) = 0, no settling, level 2 always touches.
  const KelvinSeries law({0.4, 0.8, 1.5}, {1e-3, 0.1, 10.0}, 0.02);
  expect_same_loads(law, problem(0.03), {0.0, 0.01, 0.3, 3.0, 30.0, 300.0}, 1e-11);
}

TEST(TermByTermHistory, equals_the_whole_kernel_under_a_ramp_and_a_table) {
  // A kink of the load ends the smooth history: terms slower than 1/50 of the time since
  // the kink go back to the kernel, and the Laguerre nodes never cross it.
  // Times on the kinks themselves (0.05; 1e-4, 0.01, 0.2), with the history going on past
  // them: there the loads must still sum to the nominal load (the history's panels start
  // small again at each kink; they once did not, and the sum broke by 5e-5 at t = 0.01).
  const PronySeries law = ten_terms();
  std::vector<double> times = kTimes;
  times.insert(times.end(), {1e-4, 0.05, 0.2});
  std::sort(times.begin(), times.end());
  ContactProblem p = problem(0.005);
  for (const LoadShape& shape :
       {LoadShape::ramp(0.05), LoadShape::table({{0.0, 0.2}, {1e-4, 0.5}, {0.01, 0.6}, {0.2, 1.0}})}) {
    p.loading = shape;
    expect_same_loads(law, p, times, 1e-11);
    const PointResult r = evaluate_point(p, law, {times, {}});
    for (const Snapshot& snap : r.series) {
      const double nominal = p.pbar0 * shape.at(snap.t) * p.l * p.l;
      EXPECT_NEAR(snap.P1 + snap.P2, nominal, 1e-10 * nominal) << "t = " << snap.t;
    }
  }
}

TEST(TermByTermHistory, a_settled_load_is_one_panel) {
  // Past 40 of the longest retardation time X no longer changes: the history after it is
  // one panel, not the 4.4 panels a decade of time (a factor 1.69 each) the graded layout
  // spends: from about 25 s to 1e4 s, 2.6 decades, 11 panels of 12 solves.
  const PronySeries law = ten_terms();
  const SeriesHidden hidden(law);
  const ContactProblem p = problem(0.005);
  const std::vector<double> late{1e4};
  const PointResult by_terms = evaluate_point(p, law, {late, {}});
  const PointResult whole = evaluate_point(p, hidden, {late, {}});
  EXPECT_GE(whole.history_samples - by_terms.history_samples, 12 * 10);
  const double L = p.pbar0 * p.l * p.l;
  EXPECT_NEAR(by_terms.series[0].P1 + by_terms.series[0].P2, L, 1e-12 * L);
  EXPECT_NEAR(by_terms.series[0].P1, whole.series[0].P1, 1e-11 * L);
}
