#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "model/problem/contact_problem.hpp"
#include "model/laws/creep_laws.hpp"
#include "model/point/parameters.hpp"

using namespace punchsweep::model;

namespace {

// The command line's manual, whose option table the declarations must match.
std::string readme() {
  std::ifstream in(std::string(PUNCHSWEEP_SOURCE_DIR) + "/docs/cli.md");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The docs/cli.md table row of option `--NAME` ("| `--NAME` | ..."), or "" if none.
std::string readme_row(const std::string& text, std::string_view name) {
  const std::string head = std::string("| `--").append(name).append("` |");
  const std::size_t at = text.find(head);
  if (at == std::string::npos) return {};
  return text.substr(at, text.find('\n', at) - at);
}

}  // namespace

TEST(Parameters, standard_linear_solid_sweeps_l_dh_T_pbar_s_in_that_order) {
  const std::vector<const Parameter*> axes = sweep_axes(creep_laws().front().parameters);
  std::string names;
  for (const Parameter* p : axes) names += std::string(p->name) + " ";
  EXPECT_EQ(names, "l dh T pbar s ");
  for (const Parameter* p : axes) EXPECT_TRUE(p->sweepable()) << p->name;
  EXPECT_FALSE(find_parameter(kShapeConstant)->sweepable());
}

TEST(Parameters, each_error_names_the_parameter_its_value_and_its_range) {
  for (const Parameter& p : problem_parameters()) {
    for (const double bad : {std::nan(""), -1.0, 1e300 * 1e300}) {
      const std::string e = p.error(bad);
      if (p.admits(bad)) continue;
      EXPECT_NE(e.find(std::string(p.name) + " = "), std::string::npos) << e;
      EXPECT_NE(e.find(std::string(p.range)), std::string::npos) << e;
      EXPECT_NE(e.find(std::string(p.long_name)), std::string::npos) << e;
    }
  }
  EXPECT_FALSE(find_parameter(kPitch)->admits(0.0));
  EXPECT_TRUE(find_parameter(kHeightDifference)->admits(0.0));
  EXPECT_FALSE(find_parameter(kExponent)->admits(2.5)) << "s takes whole numbers only";
  EXPECT_FALSE(find_parameter(kExponent)->admits(33.0));
  EXPECT_TRUE(find_parameter(kExponent)->admits(32.0));
  EXPECT_FALSE(find_parameter(kPressure)->admits(INFINITY));
}

TEST(Parameters, problem_error_reports_the_first_bad_field_from_the_registry) {
  EXPECT_EQ(problem_error({0.75, 0.05, 0.06, Shape{2, 0.5}}), "");
  EXPECT_EQ(problem_error({-1.0, 0.05, 0.06, Shape{2, 0.5}}), find_parameter(kPitch)->error(-1.0));
  EXPECT_EQ(problem_error({0.75, 0.05, 0.0, Shape{2, 0.5}}), find_parameter(kPressure)->error(0.0));
  EXPECT_EQ(problem_error({0.75, 0.05, 0.06, Shape{2, -0.5}}), find_parameter(kShapeConstant)->error(-0.5));
}

TEST(Parameters, readme_option_table_states_every_point_parameter_as_declared) {
  const std::string text = readme();
  ASSERT_FALSE(text.empty()) << "docs/cli.md not found";
  std::vector<const Parameter*> params = sweep_axes(creep_laws().front().parameters);
  params.push_back(find_parameter(kShapeConstant));
  for (const Parameter* p : params) {
    const std::string row = readme_row(text, p->name);
    ASSERT_FALSE(row.empty()) << "docs/cli.md has no row for --" << p->name;
    EXPECT_NE(row.find(std::string(p->meaning)), std::string::npos) << row;
    const std::string range = std::string("`").append(p->range).append("`");
    EXPECT_NE(row.find(range), std::string::npos) << row;
    if (!p->point_default.empty()) {
      EXPECT_NE(row.find("default " + std::string(p->point_default)), std::string::npos) << row;
    }
  }
}
