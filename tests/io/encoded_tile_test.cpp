#include "io/encoded_tile.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sample_tiles.hpp"

namespace punchsweep::io {
namespace {

using namespace testing;
using testing::sample_encoded_tile;

constexpr std::size_t kHeaderSize = 144;  // format version 5: seven validity counts

using testing::error_of;

void set_u64(std::vector<std::byte>* bytes, std::size_t at, std::uint64_t value) {
  std::memcpy(bytes->data() + at, &value, sizeof value);
}

TEST(EncodedTile, encoded_tile_round_trips_byte_exactly) {
  EncodedTile in = sample_encoded_tile(123456789012ULL, 13, 500);
  in.chunks[4].clear();  // an empty chunk keeps its place
  const std::vector<std::byte> bytes = pack_encoded_tile(in);
  std::size_t expected = kHeaderSize + 13 * sizeof(std::uint64_t);
  for (const auto& chunk : in.chunks) expected += chunk.size();
  EXPECT_EQ(bytes.size(), expected);
  const EncodedTile out = unpack_encoded_tile(bytes.data(), bytes.size());
  EXPECT_TRUE(out == in);
  EXPECT_EQ(out.tile, 123456789012ULL);
  EXPECT_EQ(pack_encoded_tile(out), bytes);
}

TEST(EncodedTile, encoded_tile_without_chunks_round_trips) {
  EncodedTile in;
  in.tile = 3;
  in.summary.points = 0;
  const std::vector<std::byte> bytes = pack_encoded_tile(in);
  EXPECT_EQ(bytes.size(), kHeaderSize);
  EXPECT_TRUE(unpack_encoded_tile(bytes.data(), bytes.size()) == in);
}

TEST(EncodedTile, encoded_tile_rejects_every_short_buffer) {
  const std::vector<std::byte> bytes = pack_encoded_tile(sample_encoded_tile(5, 3, 20));
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    EXPECT_THROW(unpack_encoded_tile(bytes.data(), n), std::runtime_error) << "length " << n;
  }
  EXPECT_NE(error_of([&] { unpack_encoded_tile(bytes.data(), 10); }).find("shorter than"), std::string::npos);
  EXPECT_NE(error_of([&] { unpack_encoded_tile(bytes.data(), bytes.size() - 1); }).find("run past the end"),
            std::string::npos);
}

TEST(EncodedTile, encoded_tile_rejects_a_buffer_with_trailing_bytes) {
  std::vector<std::byte> bytes = pack_encoded_tile(sample_encoded_tile(5, 3, 20));
  bytes.push_back(std::byte{0});
  EXPECT_NE(error_of([&] { unpack_encoded_tile(bytes.data(), bytes.size()); }).find("need"),
            std::string::npos);
}

TEST(EncodedTile, encoded_tile_rejects_a_wrong_magic_or_version) {
  const std::vector<std::byte> good = pack_encoded_tile(sample_encoded_tile(5, 3, 20));
  std::vector<std::byte> bytes = good;
  bytes[0] ^= std::byte{0x01};
  EXPECT_NE(error_of([&] { unpack_encoded_tile(bytes.data(), bytes.size()); }).find("magic"),
            std::string::npos);
  bytes = good;
  bytes[4] ^= std::byte{0x02};
  EXPECT_NE(error_of([&] { unpack_encoded_tile(bytes.data(), bytes.size()); }).find("version"),
            std::string::npos);
}

TEST(EncodedTile, encoded_tile_rejects_lengths_that_do_not_fit_the_buffer) {
  const std::vector<std::byte> good = pack_encoded_tile(sample_encoded_tile(5, 3, 20));
  constexpr std::size_t kChunkCountAt = kHeaderSize - sizeof(std::uint64_t);
  std::vector<std::byte> bytes = good;
  set_u64(&bytes, kChunkCountAt, ~std::uint64_t{0});  // would overflow a size computation
  EXPECT_NE(error_of([&] { unpack_encoded_tile(bytes.data(), bytes.size()); }).find("impossible chunk count"),
            std::string::npos);
  bytes = good;
  set_u64(&bytes, kHeaderSize, ~std::uint64_t{0});  // first chunk length
  EXPECT_NE(error_of([&] { unpack_encoded_tile(bytes.data(), bytes.size()); }).find("run past the end"),
            std::string::npos);
  bytes = good;
  set_u64(&bytes, kHeaderSize + 8, ~std::uint64_t{0} - 5);  // lengths whose sum wraps around
  EXPECT_THROW(unpack_encoded_tile(bytes.data(), bytes.size()), std::runtime_error);
  bytes = good;
  set_u64(&bytes, kChunkCountAt, 2);  // the third length would be read as chunk bytes
  EXPECT_THROW(unpack_encoded_tile(bytes.data(), bytes.size()), std::runtime_error);
}

TEST(EncodedTile, encoded_tile_rejects_summary_counts_beyond_its_points) {
  const EncodedTile tile = sample_encoded_tile(5, 3, 20);
  constexpr std::size_t kPointsAt = 16;
  constexpr std::size_t kRegimesAt = 24;
  constexpr std::size_t kValidityAt = 48;
  std::vector<std::byte> bytes = pack_encoded_tile(tile);
  set_u64(&bytes, kPointsAt, 10);
  EXPECT_NE(error_of([&] { unpack_encoded_tile(bytes.data(), bytes.size()); }).find("exceed"),
            std::string::npos);
  bytes = pack_encoded_tile(tile);
  set_u64(&bytes, kRegimesAt, ~std::uint64_t{0});
  EXPECT_THROW(unpack_encoded_tile(bytes.data(), bytes.size()), std::runtime_error);
  bytes = pack_encoded_tile(tile);
  // Each count alone fits, their sum does not (nor would it in 64 bits).
  for (std::size_t c = 0; c < tile.summary.validity.size(); ++c) set_u64(&bytes, kValidityAt + 8 * c, tile.summary.points);
  EXPECT_THROW(unpack_encoded_tile(bytes.data(), bytes.size()), std::runtime_error);
}

TEST(EncodedTile, encoded_tile_keeps_its_bem_counts_and_rejects_impossible_ones) {
  EncodedTile tile = sample_encoded_tile(5, 3, 20);
  tile.summary.bem_regimes = {4, 5, 6};
  tile.summary.bem_agreeing = 15;  // all of them
  const std::vector<std::byte> good = pack_encoded_tile(tile);
  EXPECT_EQ(unpack_encoded_tile(good.data(), good.size()).summary, tile.summary);
  constexpr std::size_t kBemRegimesAt = 104;  // after seven validity counts from 48
  constexpr std::size_t kBemAgreeingAt = 128;
  std::vector<std::byte> bytes = good;
  set_u64(&bytes, kBemRegimesAt, tile.summary.points);  // with the others, more than the points
  EXPECT_NE(error_of([&] { unpack_encoded_tile(bytes.data(), bytes.size()); }).find("BEM counts exceed"),
            std::string::npos);
  bytes = good;
  set_u64(&bytes, kBemAgreeingAt, 16);  // more agreeing points than BEM points
  EXPECT_NE(error_of([&] { unpack_encoded_tile(bytes.data(), bytes.size()); }).find("agree with the model"),
            std::string::npos);
}

}  // namespace
}  // namespace punchsweep::io
