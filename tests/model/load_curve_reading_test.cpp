// Reading a texture's load curve below its first sample (issue 48): a level whose touchdown
// lies between the load and the first sample has no contact yet, however coarse the grid.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "model/surface/load_curve.hpp"

using namespace punchsweep::model;

namespace {

// Two levels; the first sample at X = 1 already has level 1 in contact (touchdown 0.4);
// the next at X = 2. Numbers chosen by hand, loads summing to X Lx Ly (cell area 1).
LoadCurve two_level_curve() {
  LoadCurve c;
  c.cell_area = 1.0;
  c.site_level = {0, 1};
  c.site_touchdown = {0.0, 0.4};
  c.level_touchdown = {0.0, 0.4};
  c.level_share = {0.8, 0.2};
  c.s_tallest = 2;
  c.samples = {{1.0, {0.9, 0.1}, {0.3, 0.01}}, {2.0, {1.7, 0.3}, {0.5, 0.04}}};
  c.pressure_monotone = {1};
  c.X_resolved = 1.0;
  return c;
}

}  // namespace

TEST(LoadCurveReading, below_the_first_sample_a_level_before_its_touchdown_has_no_area_or_load) {
  const LoadCurve c = two_level_curve();
  const CurveState before = c.at(0.2);  // below level 1's touchdown
  EXPECT_EQ(before.range, CurveRange::below_resolution);
  EXPECT_EQ(before.level_area[1], 0.0);
  EXPECT_EQ(before.level_load[1], 0.0);
  // The tallest level's area follows the isolated punch, a^2 ~ X^(2/(s+1)), from the sample.
  EXPECT_DOUBLE_EQ(before.level_area[0], 0.3 * std::pow(0.2, 2.0 / 3.0));
  // The loads still sum to X Lx Ly: level 1's share is the tallest level's.
  EXPECT_DOUBLE_EQ(before.level_load[0] + before.level_load[1], 0.2);
  const CurveState after = c.at(0.5);  // past it, still below the first sample
  EXPECT_DOUBLE_EQ(after.level_area[1], 0.01 * std::pow(0.5, 2.0 / 3.0));
  EXPECT_DOUBLE_EQ(after.level_load[1], 0.1 * 0.5);
  EXPECT_DOUBLE_EQ(after.area_fraction, (0.3 + 0.01) * std::pow(0.5, 2.0 / 3.0));
}
