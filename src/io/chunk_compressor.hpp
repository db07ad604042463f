#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

namespace punchsweep::io {

/// Encodes one HDF5 chunk the way the shuffle + deflate filter pipeline does, so the bytes
/// can go to H5Dwrite_chunk and any reader decodes them with the standard filters.
/// It keeps one zlib stream and its buffers for all chunks: HDF5's own deflate filter
/// sets up a fresh stream (a quarter MiB of state) per chunk, and that allocation churn
/// cost more than the compression itself.
class ChunkCompressor {
 public:
  /// `level`: the zlib deflate level, 1 (fastest) to 9.
  explicit ChunkCompressor(int level);
  ~ChunkCompressor();
  ChunkCompressor(ChunkCompressor&&) noexcept;
  ChunkCompressor& operator=(ChunkCompressor&&) noexcept;
  ChunkCompressor(const ChunkCompressor&) = delete;
  ChunkCompressor& operator=(const ChunkCompressor&) = delete;

  /// Byte-shuffles `size` bytes of `element_size`-byte elements (as H5Z_FILTER_SHUFFLE:
  /// the first bytes of all elements, then the second bytes, ...; nothing to do for 1-byte
  /// elements) and deflates the result into a zlib stream (as H5Z_FILTER_DEFLATE). The
  /// returned bytes stay valid until the next call. Throws std::runtime_error if zlib fails.
  std::span<const std::byte> compress(const void* data, std::size_t size, std::size_t element_size);

 private:
  struct Stream;
  std::unique_ptr<Stream> stream_;
  std::vector<std::byte> shuffled_;
  std::vector<std::byte> compressed_;
};

}  // namespace punchsweep::io
