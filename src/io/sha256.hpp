#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string_view>

namespace punchsweep::io {

using Digest = std::array<unsigned char, 32>;

/// SHA-256 (FIPS 180-4), incremental: update() any number of times, then digest().
class Sha256 {
 public:
  Sha256();
  void update(const void* data, std::size_t size);
  Digest digest();  ///< the hash of everything given; the object is spent after it

 private:
  void block(const unsigned char* p);
  std::array<std::uint32_t, 8> h_;
  std::array<unsigned char, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t length_ = 0;
};

/// HMAC-SHA-256 (RFC 2104) of the parts concatenated, under `key`: what the table cache
/// signs its files with.
Digest hmac_sha256(std::string_view key, std::initializer_list<std::string_view> parts);

}  // namespace punchsweep::io
