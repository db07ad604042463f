#include "io/chunk_compressor.hpp"

#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

namespace punchsweep::io {
namespace {

/// Inflates a zlib stream of known decoded size.
std::vector<std::byte> inflate_all(std::span<const std::byte> encoded, std::size_t size) {
  std::vector<std::byte> out(size);
  uLongf out_size = static_cast<uLongf>(size);
  const int status =
      uncompress(reinterpret_cast<Bytef*>(out.data()), &out_size,
                 reinterpret_cast<const Bytef*>(encoded.data()), static_cast<uLong>(encoded.size()));
  EXPECT_EQ(status, Z_OK);
  EXPECT_EQ(out_size, size);
  return out;
}

/// HDF5's shuffle filter, written out from its definition: byte b of element i goes to
/// b * elements + i; bytes after the last whole element stay in place.
std::vector<std::byte> shuffle(const std::vector<std::byte>& in, std::size_t element_size) {
  const std::size_t elements = in.size() / element_size;
  if (element_size <= 1 || elements <= 1) return in;
  std::vector<std::byte> out(in);
  for (std::size_t i = 0; i < elements; ++i) {
    for (std::size_t b = 0; b < element_size; ++b) out[b * elements + i] = in[i * element_size + b];
  }
  return out;
}

std::vector<std::byte> sample_bytes(std::size_t size, unsigned seed) {
  std::vector<std::byte> bytes(size);
  std::uint32_t x = seed;
  for (auto& b : bytes) {
    x = x * 1664525U + 1013904223U;
    b = static_cast<std::byte>(x >> 24);
  }
  return bytes;
}

TEST(ChunkCompressor, chunk_compressor_output_is_the_shuffled_input_deflated) {
  ChunkCompressor compressor(1);
  for (const std::size_t element_size : {1UL, 8UL}) {
    for (const std::size_t size : {0UL, 1UL, 8UL, 800UL, 803UL, 26000UL}) {
      const std::vector<std::byte> input = sample_bytes(size, static_cast<unsigned>(size + element_size));
      const std::span<const std::byte> encoded =
          compressor.compress(input.data(), input.size(), element_size);
      EXPECT_EQ(inflate_all(encoded, size), shuffle(input, element_size))
          << "element size " << element_size << ", " << size << " bytes";
    }
  }
}

TEST(ChunkCompressor, chunk_compressor_shrinks_smooth_float_data) {
  std::vector<double> values(4096);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = 0.25 + 1e-3 * static_cast<double>(i % 64);
  ChunkCompressor compressor(1);
  const std::size_t size = values.size() * sizeof(double);
  const std::span<const std::byte> encoded = compressor.compress(values.data(), size, sizeof(double));
  EXPECT_LT(encoded.size(), size / 4);
  std::vector<std::byte> raw(size);
  std::memcpy(raw.data(), values.data(), size);
  EXPECT_EQ(inflate_all(encoded, size), shuffle(raw, sizeof(double)));
}

// Doubles whose low mantissa bytes are noise (as a1_inf's): those planes go into stored
// blocks, more than 65535 bytes of them here, so several blocks; the stream must still
// inflate to the shuffled input and cost no more than the raw bytes plus framing.
TEST(ChunkCompressor, noise_planes_are_stored_and_the_stream_still_inflates) {
  const std::size_t n = 20000;
  std::vector<double> values(n);
  std::uint64_t x = 12345;
  for (auto& v : values) {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    v = 0.25 + 0.25 * static_cast<double>(x >> 11) * 0x1p-53;  // in [0.25, 0.5): one exponent
  }
  ChunkCompressor compressor(1);
  const std::size_t size = n * sizeof(double);
  const std::span<const std::byte> encoded = compressor.compress(values.data(), size, sizeof(double));
  std::vector<std::byte> raw(size);
  std::memcpy(raw.data(), values.data(), size);
  EXPECT_EQ(inflate_all(encoded, size), shuffle(raw, sizeof(double)));
  // The first block after the 2-byte zlib header is stored (header byte 0) and full (LEN 65535).
  ASSERT_GT(encoded.size(), 7U);
  EXPECT_EQ(encoded[2], std::byte{0});
  EXPECT_EQ(encoded[3], std::byte{0xFF});
  EXPECT_EQ(encoded[4], std::byte{0xFF});
  // 6.5 noise planes of 8, stored; the exponent planes compress: well under the raw size.
  EXPECT_LT(encoded.size(), size * 7 / 8 + 64);
  EXPECT_GT(encoded.size(), size * 6 / 8);
}

// Noise that repeats (a variable that does not depend on one axis of the chunk, as h_0 on
// T) is not stored: deflate's matches find the repeats.
TEST(ChunkCompressor, repeated_noise_still_compresses) {
  const std::size_t distinct = 1000;
  const std::size_t repeats = 4;
  std::vector<double> values(distinct * repeats);
  std::uint64_t x = 777;
  for (std::size_t i = 0; i < distinct; ++i) {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    for (std::size_t r = 0; r < repeats; ++r) values[r * distinct + i] = 1.0 + static_cast<double>(x >> 11) * 0x1p-53;
  }
  ChunkCompressor compressor(1);
  const std::size_t size = values.size() * sizeof(double);
  const std::span<const std::byte> encoded = compressor.compress(values.data(), size, sizeof(double));
  std::vector<std::byte> raw(size);
  std::memcpy(raw.data(), values.data(), size);
  EXPECT_EQ(inflate_all(encoded, size), shuffle(raw, sizeof(double)));
  EXPECT_LT(encoded.size(), size / repeats + size / 10);
}

}  // namespace
}  // namespace punchsweep::io
