#pragma once

#include <cstddef>
#include <cstdint>

namespace punchsweep::io {

/// Uncompressed bytes per grid point of a regime map: int8 regime and valid, six float64
/// regime variables, and with the time series five float64 values per snapshot time.
inline std::size_t uncompressed_bytes_per_point(bool full, std::size_t times) {
  return 2 * sizeof(std::int8_t) + 6 * sizeof(double) + (full ? 5 * sizeof(double) * times : 0);
}

}  // namespace punchsweep::io
