#include "sweep/reference_sample.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <vector>

using punchsweep::sweep::ReferenceSample;

namespace {

std::vector<std::uint64_t> members(const ReferenceSample& sample) {
  std::vector<std::uint64_t> out;
  for (std::uint64_t k = 0; k < sample.size(); ++k) out.push_back(sample.at(k));
  return out;
}

}  // namespace

TEST(ReferenceSample, all_holds_every_point_in_order) {
  const ReferenceSample all(50, std::nullopt, 7);
  EXPECT_EQ(all.size(), 50u);
  for (std::uint64_t g = 0; g < 50; ++g) {
    EXPECT_TRUE(all.contains(g));
    EXPECT_EQ(all.at(g), g);
  }
  EXPECT_FALSE(all.contains(50));
}

TEST(ReferenceSample, random_sample_holds_k_distinct_points_of_the_grid_in_increasing_order) {
  const ReferenceSample sample(1000, 37, 1);
  ASSERT_EQ(sample.size(), 37u);
  const std::vector<std::uint64_t> points = members(sample);
  for (std::size_t k = 0; k < points.size(); ++k) {
    EXPECT_LT(points[k], 1000u);
    if (k > 0) {
      EXPECT_LT(points[k - 1], points[k]);
    }
  }
  std::uint64_t contained = 0;
  for (std::uint64_t g = 0; g < 1000; ++g) contained += sample.contains(g) ? 1 : 0;
  EXPECT_EQ(contained, 37u);
}

TEST(ReferenceSample, sample_is_a_pure_function_of_points_count_and_seed) {
  EXPECT_EQ(members(ReferenceSample(104328, 500, 1)), members(ReferenceSample(104328, 500, 1)));
  EXPECT_NE(members(ReferenceSample(104328, 500, 1)), members(ReferenceSample(104328, 500, 2)));
  EXPECT_NE(members(ReferenceSample(104328, 500, 1)), members(ReferenceSample(104329, 500, 1)));
  // std::mt19937_64 is fixed by the standard and the bounded draw is our own, so the sample
  // is the same with every standard library: these values were checked against an
  // independent Python implementation of MT19937-64 and Floyd's algorithm.
  EXPECT_EQ(members(ReferenceSample(1000, 5, 1)), (std::vector<std::uint64_t>{236, 384, 497, 549, 948}));
  EXPECT_EQ(members(ReferenceSample(104328, 4, 12345)), (std::vector<std::uint64_t>{16031, 58371, 70823, 98826}));
  EXPECT_EQ(members(ReferenceSample(1, 1, 99)), std::vector<std::uint64_t>{0});
}

TEST(ReferenceSample, sample_of_every_point_is_the_whole_grid) {
  const ReferenceSample sample(64, 64, 5);
  std::vector<std::uint64_t> expected(64);
  for (std::uint64_t g = 0; g < 64; ++g) expected[g] = g;
  EXPECT_EQ(members(sample), expected);
}

TEST(ReferenceSample, every_point_is_drawn_about_equally_often) {
  // 2000 samples of 5 from 20: each point is expected 500 times (binomial sd ~19).
  std::vector<int> hits(20, 0);
  for (std::uint64_t seed = 0; seed < 2000; ++seed) {
    for (const std::uint64_t g : members(ReferenceSample(20, 5, seed))) ++hits[g];
  }
  for (std::size_t g = 0; g < hits.size(); ++g) {
    EXPECT_GT(hits[g], 400) << g;
    EXPECT_LT(hits[g], 600) << g;
  }
}

TEST(ReferenceSample, sample_larger_than_the_grid_or_empty_is_refused) {
  EXPECT_THROW(ReferenceSample(10, 11, 1), std::invalid_argument);
  EXPECT_THROW(ReferenceSample(10, 0, 1), std::invalid_argument);
}

TEST(ReferenceSample, an_explicit_list_is_the_sample_and_a_bad_one_is_refused) {
  // The points a rule of the model picked (reference.sample = invalid or boundary).
  const ReferenceSample picked(10, std::vector<std::uint64_t>{1, 4, 9});
  EXPECT_EQ(picked.size(), 3u);
  EXPECT_EQ(picked.at(1), 4u);
  for (std::uint64_t p = 0; p < 10; ++p) EXPECT_EQ(picked.contains(p), p == 1 || p == 4 || p == 9) << p;
  EXPECT_EQ(ReferenceSample(10, std::vector<std::uint64_t>{}).size(), 0u);  // a rule may pick none
  EXPECT_THROW(ReferenceSample(10, std::vector<std::uint64_t>{4, 1}), std::invalid_argument);
  EXPECT_THROW(ReferenceSample(10, std::vector<std::uint64_t>{1, 1}), std::invalid_argument);
  EXPECT_THROW(ReferenceSample(10, std::vector<std::uint64_t>{1, 10}), std::invalid_argument);
}
