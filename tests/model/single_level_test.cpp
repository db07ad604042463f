#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "model/problem/shape.hpp"
#include "model/paper/single_level.hpp"

using namespace punchsweep::model;

TEST(SingleLevel, D_starts_at_pi_and_vanishes_at_the_radius_limit) {
  EXPECT_NEAR(SingleLevel::D(0.0), std::numbers::pi, 1e-15);
  EXPECT_NEAR(SingleLevel::D(SingleLevel::kScaledRadiusLimit), 0.0, 1e-13);
  EXPECT_LT(SingleLevel::kScaledRadiusLimit, 1.0);  // "D decreases to 0 before a = l"
}

TEST(SingleLevel, contact_radius_matches_model_notes) {
  // docs/model.md section 9: pbar0 = 0.06, l = 0.75: a1 = 0.2824306 at J = 1, 0.3626029 at J = 2.5.
  const SingleLevel single(0.75, Shape{2, 0.5});
  EXPECT_NEAR(single.contact_radius(0.06 * 1.0), 0.2824306, 5e-8);
  EXPECT_NEAR(single.contact_radius(0.06 * 2.5), 0.3626029, 5e-8);
}

TEST(SingleLevel, contact_radius_solves_eq_9_5) {
  // Residual of the printed (corrected) eq 9.5: a1^(s+1)/D = A1^2 X / (5 K_P).
  for (int s = 1; s <= 6; ++s) {
    const Shape shape{s, 0.8};
    const double l = 0.9;
    const SingleLevel single(l, shape);
    for (const double X : {1e-5, 0.01, 0.2, 5.0}) {
      const double a = single.contact_radius(X);
      const double A1sq = 5.0 / std::numbers::pi * l * l;
      const double lhs = std::pow(a, s + 1) / SingleLevel::D(a / l);
      const double rhs = A1sq * X / (5.0 * load_coefficient(shape));
      EXPECT_NEAR(lhs / rhs, 1.0, 1e-12) << "s = " << s << ", X = " << X;
      EXPECT_NEAR(single.creep_scaled_pressure(a) / X, 1.0, 1e-12);
    }
  }
}

TEST(SingleLevel, isolated_punch_limit_gives_hertz_and_sneddon) {
  // l -> infinity with the punch load P = pbar0 l^2 held: the interaction terms vanish and
  // a1 must be the isolated-punch radius, h the isolated-punch depth. The far-field
  // correction to h is 2 P G(0) / l ~ 1e-9 here, so 1e-7 relative is a real check.
  const double l = 1e7;
  const double P = 0.01;
  const double X = P / (l * l);
  {  // Hertz: a = (3 P R / (4 E*))^(1/3), d = a^2/R.
    const SingleLevel single(l, Shape{2, 0.5});
    const double a = std::cbrt(0.75 * P);
    EXPECT_NEAR(single.contact_radius(X) / a, 1.0, 1e-9);
    EXPECT_NEAR(single.displacement_difference(a, X) / (a * a), 1.0, 1e-7);
  }
  {  // Sneddon cone f = C r: a = sqrt(2 P / (pi C E*)), d = (pi/2) C a.
    const double C = 0.3;
    const SingleLevel single(l, Shape{1, C});
    const double a = std::sqrt(2.0 * P / (std::numbers::pi * C));
    EXPECT_NEAR(single.contact_radius(X) / a, 1.0, 1e-9);
    EXPECT_NEAR(single.displacement_difference(a, X) / (std::numbers::pi / 2 * C * a), 1.0, 1e-7);
  }
  {  // Sneddon s = 3, f = C r^3: P = (9 pi / 8) C E* a^4, d = (3 pi / 4) C a^3.
    const double C = 0.5;
    const SingleLevel single(l, Shape{3, C});
    const double a = std::pow(P / (9.0 * std::numbers::pi / 8.0 * C), 0.25);
    EXPECT_NEAR(single.contact_radius(X) / a, 1.0, 1e-9);
    EXPECT_NEAR(single.displacement_difference(a, X) / (0.75 * std::numbers::pi * C * a * a * a), 1.0,
                1e-7);
  }
}

TEST(SingleLevel, h_of_a1_increases_for_s_1_2_3_fig_9_2) {
  // Fig. 9.2: C = 1, l = 0.5; h(a1) (X eliminated with eq 9.5) and its derivative > 0,
  // over the whole admissible range of a1.
  const double l = 0.5;
  for (int s = 1; s <= 3; ++s) {
    const SingleLevel single(l, Shape{s, 1.0});
    double previous = 0.0;
    const int n = 2000;
    for (int i = 1; i < n; ++i) {
      const double a = SingleLevel::kScaledRadiusLimit * l * i / n;
      const double h = single.displacement_difference(a);
      EXPECT_GT(h, previous) << "s = " << s << ", a1 = " << a;
      previous = h;
    }
  }
}

TEST(SingleLevel, contact_radius_at_gap_inverts_h) {
  for (int s = 1; s <= 8; ++s) {
    const SingleLevel single(0.8, Shape{s, 0.6});
    for (const double dh : {1e-6, 1e-3, 0.03, 0.2, 3.0}) {
      const double a = single.contact_radius_at_gap(dh);
      EXPECT_NEAR(single.displacement_difference(a) / dh, 1.0, 1e-11) << "s = " << s << ", dh = " << dh;
    }
  }
  EXPECT_EQ(SingleLevel(0.8, Shape{2, 0.5}).contact_radius_at_gap(0.0), 0.0);
}
