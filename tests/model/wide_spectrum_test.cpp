// A relaxation spectrum over 12 decades (a 24-term Prony series as DMA fits give, relaxation
// times 1e-7 to 1e5 s) followed for 12 decades of time: the load history's graded panels
// and age-graded kernel pieces (docs/model.md, section 12.7) against an independent brute
// force (direct two-level solves at the nodes of a fine geometric Gauss grid, no
// interpolation), and the load balance P1 + P2 = pbar0 l^2 at every time.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "model/numerics/gauss_rules.hpp"
#include "model/point/point_evaluation.hpp"
#include "model/laws/prony_series.hpp"
#include "model/paper/two_level.hpp"

using namespace punchsweep::model;

namespace {

// 24 terms, tau_i = 10^(-7 + i/2) (and 1e5 last), weights as a broad glass transition.
PronySeries wide_spectrum() {
  std::vector<double> E, tau;
  for (int i = 0; i < 24; ++i) {
    tau.push_back(i < 23 ? std::pow(10.0, -7.0 + 0.5 * i) : 1e5);
    E.push_back(0.01 + 0.15 * std::exp(-0.5 * std::pow((i - 13.0) / 3.0, 2)));
  }
  return PronySeries(0.0055, E, tau);
}

// P1, P2 at t by brute force: int E' Q over geometric Gauss pieces (ratio 1.01) graded
// from touchdown (in v = sqrt(tau - t*)) and from t (in age), Q solved directly at every node.
void brute_force(const ContactProblem& p, const CreepLaw& law, const PointResult& r, double t, double* P1,
                 double* P2) {
  const TwoLevelSystem system(p, r.radii);
  const CreepWeightedLoad load(law, p.pbar0);
  const double t0 = r.t_start;
  const double L = p.pbar0 * p.l * p.l;
  const auto Q = [&](double tau, double* q1, double* q2) {
    if (tau < t0) {
      *q1 = L * law.creep(tau);
      *q2 = 0.0;
      return;
    }
    const TwoLevelSolve s = system.continue_to(r.start, r.X_start, load(tau));
    *q1 = s.state.Q1;
    *q2 = s.state.Q2;
  };
  const GaussRule& g = gauss_legendre(16);
  *P1 = *P2 = 0.0;
  const auto add = [&](double a, double b, int map) {  // map 0: tau, 1: v from t0, 2: age
    for (int k = 0; k < 16; ++k) {
      const double x = 0.5 * (a + b) + 0.5 * (b - a) * g.nodes[k];
      const double w = 0.5 * (b - a) * g.weights[k];
      const double tau = map == 0 ? x : map == 1 ? t0 + x * x : t - x;
      const double jac = map == 1 ? 2.0 * x : 1.0;
      const double age = map == 2 ? x : t - tau;
      double q1 = 0.0, q2 = 0.0;
      Q(tau, &q1, &q2);
      *P1 += w * jac * law.relaxation_rate(age) * q1;
      *P2 += w * jac * law.relaxation_rate(age) * q2;
    }
  };
  const auto graded = [&](double from, double to, int map) {
    double a = from, b = 1e-12;
    add(a, b, map);
    for (a = b; a < to; a = b) {
      b = std::min(to, a * 1.01);
      add(a, b, map);
    }
  };
  graded(0.0, t0, 0);
  const double split = std::sqrt(0.5 * (t - t0));
  graded(0.0, split, 1);
  graded(0.0, t - t0 - split * split, 2);
  double q1 = 0.0, q2 = 0.0;
  Q(t, &q1, &q2);
  *P1 += law.relaxation(0.0) * q1;
  *P2 += law.relaxation(0.0) * q2;
}

}  // namespace

TEST(WideSpectrum, loads_balance_over_twelve_decades) {
  const PronySeries law = wide_spectrum();
  ContactProblem p;
  p.l = 0.75;
  p.pbar0 = 0.002;
  for (const double dh : {0.0, 0.01, 0.03}) {
    p.dh = dh;
    std::vector<double> times;
    for (int k = 0; k <= 48; ++k) times.push_back(std::pow(10.0, -6.0 + 0.25 * k));
    const PointResult r = evaluate_point(p, law, {times, {}});
    EXPECT_LT(r.history_samples, 2000) << "graded panels: a few hundred solves, not millions";
    for (const Snapshot& s : r.series) {
      EXPECT_NEAR((s.P1 + s.P2) / (p.pbar0 * p.l * p.l), 1.0, 1e-10) << "t = " << s.t << ", dh = " << dh;
    }
  }
}

TEST(WideSpectrum, loads_match_a_brute_force_history) {
  const PronySeries law = wide_spectrum();
  ContactProblem p;
  p.l = 0.75;
  p.pbar0 = 0.002;
  p.dh = 0.01;
  const std::vector<double> times{10.0, 1e4};
  const PointResult r = evaluate_point(p, law, {times, {}});
  ASSERT_EQ(r.regime, Regime::delayed);
  for (std::size_t i = 0; i < times.size(); ++i) {
    double P1 = 0.0, P2 = 0.0;
    brute_force(p, law, r, times[i], &P1, &P2);
    const double L = p.pbar0 * p.l * p.l;
    EXPECT_NEAR(r.series[i].P1, P1, 1e-9 * L) << "t = " << times[i];
    EXPECT_NEAR(r.series[i].P2, P2, 1e-9 * L) << "t = " << times[i];
  }
}
