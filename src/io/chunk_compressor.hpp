#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

struct libdeflate_compressor;

namespace punchsweep::io {

/// Encodes one HDF5 chunk the way the shuffle + deflate filter pipeline does, so the bytes
/// can go to H5Dwrite_chunk and any reader decodes them with the standard filters.
/// The deflate is libdeflate's whole-buffer zlib format (the stream HDF5's deflate filter
/// writes and reads with zlib): at level 1 it encodes a regime map's chunks about twice
/// as fast as zlib's deflate. One compressor and its buffers serve all chunks: HDF5's own
/// filter sets up a fresh zlib stream (a quarter MiB of state) per chunk.
class ChunkCompressor {
 public:
  /// `level`: the deflate level, 1 (fastest) to 9 (as HDF5's; libdeflate's own levels).
  explicit ChunkCompressor(int level);

  /// Byte-shuffles `size` bytes of `element_size`-byte elements (as H5Z_FILTER_SHUFFLE:
  /// the first bytes of all elements, then the second bytes, ...; nothing to do for 1-byte
  /// elements) and deflates the result into a zlib stream (as H5Z_FILTER_DEFLATE). The
  /// returned bytes stay valid until the next call. Throws std::runtime_error if deflate fails.
  std::span<const std::byte> compress(const void* data, std::size_t size, std::size_t element_size);

 private:
  struct Release {
    void operator()(libdeflate_compressor* c) const;
  };
  std::unique_ptr<libdeflate_compressor, Release> compressor_;
  std::vector<std::byte> shuffled_;
  std::vector<std::byte> compressed_;
};

/// Whether `zlib` (a chunk as compress() makes it) inflates to exactly `size` bytes: what a
/// reader of the map will do with it, checked before a chunk from a file is written.
bool inflates_to(std::span<const std::byte> zlib, std::size_t size);

}  // namespace punchsweep::io
