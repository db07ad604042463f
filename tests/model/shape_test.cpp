#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "model/problem/contact_problem.hpp"
#include "model/problem/parameter.hpp"
#include "model/problem/shape.hpp"

using namespace punchsweep::model;

TEST(Shape, sphere_coefficients_are_hertz) {
  // Hertz with f = r^2/(2R): P = 4 E* a^3 / (3R), d = a^2 / R.
  const Shape sphere{2, 0.5};
  EXPECT_NEAR(load_coefficient(sphere), 4.0 / 3.0, 1e-15);
  EXPECT_NEAR(depth_coefficient(sphere), 1.0, 1e-15);
}

TEST(Shape, cone_coefficients_are_sneddon) {
  // Sneddon's cone f = C r: d = (pi/2) C a, P = (pi/2) C E* a^2.
  const Shape cone{1, 0.7};
  EXPECT_NEAR(load_coefficient(cone), std::numbers::pi / 2 * 0.7, 1e-15);
  EXPECT_NEAR(depth_coefficient(cone), std::numbers::pi / 2 * 0.7, 1e-15);
}

TEST(Shape, every_exponent_matches_sneddons_power_law_solution) {
  // Sneddon (1965) for f = C r^n: d = sqrt(pi) Gamma(n/2 + 1) / Gamma(n/2 + 1/2) C a^n and
  // P = 2 n/(n+1) E* d a; a different closed form from the notes' K_P, K_d.
  for (int s = Shape::kMinExponent; s <= Shape::kMaxExponent; ++s) {
    const Shape shape{s, 1.3};
    const double depth = std::sqrt(std::numbers::pi) * std::tgamma(0.5 * s + 1.0) /
                         std::tgamma(0.5 * s + 0.5) * 1.3;
    const double load = 2.0 * s / (s + 1.0) * depth;
    EXPECT_NEAR(depth_coefficient(shape) / depth, 1.0, 1e-12) << "s = " << s;
    EXPECT_NEAR(load_coefficient(shape) / load, 1.0, 1e-12) << "s = " << s;
  }
}

TEST(Shape, out_of_range_shapes_are_named) {
  EXPECT_EQ(shape_error({2, 0.5}), "");
  EXPECT_NE(shape_error({0, 0.5}).find("s = 0"), std::string::npos);
  EXPECT_NE(shape_error({33, 0.5}).find("[1, 32]"), std::string::npos);
  EXPECT_NE(shape_error({2, 0.0}).find("C > 0"), std::string::npos);
  EXPECT_NE(shape_error({2, std::nan("")}).find("C"), std::string::npos);
}

TEST(ContactProblem, each_bad_field_is_named_with_its_range) {
  EXPECT_EQ(problem_error({0.75, 0.05, 0.06, Shape{2, 0.5}}), "");
  EXPECT_NE(problem_error({-1.0, 0.05, 0.06, Shape{2, 0.5}}).find("l > 0"), std::string::npos);
  EXPECT_NE(problem_error({0.75, -0.1, 0.06, Shape{2, 0.5}}).find("dh >= 0"), std::string::npos);
  EXPECT_NE(problem_error({0.75, 0.05, 0.0, Shape{2, 0.5}}).find("pbar > 0"), std::string::npos);
  EXPECT_NE(problem_error({0.75, 0.05, 0.06, Shape{0, 0.5}}).find("[1, 32]"), std::string::npos);
  EXPECT_NE(problem_error({std::nan(""), 0.05, 0.06, Shape{2, 0.5}}).find("pitch"), std::string::npos);
}
