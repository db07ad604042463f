// The periodic model where its spots are small (docs/model.md, section 14.7): the small-spot
// table against the refined localization it is made from, its limits (the isolated punch,
// the lattice's exact far field), the hand-over to the boundary elements' tables, and the
// model at points: the isolated punch's closed forms (Lee and Radok), the refined model
// wherever its spots are small, and two levels at one height.
#include <gtest/gtest.h>

#include "shipped_tables.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "engine/periodic_tables.hpp"
#include "engine/point_evaluation.hpp"
#include "model/periodic/periodic_solution.hpp"
#include "model/shells/single_level_shells.hpp"
#include "model/periodic/small_spot_table.hpp"
#include "model/numerics/lattice.hpp"
#include "model/periodic/small_spot_builder.hpp"
#include "model/shells/two_level_shells.hpp"

using namespace punchsweep;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

model::Localization refined() {
  model::Localization loc;
  loc.shells = model::Localization::kRefinedShells;
  loc.distributed = true;
  return loc;
}

/// The isolated punch's coefficients (notes section 2), computed here: P = K_P a^(s+1),
/// d = K_d a^s for f = C r^s.
double K_P(int s, double C) {
  return std::pow(2.0, s - 1) * s * s * std::pow(std::tgamma(s / 2.0), 2) * C / ((s + 1) * std::tgamma(s));
}
double K_d(int s, double C) { return s * std::pow(std::tgamma(s / 2.0), 2) * C / (std::pow(2.0, 2 - s) * std::tgamma(s)); }

input::Keywords keywords_of(const std::vector<std::string>& args) {
  input::Keywords keywords;
  for (std::size_t i = 0; i + 1 < args.size(); i += 2) keywords.emplace_back(args[i].substr(2), args[i + 1]);
  return keywords;
}

std::string text(double x) {
  char out[40];
  std::snprintf(out, sizeof out, "%.17g", x);
  return out;
}

using test::use_shipped_tables;

}  // namespace

// The shipped tables are what the builder makes (to its Newton roots' tolerance: another
// machine's rounding may move the last bits).
TEST(SmallSpotTable, shipped_ones_are_what_the_builder_makes) {
  for (const int s : {1, 2, 3}) {
    const std::optional<model::SmallSpotTable> shipped = engine::shipped_small_spot_table(s);
    ASSERT_TRUE(shipped) << s;
    const std::vector<double> a = shipped->tables(), b = model::build_small_spot_table(s).tables();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k], b[k], 1e-11 * std::abs(b[k])) << "s " << s << " at " << k;
  }
}

namespace {

// Between its samples the table is the refined localization with the exact far field: the
// single level's h and a1 to 1e-7 (measured 1e-10 to 7e-9), the two levels' radii to 1e-4
// of a1 and Q2 to 1e-4 of the load (measured 5e-7 to 2e-5, s = 3 the largest), at loads
// log-uniform over eight decades below the top of the table and height differences uniform.
void expect_meets_the_refined_localization(const model::SmallSpotTable& t, int trials, std::mt19937_64& random) {
  const int s = t.s;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const model::SingleLevelShells single(1.0, model::Shape{s, 1.0}, refined());
  const double lo = std::min(1e-10, 1e-8 * t.xi_top());
  for (int trial = 0; trial < trials; ++trial) {
    const double xi = std::exp(std::log(lo) + unit(random) * std::log(t.xi_top() / lo));
    const double a = single.contact_radius(xi), h_own = single.displacement_difference(a, xi);
    const model::PeriodicState table = t.single(xi);
    EXPECT_NEAR(table.h, h_own + t.far_field_correction * xi, 1e-7 * table.h) << "s " << s << " xi " << xi;
    EXPECT_NEAR(table.a1, a, 1e-7 * a) << "s " << s << " xi " << xi;
    // Two levels at eta: the refined state at the height difference eta h_own.
    const double eta = unit(random);
    model::ContactProblem problem;
    problem.l = 1.0;
    problem.shape = {s, 1.0};
    problem.dh = eta * h_own;
    const model::TwoLevelShells system(problem, refined());
    const model::PeriodicState two = t.two_level(xi, eta);
    const model::TwoLevelSolve direct = system.solve(xi, {two.a1, two.a2, two.Q1, two.Q2});
    ASSERT_TRUE(direct.converged) << "s " << s << " xi " << xi << " eta " << eta;
    EXPECT_NEAR(two.a1, direct.state.a1, 1e-4 * direct.state.a1) << "s " << s << " xi " << xi << " eta " << eta;
    EXPECT_NEAR(two.a2, direct.state.a2, 1e-4 * direct.state.a1) << "s " << s << " xi " << xi << " eta " << eta;
    EXPECT_NEAR(two.Q2, direct.state.Q2, 1e-4 * xi) << "s " << s << " xi " << xi << " eta " << eta;
  }
}

// As the load vanishes the table is the isolated punch (a1 -> a0, h - K_d a1^s -> Psi xi,
// Psi the lattice's exact far field), and two isolated punches at v = 0.
void expect_the_isolated_punch_in_the_far_field(const model::SmallSpotTable& t) {
  const int s = t.s;
  // Spots of 0.001 l to 0.01 l; the spots' size enters at O(a^2) (1.2e-4 at a = 0.01 l).
  for (const double a0 : {1e-3, 3e-3, 1e-2}) {
    const double xi = K_P(s, 1.0) * std::pow(a0, s + 1);
    const model::PeriodicState state = t.single(xi);
    EXPECT_NEAR(state.a1, a0, 1e-6 * a0) << "s " << s << " xi " << xi;
    EXPECT_NEAR((state.h - K_d(s, 1.0) * std::pow(state.a1, s)) / xi, model::lattice_far_field_constant(),
                1e-5 + 2.0 * a0 * a0)
        << "s " << s << " xi " << xi;
  }
  for (const double eta : {0.0, 0.1, 0.5, 0.9, 0.999}) {
    const auto [y1, y2] = model::SmallSpotTable::isolated_two_level(s, eta);
    EXPECT_NEAR(std::pow(y1, s) - std::pow(y2, s), eta, 1e-14) << s;
    EXPECT_NEAR(std::pow(y1, s + 1) + std::pow(y2, s + 1), 1.0, 1e-14) << s;
  }
}

}  // namespace

TEST(SmallSpotTable, meets_the_refined_localization_between_its_samples) {
  std::mt19937_64 random(34);
  for (const int s : {1, 2, 3}) expect_meets_the_refined_localization(*engine::shipped_small_spot_table(s), 25, random);
}

TEST(SmallSpotTable, tends_to_the_isolated_punch_in_the_lattices_far_field) {
  for (const int s : {1, 2, 3}) expect_the_isolated_punch_in_the_far_field(*engine::shipped_small_spot_table(s));
}

// Every exponent the periodic model takes has its table, built as on first use: s = 7 to 16
// found no two-level state at one height (eta = 0) at the top of the table, where the single
// level's radius band (0.34 l to 0.40 l) put two equal spots within 2% of merging; their
// bands end at 0.34 l, and 128 samples across the height difference keep level 2's radius
// as close as the shipped tables' (measured with 40 points a table: 2e-5 of a1 at s = 15).
// Each meets the refined localization and the isolated punch as the shipped ones do.
TEST(SmallSpotTable, every_exponent_is_built_and_meets_its_limits) {
  std::mt19937_64 random(35);
  for (int s = 4; s <= model::Localization::kMaxPeriodicExponent; ++s) {
    const model::SmallSpotTable t = model::build_small_spot_table(s);
    expect_meets_the_refined_localization(t, 10, random);
    expect_the_isolated_punch_in_the_far_field(t);
  }
}

TEST(SmallSpotTable, refuses_inconsistent_numbers) {
  const model::SmallSpotTable t = *engine::shipped_small_spot_table(2);
  ASSERT_TRUE(model::SmallSpotTable::from_tables(t.tables()));
  std::vector<double> numbers = t.tables();
  numbers.pop_back();
  EXPECT_FALSE(model::SmallSpotTable::from_tables(numbers));
  numbers = t.tables();
  numbers[10] = 1.01;  // a1 / a0 of the single level at v = 0: the isolated punch at v = 0 is not a ratio of one
  EXPECT_FALSE(model::SmallSpotTable::from_tables(numbers));
  numbers = t.tables();
  numbers.back() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(model::SmallSpotTable::from_tables(numbers));
}

// The hand-over (periodic_solution.hpp): continuous, and its slope too, at the ends of both bands,
// and what a switch without the blend would have jumped by there: the two tables' difference
// across each band (measured: h 3.5e-6 to 4e-6 over the gap's band, a1 1.8e-4 to 3.4e-4 over
// the radii's; the bounds are the tables' accuracy against N = 2048, docs/model.md, 14.7).
TEST(PeriodicSolution, hands_over_smoothly) {
  for (const int s : {1, 2, 3}) {
    const std::shared_ptr<const model::PeriodicSolution> p = engine::periodic_solution_for(s, std::nullopt, true);
    const model::SmallSpotTable& small = p->small();
    const int n = s + 1;
    const auto xi_of = [n](double v) { return std::pow(v, n); };
    double jump_h = 0.0, jump_a = 0.0;
    for (int k = 0; k <= 50; ++k) {
      const double xi_gap = xi_of(small.v_gap_hand + (small.v_gap_top - small.v_gap_hand) * k / 50.0);
      jump_h = std::max(jump_h, std::abs(small.single(xi_gap).h / p->tables().single(xi_gap).h - 1.0));
      const double xi = xi_of(small.v_hand + (small.v_top - small.v_hand) * k / 50.0);
      jump_a = std::max(jump_a, std::abs(small.single(xi).a1 / p->tables().single(xi).a1 - 1.0));
    }
    std::printf("s = %d: across their bands the two tables differ by %.1e in h, %.1e in a1\n", s, jump_h, jump_a);
    EXPECT_LT(jump_h, 1e-5) << s;
    EXPECT_LT(jump_a, 1e-3) << s;
    // At each end of each band: no step in the value beyond its slope's; in h's slope none
    // beyond 1e-4, in a1's none beyond the steps the boundary elements' own a1 curve takes at
    // its samples (its rims' estimate: 1e-2 to 3e-1 of the slope).
    const auto slope_of = [&](const auto& f, double w, double e) { return (f(w + 0.1 * e) - f(w - 0.1 * e)) / (0.2 * e); };
    double own_steps = 0.0;
    for (int k = 5; k < 60; ++k) {
      const double v = p->tables().sample_v(k), e = 1e-6 * v;
      const auto a1 = [&](double w) { return p->tables().single(xi_of(w)).a1; };
      own_steps = std::max(own_steps, std::abs(slope_of(a1, v - e, e) / slope_of(a1, v + e, e) - 1.0));
    }
    for (const double v : {small.v_gap_hand, small.v_gap_top, small.v_hand, small.v_top}) {
      const double e = 1e-6 * v;
      for (const bool gap : {true, false}) {
        const auto f = [&](double w) { return gap ? p->single(xi_of(w)).h : p->single(xi_of(w)).a1; };
        const double left = slope_of(f, v - e, e), right = slope_of(f, v + e, e);
        EXPECT_NEAR(f(v + e) - f(v - e), e * (left + right), 1e-3 * e * std::abs(left + right)) << s << " at v " << v;
        EXPECT_NEAR(left, right, (gap ? 1e-4 : own_steps) * std::abs(left)) << s << " at v " << v << (gap ? " h" : " a1");
      }
    }
  }
}

// The touchdown inverts the blended h in each of its stretches, and the two-level state
// starts there from the single level's: a2 = 0 and Q2 = 0 to the rounding of the touchdown
// (a2 grows as (xi - xi*)^(1/s), so 1e-15 of the load leaves a2 ~ 1e-5 a1), the same a1 (to
// 1e-9 below the hand-over; above, the boundary elements' surface reads its touchdown radii
// across its rows, within 3e-5 of the single level's, as it did before the small-spot table).
TEST(PeriodicSolution, touches_down_where_h_says_and_starts_from_the_single_level) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const int s : {1, 2, 3}) {
    const std::shared_ptr<const model::PeriodicSolution> p = engine::periodic_solution_for(s, std::nullopt, true);
    const model::SmallSpotTable& small = p->small();
    for (const double xi : {1e-9, 1e-4, 0.5 * small.xi_gap_hand(), 0.5 * (small.xi_gap_hand() + small.xi_gap_top()),
                            0.5 * (small.xi_gap_top() + small.xi_hand()), 0.5 * (small.xi_hand() + small.xi_top()),
                            small.xi_top() * 3.0, std::exp(std::log(1e-8) + unit(random) * std::log(1e8))}) {
      const double delta = p->single(xi).h;
      if (!(delta < p->delta_top())) continue;
      const double star = p->touchdown(delta);
      EXPECT_NEAR(star, xi, 1e-12 * xi) << "s " << s << " xi " << xi;
      const model::PeriodicState at = p->two_level(star, delta), single = p->single(star);
      EXPECT_NEAR(at.a2, 0.0, 1e-5 * single.a1) << "s " << s << " xi " << xi;
      EXPECT_NEAR(at.Q2, 0.0, 1e-8 * xi) << "s " << s << " xi " << xi;
      EXPECT_NEAR(at.a1, single.a1, (xi <= small.xi_hand() ? 1e-9 : 3e-5) * single.a1) << "s " << s << " xi " << xi;
    }
  }
}

// A sparse lattice at a tiny load is one isolated punch creeping (Lee and Radok 1960): the
// radius follows a1^(s+1) = P J(t) / K_P, P = pbar l^2, J(t) = T - (T - 1) e^-t; s = 2 is
// Hertz, 1 and 3 the power-law punch (notes section 2). The gap h(0) = K_d a1^s + Psi P / l
// (lattice.hpp). l = 10, pbar = 1e-6, T = 5: the lattice moves a1 by (a1/l)^3 < 1e-6.
TEST(PeriodicModel, an_isolated_spot_follows_lee_and_radok) {
  use_shipped_tables();
  const double l = 10.0, pbar = 1e-6, T = 5.0, C = 0.5;
  const std::vector<double> times = {0.0, 0.5, 1.0, 2.0, 5.0};
  for (const int s : {1, 2, 3}) {
    const engine::PointRun m = engine::evaluate_point(keywords_of({"--l", "10", "--dh", "1", "--T", "5", "--pbar", "1e-6", "--s",
                                                             std::to_string(s), "--times", "0,0.5,1,2,5"}));
    ASSERT_TRUE(m.result.valid()) << m.result.reason();
    ASSERT_EQ(m.result.regime, model::Regime::never);
    const double P = pbar * l * l;
    for (std::size_t k = 0; k < times.size(); ++k) {
      const double J = T - (T - 1.0) * std::exp(-times[k]);
      const double a = std::pow(P * J / K_P(s, C), 1.0 / (s + 1));
      EXPECT_NEAR(m.result.series[k].a1, a, 1e-4 * a) << "s " << s << " t " << times[k];
    }
    const double a0 = std::pow(P / K_P(s, C), 1.0 / (s + 1));
    const double h0 = K_d(s, C) * std::pow(a0, s) + model::lattice_far_field_constant() * P / l;
    EXPECT_NEAR(m.result.h_0, h0, 1e-5 * h0) << "s " << s;
  }
}

// Where the refined localization is valid and its spots are small (a1 < 0.05 l at every
// time), the periodic model is it, with the lattice's exact far field: over a wide grid of
// l 0.05-20, pbar 1e-8-1e-2, s 1-3 and height differences from 0 to past h_inf, loads within
// 1e-3 of pbar l^2 and radii within 0.5% (a2 within 0.5% of a1 where it has just touched:
// the far field moves its touchdown by up to 3e-4 of the load).
TEST(PeriodicModel, equals_the_refined_model_where_spots_are_small) {
  use_shipped_tables();
  int compared = 0;
  double worst_load = 0.0, worst_a1 = 0.0, worst_a2 = 0.0;
  for (const int s : {1, 2, 3}) {
    for (int i = 0; i < 7; ++i) {
      const double l = 0.05 * std::pow(400.0, i / 6.0);
      for (int j = 0; j < 7; ++j) {
        const double pbar = 1e-8 * std::pow(1e6, j / 6.0);
        // Height differences from the gaps at t = 0 and t = inf of this (l, pbar).
        const std::vector<std::string> base = {"--l", text(l), "--T", "3", "--pbar", text(pbar), "--s", std::to_string(s),
                                               "--times", "0,0.3,1,5"};
        std::vector<std::string> probe = base;
        probe.insert(probe.end(), {"--dh", "1e9"});
        const engine::PointRun free = engine::evaluate_point(keywords_of(probe));
        for (const double share : {0.0, 0.5, 1.2, 2.0, 3.5}) {
          const double dh = share * free.result.h_0;
          std::vector<std::string> args = base;
          args.insert(args.end(), {"--dh", text(dh)});
          std::vector<std::string> ref_args = args;
          ref_args.insert(ref_args.end(), {"--localization", "refined"});
          const engine::PointRun r = engine::evaluate_point(keywords_of(ref_args));
          if (!r.result.valid() || r.result.series.back().a1 > 0.05 * l) continue;
          const engine::PointRun p = engine::evaluate_point(keywords_of(args));
          ASSERT_TRUE(p.result.valid()) << p.result.reason();
          ASSERT_EQ(p.result.regime, r.result.regime) << "s " << s << " l " << l << " pbar " << pbar << " dh " << dh;
          const double load = pbar * l * l;
          for (std::size_t k = 0; k < p.result.series.size(); ++k) {
            const model::Snapshot &a = p.result.series[k], &b = r.result.series[k];
            const std::string at = "s " + std::to_string(s) + " l " + text(l) + " pbar " + text(pbar) + " dh " + text(dh) +
                                   " t " + text(a.t);
            worst_load = std::max({worst_load, std::abs(a.P1 - b.P1) / load, std::abs(a.P2 - b.P2) / load});
            worst_a1 = std::max(worst_a1, std::abs(a.a1 / b.a1 - 1.0));
            worst_a2 = std::max(worst_a2, std::abs(a.a2 - b.a2) / std::max(b.a2, b.a1));
            EXPECT_NEAR(a.P1, b.P1, 1e-3 * load) << at;
            EXPECT_NEAR(a.P2, b.P2, 1e-3 * load) << at;
            EXPECT_NEAR(a.a1, b.a1, 5e-3 * b.a1) << at;
            EXPECT_NEAR(a.a2, b.a2, 5e-3 * std::max(b.a2, b.a1)) << at;
          }
          ++compared;
        }
      }
    }
  }
  std::printf("compared %d points: loads within %.1e of pbar l^2, a1 within %.1e, a2 within %.1e\n", compared,
              worst_load, worst_a1, worst_a2);
  EXPECT_GT(compared, 150);
}

// Two levels at one height (dh = 0) are one square lattice of pitch l / sqrt(2): over l
// 0.05-20, pbar 1e-8-0.1, s 1-3, every point is valid and immediate, its levels' radii and
// loads equal to the last bit, and each level the single level of that lattice (the same
// table read at its load: to 1e-8 where the spots are small, to the boundary elements' 3e-3
// where they are not).
TEST(PeriodicModel, two_levels_at_one_height_are_one_lattice) {
  use_shipped_tables();
  std::mt19937_64 random(200);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double l = 0.05 * std::pow(400.0, unit(random)), pbar = 1e-8 * std::pow(1e7, unit(random));
    const int s = 1 + static_cast<int>(random() % 3);
    const double T = 1.0 + 9.0 * unit(random);
    const std::vector<std::string> args = {"--l", text(l), "--dh", "0", "--T", text(T), "--pbar", text(pbar), "--s",
                                           std::to_string(s), "--times", "0,1,5"};
    const engine::PointRun m = engine::evaluate_point(keywords_of(args));
    ASSERT_TRUE(m.result.valid()) << m.result.reason();
    ASSERT_EQ(m.result.regime, model::Regime::immediate);
    EXPECT_EQ(m.result.a1_inf, m.result.a2_inf);
    const engine::PointRun one = engine::evaluate_point(keywords_of({"--l", text(l / std::numbers::sqrt2), "--dh", "1e9", "--T",
                                                               text(T), "--pbar", text(pbar), "--s", std::to_string(s),
                                                               "--times", "0,1,5"}));
    for (std::size_t k = 0; k < 3; ++k) {
      const model::Snapshot &a = m.result.series[k], &b = one.result.series[k];
      EXPECT_EQ(a.a1, a.a2);
      EXPECT_EQ(a.P1, a.P2);
      const bool small = b.a1 < 0.15 * l / std::numbers::sqrt2;  // both below the hand-over
      EXPECT_NEAR(a.a1, b.a1, (small ? 1e-8 : 3e-3) * b.a1) << "l " << l << " pbar " << pbar << " s " << s << " t " << a.t;
    }
  }
}
