// Ramped and tabulated loads (docs/model.md, section 10): the shape's rules, the
// creep-weighted load X(t) = int J(t - tau) dpbar(tau) against closed forms and an
// independent quadrature, the ramp's convergence to the step, and whole points under a ramp
// (touchdown where h = dh, immediate meaning "while the load rises", the load balance
// P1 + P2 = pbar(t) l^2 through the kink of the ramp).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/load/creep_weighted_load.hpp"
#include "model/problem/load_shape.hpp"
#include "model/point/point_evaluation.hpp"
#include "model/paper/pressure.hpp"
#include "model/laws/prony_series.hpp"
#include "model/paper/single_level.hpp"
#include "model/laws/standard_linear_solid.hpp"

using namespace punchsweep::model;

namespace {

std::string refusal(const std::vector<LoadShape::Point>& points) {
  try {
    LoadShape::table(points);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

// The standard linear solid under a ramp over t_r, by hand: int_0^u J = T u - (T - 1)(1 - e^-u),
// g(t) = I(t)/t_r before t_r and (I(t) - I(t - t_r))/t_r = T - (T - 1) e^-t (e^t_r - 1)/t_r
// after it.
double sls_ramp(double T, double t_r, double t) {
  if (t <= t_r) return (T * t + (T - 1.0) * std::expm1(-t)) / t_r;
  return T - (T - 1.0) * std::exp(-t) * std::expm1(t_r) / t_r;
}

}  // namespace

TEST(LoadShape, refuses_what_the_model_cannot_hold) {
  EXPECT_NE(refusal({{0.0, 0.0}, {1.0, 0.8}, {2.0, 0.5}, {3.0, 1.0}}).find("does not recede"), std::string::npos);
  EXPECT_NE(refusal({{0.5, 0.0}, {1.0, 1.0}}).find("starts at t = 0"), std::string::npos);
  EXPECT_NE(refusal({{0.0, 0.0}, {1.0, 0.9}}).find("phi = 1"), std::string::npos);
  EXPECT_NE(refusal({{0.0, 0.0}, {1.0, 1.5}}).find("[0, 1]"), std::string::npos);
  EXPECT_NE(refusal({{0.0, 0.0}, {1.0, 0.5}, {1.0, 1.0}}).find("increase strictly"), std::string::npos);
  EXPECT_THROW(LoadShape::ramp(-1.0), std::invalid_argument);
  EXPECT_TRUE(LoadShape::ramp(0.0).is_step());
  EXPECT_TRUE(LoadShape::table({{0.0, 1.0}, {5.0, 1.0}}).is_step());
}

TEST(LoadShape, ramp_and_table_values) {
  const LoadShape ramp = LoadShape::ramp(4.0);
  EXPECT_EQ(ramp.jump(), 0.0);
  EXPECT_EQ(ramp.rise_time(), 4.0);
  EXPECT_EQ(ramp.at(1.0), 0.25);
  EXPECT_EQ(ramp.at(9.0), 1.0);
  const LoadShape table = LoadShape::table({{0.0, 0.3}, {2.0, 0.3}, {5.0, 1.0}, {8.0, 1.0}});
  EXPECT_EQ(table.jump(), 0.3);
  EXPECT_EQ(table.rise_time(), 5.0);
  EXPECT_NEAR(table.at(3.5), 0.3 + 0.7 * 1.5 / 3.0, 1e-15);
  EXPECT_EQ(table.kinks(), (std::vector<double>{2.0, 5.0}));
}

TEST(CreepWeightedLoad, sls_ramp_is_its_closed_form) {
  for (const double T : {2.0, 10.0}) {
    const StandardLinearSolid sls(T);
    for (const double t_r : {0.01, 1.0, 30.0}) {
      const CreepWeightedLoad load(sls, 0.04, LoadShape::ramp(t_r));
      for (const double t : {1e-4, 0.5 * t_r, t_r, 1.3 * t_r, 5.0, 200.0}) {
        EXPECT_NEAR(load.response(t), sls_ramp(T, t_r, t), 1e-13 * T) << "T = " << T << ", t_r = " << t_r << ", t = " << t;
      }
      EXPECT_EQ(load.response_initial(), 0.0);
      EXPECT_EQ(load.nominal_pressure(0.5 * t_r), 0.02);
    }
  }
}

// A table with a jump and a kink, on a 3-term Prony series, against
// phi(0+) J(t) + int_0^t J(t - tau) phi'(tau) dtau by composite Simpson per linear piece.
TEST(CreepWeightedLoad, table_is_the_superposition_of_its_pieces) {
  const PronySeries law(0.25, {0.25, 0.3, 0.2}, {0.1, 1.0, 10.0});
  const std::vector<LoadShape::Point> points{{0.0, 0.3}, {2.0, 0.3}, {5.0, 0.9}, {6.0, 1.0}};
  const CreepWeightedLoad load(law, 1.0, LoadShape::table(points));
  for (const double t : {1.0, 3.0, 5.5, 6.0, 40.0}) {
    double expected = 0.3 * law.creep(t);
    for (std::size_t k = 1; k < points.size(); ++k) {
      const double a = points[k - 1].t;
      const double b = std::min(points[k].t, t);
      if (!(b > a)) continue;
      const double slope = (points[k].phi - points[k - 1].phi) / (points[k].t - points[k - 1].t);
      const int n = 4000;
      const double h = (b - a) / n;
      double sum = law.creep(t - a) + law.creep(t - b);
      for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * law.creep(t - a - i * h);
      expected += slope * sum * h / 3.0;
    }
    EXPECT_NEAR(load.response(t), expected, 1e-12) << "t = " << t;
    const double g = load.response(t);
    EXPECT_NEAR(load.time_at_response(g), t, 1e-10 * t);
  }
  EXPECT_NEAR(load.response_initial(), 0.3, 1e-16);
}

// Issue 22: a table of many pieces sums its completed pieces by the recursion of
// CreepWeightedLoad::CompletedPieces (O(terms) per evaluation instead of O(pieces x terms):
// a 400-point table took 34 s a point). Held to the direct superposition of the pieces,
// each through the law's own creep_integral, and its derivative to J(t - t_a) - J(t - t_b)
// summed piece by piece, over a wide spectrum (10 decades) and 300 uneven pieces.
TEST(CreepWeightedLoad, a_long_table_equals_the_sum_over_its_pieces) {
  std::vector<double> E, tau;
  for (int i = 0; i < 11; ++i) {
    E.push_back(1.0 + 0.3 * i);
    tau.push_back(std::pow(10.0, -4.0 + i));
  }
  const PronySeries law(0.5, E, tau);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<LoadShape::Point> points{{0.0, 0.1}};
  for (int k = 1; k <= 300; ++k) {
    const double phi = k == 300 ? 1.0 : std::min(1.0, points.back().phi + 0.9 / 300.0 * 2.0 * unit(rng));
    points.push_back({points.back().t + std::pow(10.0, -3.0 + 5.0 * unit(rng)), phi});
  }
  const CreepWeightedLoad load(law, 1.0, LoadShape::table(points));
  const double end = points.back().t;
  for (const double t : {1e-3, 0.7, 13.0, 0.5 * end, end * (1.0 - 1e-9), end, 2.0 * end, 1e3 * end}) {
    double g = 0.1 * law.creep(t);
    double rate = 0.1 * law.creep_rate(t);
    for (std::size_t k = 1; k < points.size(); ++k) {
      const double a = points[k - 1].t;
      if (!(t > a)) break;
      const double b = std::min(points[k].t, t);
      const double slope = (points[k].phi - points[k - 1].phi) / (points[k].t - points[k - 1].t);
      g += slope * law.creep_integral(t - b, b - a);
      rate += slope * (law.creep(t - a) - (t > points[k].t ? law.creep(t - points[k].t) : 0.0));
    }
    EXPECT_NEAR(load.response(t), g, 1e-12 * g) << "t = " << t;
    // The direct rate cancels (each piece adds J(t - t_a) - J(t - t_b), two numbers near
    // J(inf)): its own rounding is about eps J(inf) a piece, which bounds the agreement.
    const double rounding = 2.0 * std::numeric_limits<double>::epsilon() * law.creep_final() * 300.0;
    EXPECT_NEAR(load.response_rate(t), rate, 1e-10 * std::abs(rate) + rounding) << "t = " << t;
  }
}

// g_ramp(t) - J(t) = -(t_r/2) J'(t) + O(t_r^2): first order in the ramp time.
TEST(CreepWeightedLoad, ramp_converges_to_the_step_at_first_order) {
  const StandardLinearSolid sls(5.0);
  const double t = 1.5;
  double previous = 0.0;
  for (const double t_r : {1e-1, 1e-2, 1e-3, 1e-4}) {
    const double error = std::abs(CreepWeightedLoad(sls, 1.0, LoadShape::ramp(t_r)).response(t) - sls.creep(t));
    if (previous > 0.0) {
      EXPECT_NEAR(std::log10(previous / error), 1.0, 0.03) << "t_r = " << t_r;
    }
    previous = error;
  }
}

TEST(Level1Pressure, carries_the_ramped_nominal_load) {
  ContactProblem problem;
  problem.l = 1.0;
  problem.pbar0 = 0.02;
  problem.dh = 10.0;  // level 2 never touches: the single-level phase throughout
  problem.loading = LoadShape::ramp(2.0);
  const StandardLinearSolid sls(2.5);
  const Level1Pressure pressure(problem, sls);
  const SingleLevel single(problem.l, problem.shape);
  for (const double t : {0.5, 2.0, 3.0, 8.0}) {
    EXPECT_NEAR(pressure.contact_radius(t), single.contact_radius(0.02 * sls_ramp(2.5, 2.0, t)), 1e-14);
    const double nominal = 0.02 * std::min(t / 2.0, 1.0) * problem.l * problem.l;
    EXPECT_NEAR(pressure.total_load(t), nominal, 1e-9 * nominal) << "t = " << t;
  }
}

TEST(PointUnderRamp, touches_where_h_reaches_dh_and_names_when) {
  const StandardLinearSolid sls(4.0);
  ContactProblem problem;
  problem.l = 0.75;
  problem.pbar0 = 0.03;
  const SingleLevel single(problem.l, problem.shape);
  for (const double t_r : {0.5, 3.0}) {
    problem.loading = LoadShape::ramp(t_r);
    for (const double dh : {0.01, 0.03, 0.05}) {
      problem.dh = dh;
      const PointResult r = evaluate_point(problem, sls, {{0.0, 0.3, t_r, 1.1 * t_r, 4.0, 12.0}, {}});
      ASSERT_TRUE(r.t_star.has_value()) << "dh = " << dh;
      const double X = problem.pbar0 * sls_ramp(4.0, t_r, *r.t_star);
      EXPECT_NEAR(single.displacement_difference(single.contact_radius(X), X), dh, 1e-10) << "dh = " << dh;
      EXPECT_EQ(r.regime, *r.t_star <= t_r ? Regime::immediate : Regime::delayed) << "dh = " << dh;
      EXPECT_TRUE(r.valid()) << r.reason();
      for (const Snapshot& s : r.series) {
        const double nominal = problem.pbar0 * std::min(s.t / t_r, 1.0) * problem.l * problem.l;
        EXPECT_NEAR(s.P1 + s.P2, nominal, 1e-9 * problem.pbar0) << "t = " << s.t;
      }
    }
  }
}

// t*, a1 and a2 of a ramp approach the step's as t_r -> 0 at first order.
TEST(PointUnderRamp, converges_to_the_step_at_first_order) {
  const StandardLinearSolid sls(4.0);
  ContactProblem problem;
  problem.l = 0.75;
  problem.pbar0 = 0.03;
  problem.dh = 0.04;
  const EvaluationOptions options{{3.0}, {}};
  const PointResult step = evaluate_point(problem, sls, options);
  ASSERT_EQ(step.regime, Regime::delayed);
  double previous_t = 0.0, previous_a2 = 0.0;
  for (const double t_r : {1e-1, 1e-2, 1e-3}) {
    problem.loading = LoadShape::ramp(t_r);
    const PointResult r = evaluate_point(problem, sls, options);
    const double error_t = std::abs(*r.t_star - *step.t_star);
    const double error_a2 = std::abs(r.series[0].a2 - step.series[0].a2);
    if (previous_t > 0.0) {
      EXPECT_NEAR(std::log10(previous_t / error_t), 1.0, 0.05) << "t_r = " << t_r;
      EXPECT_NEAR(std::log10(previous_a2 / error_a2), 1.0, 0.05) << "t_r = " << t_r;
    }
    previous_t = error_t;
    previous_a2 = error_a2;
  }
}
