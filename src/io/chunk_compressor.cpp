#include "io/chunk_compressor.hpp"

#include <libdeflate.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <algorithm>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <string>

namespace punchsweep::io {
namespace {

// Below this many elements a chunk is deflated whole: the byte-entropy test is too noisy
// and the time too small to matter.
constexpr std::size_t kMinElementsForStoredPlanes = 1024;

// Empirical entropy (bits per byte) of a plane of n bytes is taken as "noise" when it lies
// within this many times the plug-in estimator's bias for uniform bytes, 255 / (2 n ln 2),
// of 8 bits. Uniform bytes land at 1.0 +- 0.1 times the bias; a plane whose values repeat
// r times (as a variable that does not depend on an axis of the chunk) sits near r times
// it, so repeats (r >= 2) stay with deflate, whose matches compress them.
constexpr double kNoiseBiasFactor = 1.5;

// n log2 n for a byte count n.
double n_log2_n(std::uint32_t n) { return n == 0 ? 0.0 : n * std::log2(static_cast<double>(n)); }

// Whether the plane's bytes are indistinguishable from uniform noise (deflate would store
// them anyway, after spending its match search on them).
bool is_noise(const std::byte* plane, std::size_t n) {
  // Four histograms over interleaved bytes, added: a run of equal bytes then increments
  // four counters in turn instead of waiting on one (the same counts).
  std::array<std::array<std::uint32_t, 256>, 4> partial{};
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    for (int k = 0; k < 4; ++k) ++partial[k][static_cast<std::uint8_t>(plane[i + k])];
  }
  for (; i < n; ++i) ++partial[0][static_cast<std::uint8_t>(plane[i])];
  std::array<std::uint32_t, 256> count{};
  for (int v = 0; v < 256; ++v) count[v] = partial[0][v] + partial[1][v] + partial[2][v] + partial[3][v];
  double sum = 0.0;
  for (const std::uint32_t c : count) sum += n_log2_n(c);
  const double entropy = std::log2(static_cast<double>(n)) - sum / static_cast<double>(n);
  const double bias = 255.0 / (2.0 * static_cast<double>(n) * std::numbers::ln2);
  return entropy > 8.0 - kNoiseBiasFactor * bias;
}

void put_u16_le(std::byte* out, std::size_t v) {
  out[0] = static_cast<std::byte>(v & 0xFF);
  out[1] = static_cast<std::byte>((v >> 8) & 0xFF);
}

}  // namespace

void ChunkCompressor::Release::operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }

ChunkCompressor::ChunkCompressor(int level) : compressor_(libdeflate_alloc_compressor(level)) {
  if (level < 1 || level > 9 || !compressor_) {
    throw std::runtime_error("libdeflate: cannot set up deflate level " + std::to_string(level) + " (valid: 1 to 9)");
  }
}

std::span<const std::byte> ChunkCompressor::compress(const void* data, std::size_t size,
                                                     std::size_t element_size) {
  const auto* in = static_cast<const std::byte*>(data);
  const std::size_t elements = element_size == 0 ? 0 : size / element_size;
  if (element_size > 1 && elements > 1) {
    shuffled_.resize(size);
    if (element_size == 8) {
      // Doubles (every float variable of a map): each element read once, its bytes to
      // their planes.
      std::byte* plane[8];
      for (std::size_t b = 0; b < 8; ++b) plane[b] = shuffled_.data() + b * elements;
      for (std::size_t i = 0; i < elements; ++i) {
        const std::byte* e = in + 8 * i;
        for (std::size_t b = 0; b < 8; ++b) plane[b][i] = e[b];
      }
    } else {
      for (std::size_t b = 0; b < element_size; ++b) {
        std::byte* out = shuffled_.data() + b * elements;
        for (std::size_t i = 0; i < elements; ++i) out[i] = in[i * element_size + b];
      }
    }
    // Like HDF5's shuffle, bytes after the last whole element stay as they are.
    for (std::size_t i = elements * element_size; i < size; ++i) shuffled_[i] = in[i];
    in = shuffled_.data();
  }

  // Leading planes of noise (the low mantissa bytes of most doubles: the first planes after
  // the shuffle on a little-endian machine) go into stored blocks; the top plane always
  // goes to deflate, which then needs to see only the rest.
  std::size_t stored = 0;
  if (element_size > 1 && elements >= kMinElementsForStoredPlanes) {
    while (stored + 1 < element_size && is_noise(in + stored * elements, elements)) ++stored;
  }
  const std::size_t stored_bytes = stored * elements;
  if (stored_bytes == 0) {
    compressed_.resize(libdeflate_zlib_compress_bound(compressor_.get(), size));
    const std::size_t written =
        libdeflate_zlib_compress(compressor_.get(), in, size, compressed_.data(), compressed_.size());
    if (written == 0) {
      throw std::runtime_error("libdeflate: deflate of a " + std::to_string(size) + "-byte chunk failed");
    }
    return {compressed_.data(), written};
  }

  // A zlib stream by hand (RFC 1950/1951): header; non-final stored blocks of at most
  // 65535 bytes (each starts on a byte boundary, so its 3 header bits and padding make one
  // zero byte, then LEN and ~LEN); the rest as raw deflate blocks, the last one final; the
  // Adler-32 of all the data, big-endian.
  constexpr std::size_t kMaxStored = 65535;
  const std::size_t blocks = (stored_bytes + kMaxStored - 1) / kMaxStored;
  const std::size_t rest = size - stored_bytes;
  compressed_.resize(2 + blocks * 5 + stored_bytes + libdeflate_deflate_compress_bound(compressor_.get(), rest) + 4);
  std::byte* out = compressed_.data();
  out[0] = std::byte{0x78};  // deflate, 32 KiB window
  out[1] = std::byte{0x01};  // fastest level; (0x78 * 256 + 0x01) % 31 == 0
  out += 2;
  for (std::size_t at = 0; at < stored_bytes; at += kMaxStored) {
    const std::size_t len = std::min(kMaxStored, stored_bytes - at);
    out[0] = std::byte{0x00};  // BFINAL 0, BTYPE 00 (stored)
    put_u16_le(out + 1, len);
    put_u16_le(out + 3, ~len & 0xFFFF);
    std::memcpy(out + 5, in + at, len);
    out += 5 + len;
  }
  const std::size_t room = static_cast<std::size_t>(compressed_.data() + compressed_.size() - out) - 4;
  const std::size_t written = libdeflate_deflate_compress(compressor_.get(), in + stored_bytes, rest, out, room);
  if (written == 0) {
    throw std::runtime_error("libdeflate: deflate of a " + std::to_string(size) + "-byte chunk failed");
  }
  out += written;
  const std::uint32_t adler = libdeflate_adler32(1, in, size);
  for (int shift = 24; shift >= 0; shift -= 8) *out++ = static_cast<std::byte>((adler >> shift) & 0xFF);
  return {compressed_.data(), static_cast<std::size_t>(out - compressed_.data())};
}

bool inflates_to(std::span<const std::byte> zlib, std::size_t size) {
  const std::unique_ptr<libdeflate_decompressor, void (*)(libdeflate_decompressor*)> d(libdeflate_alloc_decompressor(),
                                                                                      libdeflate_free_decompressor);
  if (!d) throw std::runtime_error("libdeflate: cannot set up a decompressor");
  std::vector<std::byte> out(size);
  std::size_t actual = 0;
  return libdeflate_zlib_decompress(d.get(), zlib.data(), zlib.size(), out.data(), out.size(), &actual) ==
             LIBDEFLATE_SUCCESS &&
         actual == size;
}

}  // namespace punchsweep::io
