// The ensemble's statistics against values worked by hand and numpy's conventions
// (numpy.percentile's default "linear": position (n - 1) p; numpy.std with ddof = 1).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "model/numerics/sample_statistics.hpp"

using punchsweep::model::percentile;
using punchsweep::model::sample_statistics;

TEST(SampleStatistics, eight_values_give_numpys_mean_spread_and_band) {
  // 1..8 shuffled: mean 4.5; sum of squares about it 42, so sd sqrt(42 / 7) = sqrt(6);
  // p5 at position 0.35: 1.35; median at 3.5: 4.5; p95 at 6.65: 7.65.
  const auto s = sample_statistics({5, 3, 8, 1, 7, 2, 6, 4});
  EXPECT_EQ(s.n, 8u);
  EXPECT_DOUBLE_EQ(s.mean, 4.5);
  EXPECT_DOUBLE_EQ(s.sd, std::sqrt(6.0));
  EXPECT_DOUBLE_EQ(s.se, std::sqrt(6.0) / std::sqrt(8.0));
  EXPECT_DOUBLE_EQ(s.p5, 1.35);
  EXPECT_DOUBLE_EQ(s.median, 4.5);
  EXPECT_DOUBLE_EQ(s.p95, 7.65);
  EXPECT_EQ(s.infinite, 0u);
}

TEST(SampleStatistics, a_level_that_never_touches_in_some_draws_is_infinite_where_it_reaches) {
  const double inf = std::numeric_limits<double>::infinity();
  // 1, 2, 3, inf: the mean infinite, the spread undefined; the median (position 1.5) is
  // 2.5, p5 (0.15) 1.15, p95 (2.85) between 3 and infinity: infinite.
  const auto s = sample_statistics({3, inf, 1, 2});
  EXPECT_TRUE(std::isinf(s.mean));
  EXPECT_TRUE(std::isnan(s.sd) && std::isnan(s.se));
  EXPECT_DOUBLE_EQ(s.median, 2.5);
  EXPECT_DOUBLE_EQ(s.p5, 1.15);
  EXPECT_TRUE(std::isinf(s.p95));
  EXPECT_EQ(s.infinite, 1u);
  EXPECT_DOUBLE_EQ(percentile({1.0, 2.0, inf}, 0.5), 2.0);  // exactly on an order statistic
}

TEST(SampleStatistics, one_value_has_no_spread_and_nan_is_refused) {
  const auto s = sample_statistics({2.5});
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.p5, 2.5);
  EXPECT_DOUBLE_EQ(s.p95, 2.5);
  EXPECT_TRUE(std::isnan(s.sd));
  EXPECT_THROW(sample_statistics({}), std::invalid_argument);
  EXPECT_THROW(sample_statistics({1.0, std::nan("")}), std::invalid_argument);
}
