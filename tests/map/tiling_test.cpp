#include <gtest/gtest.h>

#include <vector>

#include "map/tiling.hpp"

using namespace punchsweep::map;

namespace {
constexpr std::size_t kAxes = 5;  // a standard linear solid's grid: l, dh, T, pbar, s
}  // namespace

TEST(Tiling, chunk_fills_fast_axes_first_then_part_of_the_next) {
  const Tiling t({7, 23, 9, 24, 3}, 4096);
  // s (3) x pbar (24) x T (9) = 648 points; 4096 / 648 = 6 values of dh; l gets 1.
  EXPECT_EQ(t.chunk(), (Index{1, 6, 9, 24, 3}));
  EXPECT_EQ(t.tiles(), 7u * 4u);  // 23 dh values in tiles of 6: 6, 6, 6, 5
}

TEST(Tiling, tiny_target_gives_one_point_tiles_and_huge_gives_one_tile) {
  const Index shape{2, 3, 4, 5, 6};
  EXPECT_EQ(Tiling(shape, 1).chunk(), (Index{1, 1, 1, 1, 1}));
  EXPECT_EQ(Tiling(shape, 1).tiles(), 720u);
  EXPECT_EQ(Tiling(shape, 1000000).chunk(), shape);
  EXPECT_EQ(Tiling(shape, 1000000).tiles(), 1u);
}

TEST(Tiling, tiles_cover_every_point_exactly_once) {
  for (const std::size_t target : {1u, 5u, 7u, 64u, 100u, 5000u}) {
    const Index shape{3, 7, 2, 5, 3};
    const Tiling t(shape, target);
    std::vector<int> hits(3 * 7 * 2 * 5 * 3, 0);
    std::size_t points = 0;
    for (std::size_t k = 0; k < t.tiles(); ++k) {
      const TileBox b = t.box(k);
      points += b.points();
      for (std::size_t a = 0; a < kAxes; ++a) {
        ASSERT_EQ(b.start[a] % t.chunk()[a], 0u) << "tiles are chunk-aligned";
        ASSERT_LE(b.start[a] + b.count[a], shape[a]);
      }
      for (std::size_t i0 = 0; i0 < b.count[0]; ++i0)
        for (std::size_t i1 = 0; i1 < b.count[1]; ++i1)
          for (std::size_t i2 = 0; i2 < b.count[2]; ++i2)
            for (std::size_t i3 = 0; i3 < b.count[3]; ++i3)
              for (std::size_t i4 = 0; i4 < b.count[4]; ++i4) {
                const std::size_t i = (((((b.start[0] + i0) * 7 + b.start[1] + i1) * 2 + b.start[2] + i2) * 5 +
                                        b.start[3] + i3) * 3) + b.start[4] + i4;
                ++hits[i];
              }
    }
    EXPECT_EQ(points, hits.size()) << "target " << target;
    for (const int h : hits) ASSERT_EQ(h, 1) << "target " << target;
  }
}
