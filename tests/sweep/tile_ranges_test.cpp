#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "sweep/tile_ranges.hpp"

using punchsweep::sweep::TileRanges;

TEST(TileRanges, a_huge_fresh_sweep_is_one_range_and_batches_come_off_its_front) {
  TileRanges all(std::uint64_t{244140625});  // a 1e12-point grid in tiles of 4096
  EXPECT_EQ(all.size(), 244140625U);
  EXPECT_EQ(all.flat(), (std::vector<std::uint64_t>{0, 244140625}));  // no per-tile memory
  const TileRanges batch = all.take(256);
  EXPECT_EQ(batch.flat(), (std::vector<std::uint64_t>{0, 256}));
  EXPECT_EQ(all.front(), 256U);
  EXPECT_EQ(all.pop_front(), 256U);
  EXPECT_EQ(all.size(), 244140625U - 257);
}

TEST(TileRanges, gaps_of_a_resumed_sweep_keep_their_order_across_takes) {
  TileRanges gaps;
  gaps.add(0, 3);
  gaps.add(3, 4);  // touching ranges merge
  gaps.add(7);
  gaps.add(9, 12);
  EXPECT_EQ(gaps.flat(), (std::vector<std::uint64_t>{0, 4, 7, 8, 9, 12}));
  EXPECT_EQ(gaps.size(), 8U);
  const TileRanges first = gaps.take(5);  // across a gap
  EXPECT_EQ(first.tiles(), (std::vector<std::uint64_t>{0, 1, 2, 3, 7}));
  TileRanges received;
  received.add_flat(gaps.take(10).flat());  // as a worker receives a batch
  EXPECT_EQ(received.tiles(), (std::vector<std::uint64_t>{9, 10, 11}));
  EXPECT_TRUE(gaps.empty());
}
