#include "io/tile_codec.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "sample_tiles.hpp"

namespace punchsweep::io {
namespace {

using testing::same_bits;
using testing::sample_tile;

/// The message of the runtime_error `f` throws ("" if it throws none).
template <typename F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(TileCodec, tile_codec_round_trips_bit_exactly) {
  const TileData in = sample_tile(42, 37, 5, true);
  std::ptrdiff_t nans = 0;
  for (const auto* v : {&in.t_star, &in.h_0, &in.a1, &in.area_fraction}) {
    nans += std::count_if(v->begin(), v->end(), [](double x) { return std::isnan(x); });
  }
  ASSERT_GT(nans, 2) << "the sample must carry NaN payloads for this test to mean anything";
  const std::vector<std::byte> bytes = pack_tile(123456789012ULL, in);
  EXPECT_EQ(bytes.size(), packed_tile_size(37, 37 * 5));
  TileData out;
  EXPECT_EQ(unpack_tile(bytes.data(), bytes.size(), &out), 123456789012ULL);
  EXPECT_TRUE(same_bits(in, out));
  EXPECT_EQ(pack_tile(123456789012ULL, out), bytes);
}

TEST(TileCodec, tile_codec_round_trips_a_regime_only_tile) {
  const TileData in = sample_tile(3, 64, 5, false);
  const std::vector<std::byte> bytes = pack_tile(7, in);
  EXPECT_EQ(bytes.size(), packed_tile_size(64, 0));
  TileData out = sample_tile(9, 2, 3, true);  // stale contents must be replaced, not kept
  EXPECT_EQ(unpack_tile(bytes.data(), bytes.size(), &out), 7U);
  EXPECT_TRUE(same_bits(in, out));
  EXPECT_TRUE(out.a1.empty());
}

TEST(TileCodec, tile_codec_rejects_every_short_buffer) {
  const std::vector<std::byte> bytes = pack_tile(5, sample_tile(1, 6, 2, true));
  TileData out;
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    EXPECT_THROW(unpack_tile(bytes.data(), n, &out), std::runtime_error) << "length " << n;
  }
  EXPECT_NE(error_of([&] { unpack_tile(bytes.data(), 10, &out); }).find("shorter than"), std::string::npos);
  EXPECT_NE(error_of([&] { unpack_tile(bytes.data(), bytes.size() - 1, &out); }).find("needs"),
            std::string::npos);
}

TEST(TileCodec, tile_codec_rejects_a_buffer_with_trailing_bytes) {
  std::vector<std::byte> bytes = pack_tile(5, sample_tile(1, 6, 2, true));
  bytes.push_back(std::byte{0});
  TileData out;
  EXPECT_THROW(unpack_tile(bytes.data(), bytes.size(), &out), std::runtime_error);
}

TEST(TileCodec, tile_codec_rejects_a_wrong_magic_or_version) {
  const std::vector<std::byte> good = pack_tile(5, sample_tile(1, 6, 2, false));
  TileData out;
  std::vector<std::byte> bytes = good;
  bytes[0] ^= std::byte{0x01};
  EXPECT_NE(error_of([&] { unpack_tile(bytes.data(), bytes.size(), &out); }).find("magic"),
            std::string::npos);
  bytes = good;
  bytes[4] ^= std::byte{0x02};
  EXPECT_NE(error_of([&] { unpack_tile(bytes.data(), bytes.size(), &out); }).find("version"),
            std::string::npos);
}

TEST(TileCodec, tile_codec_rejects_counts_that_do_not_fit_the_buffer) {
  const std::vector<std::byte> good = pack_tile(5, sample_tile(1, 6, 2, true));
  TileData out;
  const auto set_u64 = [](std::vector<std::byte>* b, std::size_t at, std::uint64_t v) {
    std::memcpy(b->data() + at, &v, sizeof v);
  };
  std::vector<std::byte> bytes = good;
  set_u64(&bytes, 16, 7);  // point count
  EXPECT_THROW(unpack_tile(bytes.data(), bytes.size(), &out), std::runtime_error);
  bytes = good;
  set_u64(&bytes, 16, ~std::uint64_t{0});  // would overflow a size computation
  EXPECT_NE(error_of([&] { unpack_tile(bytes.data(), bytes.size(), &out); }).find("impossible"),
            std::string::npos);
  bytes = good;
  set_u64(&bytes, 24, 13);  // series count not a multiple of the points
  EXPECT_NE(error_of([&] { unpack_tile(bytes.data(), bytes.size(), &out); }).find("multiple"),
            std::string::npos);
}

TEST(TileCodec, pack_tile_rejects_arrays_of_unequal_length) {
  TileData data = sample_tile(1, 6, 2, true);
  data.h_inf.pop_back();
  EXPECT_THROW(pack_tile(0, data), std::invalid_argument);
  data = sample_tile(1, 6, 2, true);
  data.P2.pop_back();
  EXPECT_THROW(pack_tile(0, data), std::invalid_argument);
  data = sample_tile(1, 6, 2, true);
  data.valid.push_back(0);
  EXPECT_THROW(pack_tile(0, data), std::invalid_argument);
}

}  // namespace
}  // namespace punchsweep::io
