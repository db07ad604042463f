#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

#include "model/numerics/lattice.hpp"
#include "model/paper/long_term_guide.hpp"
#include "model/paper/single_level.hpp"
#include "model/paper/elastic_two_level.hpp"
#include "model/paper/two_level.hpp"

using namespace punchsweep::model;

namespace {

const ContactProblem kTableProblem{0.75, 0.05, 0.06, Shape{2, 0.5}};

struct TableRow {
  double E, P1, P2, a1, a2, A1, A2;
};

}  // namespace

TEST(ElasticTwoLevel, reproduces_table_9_1_to_the_printed_digits) {
  // Table 9.1 (pbar0 = 0.06, l = 0.75, dh = 0.05), +-1 in the last printed digit.
  const TableRow rows[] = {
      {1.0, 0.0335, 0.0003, 0.2815, 0.0567, 0.9454, 0.8472},
      {0.8, 0.0327, 0.0011, 0.2976, 0.0926, 0.9432, 0.8497},
      {0.5, 0.0308, 0.0029, 0.3302, 0.1455, 0.9379, 0.8555},
      {0.4, 0.0300, 0.0038, 0.3447, 0.1662, 0.9355, 0.8581},
  };
  for (const TableRow& row : rows) {
    const ElasticTwoLevel r = solve_elastic_two_level(kTableProblem, row.E);
    SCOPED_TRACE("E/E0 = " + std::to_string(row.E));
    ASSERT_TRUE(r.converged);
    ASSERT_TRUE(r.level2_touches);
    EXPECT_NEAR(r.state.Q1 * row.E, row.P1, 1e-4);  // P = E Q
    EXPECT_NEAR(r.state.Q2 * row.E, row.P2, 1e-4);
    EXPECT_NEAR(r.state.a1, row.a1, 1e-4);
    EXPECT_NEAR(r.state.a2, row.a2, 1e-4);
    EXPECT_NEAR(r.radii.A1, row.A1, 1e-4);
    EXPECT_NEAR(r.radii.A2, row.A2, 1e-4);
  }
}

TEST(ElasticTwoLevel, matches_the_more_digits_row_of_the_model_notes) {
  const ElasticTwoLevel r = solve_elastic_two_level(kTableProblem, 1.0);
  EXPECT_NEAR(r.state.Q1, 0.0334547, 5e-8);
  EXPECT_NEAR(r.state.a1, 0.2815067, 5e-8);
  EXPECT_NEAR(r.state.a2, 0.0566924, 5e-8);
  EXPECT_NEAR(r.radii.A1, 0.9453464, 5e-8);
  EXPECT_NEAR(r.radii.A2, 0.8472096, 5e-8);
}

TEST(ElasticTwoLevel, loads_sum_to_nominal_load_and_radii_satisfy_eq_9_13) {
  for (const double E : {1.0, 0.6, 0.3}) {
    const ElasticTwoLevel r = solve_elastic_two_level(kTableProblem, E);
    const double X = kTableProblem.pbar0 / E;
    const double l = kTableProblem.l;
    EXPECT_NEAR((r.state.Q1 + r.state.Q2) / (l * l * X), 1.0, 1e-12);
    EXPECT_NEAR(std::numbers::pi * r.radii.A1 * r.radii.A1 * X, 5 * r.state.Q1 + 4 * r.state.Q2, 1e-12);
    EXPECT_NEAR(std::numbers::pi * r.radii.A2 * r.radii.A2 * X, 5 * r.state.Q2 + 4 * r.state.Q1, 1e-12);
  }
}

TEST(ElasticTwoLevel, equal_heights_give_equal_spots) {
  // dh = 0: both levels form one square lattice of pitch l/sqrt(2); by symmetry a1 = a2.
  for (int s = 1; s <= 3; ++s) {
    const ElasticTwoLevel r = solve_elastic_two_level(ContactProblem{0.75, 0.0, 0.04, Shape{s, 0.5}}, 1.0);
    ASSERT_TRUE(r.converged);
    EXPECT_NEAR(r.state.a1 / r.state.a2, 1.0, 1e-10) << "s = " << s;
    EXPECT_NEAR(r.state.Q1 / r.state.Q2, 1.0, 1e-10);
  }
}

TEST(ElasticTwoLevel, below_touchdown_only_level_one_carries_load) {
  // Table case with E large enough that h < dh: level 2 stays free.
  const ElasticTwoLevel r = solve_elastic_two_level(kTableProblem, 5.0);
  EXPECT_FALSE(r.level2_touches);
  EXPECT_EQ(r.state.a2, 0.0);
  EXPECT_NEAR(r.state.Q1, kTableProblem.l * kTableProblem.l * kTableProblem.pbar0 / 5.0, 1e-15);
}

TEST(TwoLevelSystem, joins_the_single_level_solution_continuously_at_touchdown) {
  // Delayed radii: at X slightly above X*, a1 -> a1*, a2 -> 0, Q2 -> 0.
  for (int s = 1; s <= 3; ++s) {
    const ContactProblem p{0.75, 0.075, 0.06, Shape{s, 0.5}};
    const Lattice lattice{p.l};
    const TwoLevelSystem system(p, NominalRadii{lattice.A1_single(), lattice.A_single()});
    const SingleLevel single(p.l, p.shape);
    const double a1_star = single.contact_radius_at_gap(p.dh);
    const double X_star = single.creep_scaled_pressure(a1_star);
    double previous_gap = 1.0;
    for (const double eps : {1e-2, 1e-4, 1e-6, 1e-8}) {
      const TwoLevelSolve r = system.solve_from_touchdown(X_star * (1 + eps));
      ASSERT_TRUE(r.converged) << "s = " << s << ", eps = " << eps;
      const double gap = std::abs(r.state.a1 - a1_star) + r.state.a2;
      EXPECT_LT(gap, previous_gap);
      previous_gap = gap;
      EXPECT_GT(r.state.a2, 0.0);
    }
    EXPECT_LT(previous_gap, 1e-3);
  }
}

TEST(TwoLevelSystem, residuals_vanish_at_the_solution) {
  // Re-evaluate eq 9.17 and 9.19, written out here, at the returned state.
  const ElasticTwoLevel e = solve_elastic_two_level(kTableProblem, 1.0);
  const TwoLevelSystem system(kTableProblem, e.radii);
  const double X = 0.06 * 2.0;
  const TwoLevelSolve r = system.continue_to(e.state, 0.06, X);
  ASSERT_TRUE(r.converged);
  const double l = kTableProblem.l;
  const double l2 = l / std::numbers::sqrt2;
  const auto& st = r.state;
  const auto& A = e.radii;
  const double dh = depth_coefficient(kTableProblem.shape) * (st.a1 * st.a1 - st.a2 * st.a2) +
                    4.0 / std::numbers::pi *
                        (st.Q2 / std::sqrt(l2 * l2 - st.a1 * st.a1) + st.Q1 / std::sqrt(l * l - st.a1 * st.a1) -
                         st.Q1 / std::sqrt(l2 * l2 - st.a2 * st.a2) - st.Q2 / std::sqrt(l * l - st.a2 * st.a2)) -
                    2.0 * X * (std::sqrt(A.A1 * A.A1 - st.a1 * st.a1) - std::sqrt(A.A2 * A.A2 - st.a2 * st.a2));
  EXPECT_NEAR(dh, kTableProblem.dh, 1e-12);
  EXPECT_NEAR(st.Q1 + st.Q2, l * l * X, 1e-14);
}

TEST(ElasticTwoLevel, joint_newton_from_the_guide_agrees_with_the_radius_iteration) {
  // With a guide the radii are solved together with (a1, z) by Newton; without one, eq 9.13
  // is iterated around Newton. Both must find the same root.
  for (const int s : {1, 2, 3}) {
    ContactProblem problem = kTableProblem;
    problem.shape = Shape{s, 0.5};
    const LongTermGuide guide(problem);
    for (const double E : {1.0, 0.8, 0.5, 0.4, 0.3}) {
      SCOPED_TRACE("s = " + std::to_string(s) + ", E/E0 = " + std::to_string(E));
      const ElasticTwoLevel iterated = solve_elastic_two_level(problem, E);
      const ElasticTwoLevel joint = solve_elastic_two_level(problem, E, &guide);
      ASSERT_EQ(joint.level2_touches, iterated.level2_touches);
      if (!iterated.level2_touches) continue;  // single level: no radii to solve for
      // Which took the joint Newton itself, not its fallback (the iteration).
      const Lattice lattice{problem.l};
      const auto start = guide.guess(problem.pbar0 / E);
      ASSERT_TRUE(start);
      const std::optional<ElasticTwoLevel> direct = solve_elastic_jointly(
          problem, problem.pbar0 / E, *start, NominalRadii{lattice.A1_single(), lattice.A_single()});
      ASSERT_TRUE(direct);
      EXPECT_EQ(direct->state.a1, joint.state.a1);
      EXPECT_EQ(direct->radii.A2, joint.radii.A2);
      ASSERT_TRUE(iterated.converged);
      ASSERT_TRUE(joint.converged);
      EXPECT_NEAR(joint.state.a1, iterated.state.a1, 1e-12);
      EXPECT_NEAR(joint.state.a2, iterated.state.a2, 1e-10);  // a2 = sqrt(z) near touchdown
      EXPECT_NEAR(joint.state.Q1, iterated.state.Q1, 1e-13);
      EXPECT_NEAR(joint.state.Q2, iterated.state.Q2, 1e-13);
      EXPECT_NEAR(joint.radii.A1, iterated.radii.A1, 1e-12);
      EXPECT_NEAR(joint.radii.A2, iterated.radii.A2, 1e-12);
    }
  }
}

TEST(TwoLevelSystem, linearization_matches_central_differences) {
  // Away from any root: a1 = 0.3, a2 = 0.1 at X = 0.15, radii off the touchdown ones.
  const NominalRadii radii{0.95, 0.86};
  const double X = 0.15;
  const double a1 = 0.3;
  const double z = 0.01;  // s = 2: z = a2^2
  const TwoLevelSystem system(kTableProblem, radii);
  const TwoLevelSystem::Linearization lin = system.linearize(a1, std::sqrt(z), X);
  const double h = 1e-6;
  // Central difference of (r0, r1, Q1, Q2) along one of (a1, z, A1, A2).
  auto difference = [&](int k) {
    double u[4] = {a1, z, radii.A1, radii.A2};
    double v[4] = {a1, z, radii.A1, radii.A2};
    u[k] += h;
    v[k] -= h;
    const auto plus = TwoLevelSystem(kTableProblem, {u[2], u[3]}).linearize(u[0], std::sqrt(u[1]), X);
    const auto minus = TwoLevelSystem(kTableProblem, {v[2], v[3]}).linearize(v[0], std::sqrt(v[1]), X);
    return std::array<double, 4>{(plus.r[0] - minus.r[0]) / (2 * h), (plus.r[1] - minus.r[1]) / (2 * h),
                                 (plus.Q[0] - minus.Q[0]) / (2 * h), (plus.Q[1] - minus.Q[1]) / (2 * h)};
  };
  for (int k = 0; k < 4; ++k) {
    SCOPED_TRACE("variable " + std::to_string(k));
    const std::array<double, 4> fd = difference(k);
    const double* rates_r = k < 2 ? lin.r_a : lin.r_A;
    const double* rates_Q = k < 2 ? lin.Q_a : lin.Q_A;
    const int c = k % 2;
    for (int i = 0; i < 2; ++i) {
      EXPECT_NEAR(rates_r[2 * i + c], fd[i], 1e-7 * (1.0 + std::abs(fd[i])));
      EXPECT_NEAR(rates_Q[2 * i + c], fd[2 + i], 1e-7 * (1.0 + std::abs(fd[2 + i])));
    }
  }
}

TEST(LongTermGuide, radii_correction_brings_the_guess_close_to_an_immediate_root) {
  // An immediate point's long-term state uses the radii of the elastic solution at t = 0
  // (Table 9.1's first row: A = 0.9454, 0.8472, against 0.9462, 0.8463 at touchdown).
  const LongTermGuide guide(kTableProblem);
  const ElasticTwoLevel start = solve_elastic_two_level(kTableProblem, 1.0);
  const TwoLevelSystem system(kTableProblem, start.radii);
  for (const double T : {2.0, 5.0, 10.0}) {
    SCOPED_TRACE("T = " + std::to_string(T));
    const double X = kTableProblem.pbar0 * T;
    const TwoLevelSolve root = system.continue_to(start.state, kTableProblem.pbar0, X);
    ASSERT_TRUE(root.converged);
    const auto plain = guide.guess(X);
    const auto corrected = guide.guess(X, start.radii);
    ASSERT_TRUE(plain && corrected);
    auto error = [&](const TwoLevelState& g) {
      return std::max(std::abs(g.a1 - root.state.a1), std::abs(g.a2 * g.a2 - root.state.a2 * root.state.a2) / 0.75);
    };
    EXPECT_LT(error(*corrected), 0.1 * error(*plain));
    // At the touchdown radii the two guesses are the same.
    const Lattice lattice{kTableProblem.l};
    const auto same = guide.guess(X, NominalRadii{lattice.A1_single(), lattice.A_single()});
    ASSERT_TRUE(same);
    EXPECT_EQ(same->a1, plain->a1);
    EXPECT_EQ(same->a2, plain->a2);
  }
}
