#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "model/lattice.hpp"
#include "model/single_level.hpp"
#include "model/two_level.hpp"

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
