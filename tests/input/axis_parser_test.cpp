#include "input/axis_parser.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using punchsweep::map::Axis;
using punchsweep::input::format_axis_value;
using punchsweep::input::format_axis_values;
using punchsweep::input::parse_axis;

// The message parse_axis throws for `text`; fails the test when it does not throw.
std::string axis_error(const std::string& text, bool integers = false) {
  try {
    const Axis axis = parse_axis(text, integers);
    ADD_FAILURE() << "'" << text << "' was accepted as " << format_axis_values(axis.values);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

TEST(AxisParser, list_with_commas_and_spaces_gives_the_values_in_order) {
  const Axis axis = parse_axis("  0.5, 0.75 1,\t2  ", false);
  EXPECT_EQ(axis.values, (std::vector<double>{0.5, 0.75, 1.0, 2.0}));
  EXPECT_EQ(axis.text, "0.5, 0.75 1,\t2");
  EXPECT_FALSE(axis.log_spaced);
}

TEST(AxisParser, single_value_gives_one_point) {
  const Axis axis = parse_axis(" 0.75 ", false);
  EXPECT_EQ(axis.values, std::vector<double>{0.75});
  EXPECT_EQ(axis.text, "0.75");
}

TEST(AxisParser, linspace_has_exact_endpoints_count_and_even_steps) {
  const Axis axis = parse_axis("  linspace( 0.5 ,1.25,  16 ) ", false);
  ASSERT_EQ(axis.values.size(), 16u);
  EXPECT_EQ(axis.values.front(), 0.5);
  EXPECT_EQ(axis.values.back(), 1.25);
  for (std::size_t i = 1; i < axis.values.size(); ++i) {
    EXPECT_NEAR(axis.values[i] - axis.values[i - 1], 0.05, 1e-15) << i;
  }
  EXPECT_EQ(axis.text, "linspace( 0.5 ,1.25,  16 )");
  EXPECT_FALSE(axis.log_spaced);
}

TEST(AxisParser, linspace_values_equal_the_decimals_a_list_would_give) {
  const Axis generated = parse_axis("linspace(0.5, 1.25, 16)", false);
  const Axis listed = parse_axis(
      "0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9, 0.95, 1, 1.05, 1.1, 1.15, 1.2, 1.25", false);
  EXPECT_EQ(generated.values, listed.values);
  const Axis dh = parse_axis("linspace(0.01, 0.12, 23)", false);
  ASSERT_EQ(dh.values.size(), 23u);
  EXPECT_EQ(dh.values[3], 0.025);
  EXPECT_EQ(dh.values[13], 0.075);
}

TEST(AxisParser, logspace_is_geometric_with_exact_endpoints) {
  const Axis axis = parse_axis("logspace(0.005, 0.08, 32)", false);
  ASSERT_EQ(axis.values.size(), 32u);
  EXPECT_EQ(axis.values.front(), 0.005);
  EXPECT_EQ(axis.values.back(), 0.08);
  EXPECT_TRUE(axis.log_spaced);
  const double ratio = std::pow(0.08 / 0.005, 1.0 / 31.0);
  for (std::size_t i = 1; i < axis.values.size(); ++i) {
    EXPECT_NEAR(axis.values[i] / axis.values[i - 1], ratio, 1e-14 * ratio) << i;
  }
}

TEST(AxisParser, logspace_takes_values_not_exponents) {
  const Axis axis = parse_axis("logspace(1, 1000, 4)", false);
  EXPECT_EQ(axis.values, (std::vector<double>{1.0, 10.0, 100.0, 1000.0}));
}

TEST(AxisParser, count_one_needs_equal_endpoints_and_gives_that_value) {
  EXPECT_EQ(parse_axis("linspace(2, 2, 1)", false).values, std::vector<double>{2.0});
  EXPECT_EQ(parse_axis("logspace(0.03, 0.03, 1)", false).values, std::vector<double>{0.03});
  EXPECT_NE(axis_error("linspace(2, 3, 1)").find("count 1 needs start == stop"), std::string::npos);
}

TEST(AxisParser, integer_axis_accepts_whole_numbers_only) {
  EXPECT_EQ(parse_axis("linspace(1, 3, 3)", true).values, (std::vector<double>{1.0, 2.0, 3.0}));
  EXPECT_EQ(parse_axis("1, 2, 32", true).values, (std::vector<double>{1.0, 2.0, 32.0}));
  EXPECT_EQ(axis_error("1.5", true), "1.5 is not an integer");
  EXPECT_EQ(axis_error("linspace(1, 4, 3)", true), "2.5 is not an integer");
}

TEST(AxisParser, wrong_argument_count_is_reported_with_the_count) {
  EXPECT_EQ(axis_error("linspace(1, 2)"), "linspace needs 3 arguments (start, stop, count), got 2");
  EXPECT_EQ(axis_error("logspace(1, 2, 3, 4)"), "logspace needs 3 arguments (start, stop, count), got 4");
  EXPECT_EQ(axis_error("linspace( )"), "linspace needs 3 arguments (start, stop, count), got 0");
  EXPECT_EQ(axis_error("linspace(1, , 3)"), "linspace argument 2 is empty");
}

TEST(AxisParser, count_must_be_a_positive_integer) {
  for (const char* text : {"linspace(0, 1, 0)", "linspace(0, 1, -3)", "linspace(0, 1, 2.5)",
                           "logspace(1, 2, abc)", "linspace(0, 1, 1000001)"}) {
    EXPECT_NE(axis_error(text).find("count must be an integer in [1, 1000000]"), std::string::npos) << text;
  }
}

TEST(AxisParser, decreasing_or_repeated_values_are_rejected) {
  EXPECT_EQ(axis_error("linspace(1.25, 0.5, 4)"),
            "linspace values must increase: start 1.25 is not below stop 0.5");
  EXPECT_NE(axis_error("logspace(0.08, 0.005, 4)").find("must increase"), std::string::npos);
  EXPECT_EQ(axis_error("0.5, 1, 0.75"), "values must be strictly increasing (0.75 follows 1)");
  EXPECT_EQ(axis_error("1 1"), "values must be strictly increasing (1 follows 1)");
}

TEST(AxisParser, non_numbers_and_non_finite_values_are_rejected) {
  EXPECT_EQ(axis_error("abc"), "'abc' is not a number");
  EXPECT_EQ(axis_error("1, 2x"), "'2x' is not a number");
  EXPECT_EQ(axis_error("inf"), "'inf' is not a finite number");
  EXPECT_EQ(axis_error("nan"), "'nan' is not a finite number");
  EXPECT_EQ(axis_error("1e999"), "'1e999' is out of the range of a double");
  EXPECT_EQ(axis_error("   "), "no value given");
  EXPECT_NE(axis_error("1,,2").find("empty entry"), std::string::npos);
  EXPECT_NE(axis_error("1, 2,").find("empty entry"), std::string::npos);
}

TEST(AxisParser, function_names_are_case_sensitive_and_need_closing_parenthesis) {
  EXPECT_NE(axis_error("Linspace(0, 1, 3)").find("unknown function 'Linspace'"), std::string::npos);
  EXPECT_NE(axis_error("arange(0, 1, 3)").find("unknown function 'arange'"), std::string::npos);
  EXPECT_NE(axis_error("linspace(0, 1, 3").find("missing its closing ')'"), std::string::npos);
}

TEST(AxisParser, logspace_needs_positive_endpoints) {
  EXPECT_NE(axis_error("logspace(0, 1, 3)").find("start and stop > 0"), std::string::npos);
  EXPECT_NE(axis_error("logspace(-2, 1, 3)").find("start and stop > 0"), std::string::npos);
}

TEST(AxisParser, format_axis_value_is_the_shortest_text_that_reads_back) {
  EXPECT_EQ(format_axis_value(0.1), "0.1");
  EXPECT_EQ(format_axis_value(2.0), "2");
  EXPECT_EQ(format_axis_value(0.1 + 0.2), "0.30000000000000004");
  for (const double v : {1.0 / 3.0, 2.0 / 3.0, 1e-300, 6.02214076e23, -0.055}) {
    EXPECT_EQ(std::stod(format_axis_value(v)), v) << format_axis_value(v);
  }
  EXPECT_EQ(format_axis_values({0.0, 0.5, 10.0}), "0, 0.5, 10");
}

}  // namespace
