#include "io/chunk_compressor.hpp"

#include <libdeflate.h>

#include <stdexcept>
#include <string>

namespace punchsweep::io {

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
    for (std::size_t b = 0; b < element_size; ++b) {
      std::byte* out = shuffled_.data() + b * elements;
      for (std::size_t i = 0; i < elements; ++i) out[i] = in[i * element_size + b];
    }
    // Like HDF5's shuffle, bytes after the last whole element stay as they are.
    for (std::size_t i = elements * element_size; i < size; ++i) shuffled_[i] = in[i];
    in = shuffled_.data();
  }

  compressed_.resize(libdeflate_zlib_compress_bound(compressor_.get(), size));
  const std::size_t written =
      libdeflate_zlib_compress(compressor_.get(), in, size, compressed_.data(), compressed_.size());
  if (written == 0) {
    throw std::runtime_error("libdeflate: deflate of a " + std::to_string(size) + "-byte chunk failed");
  }
  return {compressed_.data(), written};
}

}  // namespace punchsweep::io
