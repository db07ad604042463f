#pragma once

#include <cstddef>
#include <cstdint>

namespace punchsweep::io {

/// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320, as zlib and PNG use), continued
/// from `crc` so a long range can be fed in pieces: crc32(b, crc32(a)) == crc32(a + b).
/// crc32 of "123456789" is 0xCBF43926.
std::uint32_t crc32(const void* data, std::size_t size, std::uint32_t crc = 0);

}  // namespace punchsweep::io
