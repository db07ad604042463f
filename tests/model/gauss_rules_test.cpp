// The Gauss rules against their defining moments (closed forms, not the code under test):
// Legendre integrates x^m over [-1, 1] to 2/(m + 1) (m even) and 0 (m odd) for m < 2n;
// Laguerre integrates x^m exp(-x) over [0, inf) to m! for m < 2n.

#include <gtest/gtest.h>

#include <cmath>

#include "model/numerics/gauss_rules.hpp"

using namespace punchsweep::model;

TEST(GaussRules, legendre_integrates_polynomials_of_degree_below_2n) {
  for (const int n : {1, 2, 5, 12, 16}) {
    const GaussRule& rule = gauss_legendre(n);
    for (int m = 0; m < 2 * n; ++m) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], m);
      EXPECT_NEAR(sum, m % 2 == 0 ? 2.0 / (m + 1) : 0.0, 1e-14) << "n = " << n << ", m = " << m;
    }
  }
}

TEST(GaussRules, laguerre_integrates_polynomials_against_exp_minus_x) {
  for (const int n : {1, 4, 10, 12}) {
    const GaussRule& rule = gauss_laguerre(n);
    ASSERT_EQ(static_cast<int>(rule.nodes.size()), n);
    for (int i = 0; i < n; ++i) {
      EXPECT_GT(rule.weights[i], 0.0);
      if (i > 0) {
        EXPECT_GT(rule.nodes[i], rule.nodes[i - 1]);
      }
    }
    for (int m = 0; m < 2 * n; ++m) {
      double sum = 0.0;
      for (int i = 0; i < n; ++i) sum += rule.weights[i] * std::pow(rule.nodes[i], m);
      EXPECT_NEAR(sum / std::tgamma(m + 1.0), 1.0, 1e-12) << "n = " << n << ", m = " << m;
    }
  }
  // The 10-point rule's last node (LoadHistory keeps it inside the smooth history: 50 tau_k).
  EXPECT_NEAR(gauss_laguerre(10).nodes.back(), 29.92069701227389, 1e-12);
}

TEST(GaussRules, orders_outside_their_range_are_refused) {
  EXPECT_THROW(gauss_legendre(0), std::invalid_argument);
  EXPECT_THROW(gauss_legendre(129), std::invalid_argument);
  EXPECT_THROW(gauss_laguerre(0), std::invalid_argument);
  EXPECT_THROW(gauss_laguerre(33), std::invalid_argument);
}
