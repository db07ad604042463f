#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "model/paper/pressure.hpp"
#include "model/problem/shape.hpp"
#include "model/laws/standard_linear_solid.hpp"

using namespace punchsweep::model;

TEST(PunchPressure, sphere_is_hertz) {
  // Hertz: p = (2 a / (pi R)) sqrt(1 - r^2/a^2) E* for f = r^2/(2R).
  const double a = 0.3;
  for (const double r : {0.0, 0.1, 0.25, 0.299}) {
    EXPECT_NEAR(0.5 / std::numbers::pi * punch_pressure_shape(2, r, a),
                2.0 * a / std::numbers::pi * std::sqrt(1.0 - r * r / (a * a)), 1e-15);
  }
}

TEST(PunchPressure, cone_is_sneddon) {
  // Sneddon's cone f = C r: p = (C E*/2) arccosh(a/r).
  const double a = 0.2;
  const double C = 0.4;
  for (const double r : {0.001, 0.05, 0.19}) {
    EXPECT_NEAR(C / std::numbers::pi * punch_pressure_shape(1, r, a), 0.5 * C * std::acosh(a / r), 1e-14);
  }
}

TEST(PunchPressure, integrates_to_the_isolated_punch_load_for_every_s) {
  // int (C/pi) p_(k,m) 2 pi r dr = K_P a^(s+1), by the midpoint rule in u = sqrt(1 - r/a)
  // (independent of the model's Gauss rules).
  const double a = 0.35;
  for (int s = 1; s <= 9; ++s) {
    const Shape shape{s, 0.7};
    const int n = 400000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      const double u = (i + 0.5) / n;  // r = a (1 - u^2), dr = 2 a u du
      const double r = a * (1.0 - u * u);
      sum += shape.C / std::numbers::pi * punch_pressure_shape(s, r, a) * 2.0 * std::numbers::pi * r * 2.0 * a * u / n;
    }
    EXPECT_NEAR(sum / (load_coefficient(shape) * std::pow(a, s + 1)), 1.0, 2e-6) << "s = " << s;
  }
}

TEST(Level1Pressure, integrates_to_the_punch_load_in_the_single_level_phase) {
  // P1 = pbar0 l^2 while only level 1 touches; eq (9.4) must carry it, to 1e-6.
  const StandardLinearSolid sls(2.5);
  for (int s = 1; s <= 4; ++s) {
    const ContactProblem p{0.75, 0.2, 0.02, Shape{s, 0.5}};
    const Level1Pressure pressure(p, sls);
    for (const double t : {0.0, 0.4, 1.5, 6.0}) {
      EXPECT_NEAR(pressure.total_load(t) / (p.pbar0 * p.l * p.l), 1.0, 1e-6) << "s = " << s << ", t = " << t;
    }
  }
}

TEST(Level1Pressure, at_t_zero_is_the_elastic_pressure) {
  const StandardLinearSolid sls(3.0);
  const ContactProblem p{0.75, 0.2, 0.03, Shape{2, 0.5}};
  const Level1Pressure pressure(p, sls);
  const double a = pressure.contact_radius(0.0);
  for (const double r : {0.0, 0.5 * a, 0.95 * a}) {
    EXPECT_DOUBLE_EQ(pressure.at(r, 0.0), pressure.creep_scaled(r, a, p.pbar0));
  }
  EXPECT_EQ(pressure.at(1.01 * a, 0.0), 0.0);
}

TEST(Level1Pressure, elastic_material_does_not_evolve) {
  const StandardLinearSolid elastic(1.0);
  const ContactProblem p{0.75, 0.2, 0.03, Shape{3, 0.5}};
  const Level1Pressure pressure(p, elastic);
  const double a = pressure.contact_radius(0.0);
  EXPECT_NEAR(pressure.at(0.4 * a, 3.0), pressure.at(0.4 * a, 0.0), 1e-14);
}
