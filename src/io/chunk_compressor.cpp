#include "io/chunk_compressor.hpp"

#include <zlib.h>

#include <limits>
#include <stdexcept>
#include <string>

namespace punchsweep::io {

/// A z_stream must stay at one address once initialised (zlib keeps a pointer back to it).
struct ChunkCompressor::Stream {
  z_stream z{};
  ~Stream() { deflateEnd(&z); }
};

ChunkCompressor::ChunkCompressor(int level) : stream_(std::make_unique<Stream>()) {
  // The same stream parameters as HDF5's deflate filter (compress2: zlib format, 32 KiB window).
  if (deflateInit(&stream_->z, level) != Z_OK) {
    throw std::runtime_error("zlib: cannot set up deflate level " + std::to_string(level));
  }
}

ChunkCompressor::~ChunkCompressor() = default;
ChunkCompressor::ChunkCompressor(ChunkCompressor&&) noexcept = default;
ChunkCompressor& ChunkCompressor::operator=(ChunkCompressor&&) noexcept = default;

std::span<const std::byte> ChunkCompressor::compress(const void* data, std::size_t size,
                                                     std::size_t element_size) {
  if (size > std::numeric_limits<uInt>::max() / 2) {
    throw std::runtime_error("zlib: chunk of " + std::to_string(size) +
                             " bytes is too large to deflate at once");
  }
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

  z_stream& z = stream_->z;
  if (deflateReset(&z) != Z_OK) throw std::runtime_error("zlib: deflateReset failed");
  compressed_.resize(deflateBound(&z, static_cast<uLong>(size)));
  z.next_in = reinterpret_cast<Bytef*>(const_cast<std::byte*>(in));  // zlib's API is not const-correct
  z.avail_in = static_cast<uInt>(size);
  z.next_out = reinterpret_cast<Bytef*>(compressed_.data());
  z.avail_out = static_cast<uInt>(compressed_.size());
  const int status = deflate(&z, Z_FINISH);
  if (status != Z_STREAM_END) {
    throw std::runtime_error("zlib: deflate of a " + std::to_string(size) + "-byte chunk failed (status " +
                             std::to_string(status) + ")");
  }
  return {compressed_.data(), compressed_.size() - z.avail_out};
}

}  // namespace punchsweep::io
