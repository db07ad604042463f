#include "io/encoded_tile.hpp"

#include <array>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>

namespace punchsweep::io {

namespace {

constexpr std::uint32_t kMagic = 0x54455350;  // "PSET" read as little-endian bytes
// 2: BEM reference counts in the header; 3: chunks in map::kQuantities order; 4: five
// validity counts (code 4, inaccurate); 5: seven (outside_table, unloading: the periodic model).
constexpr std::uint32_t kVersion = 5;
constexpr std::size_t kHeaderSize = 2 * sizeof(std::uint32_t) +
                                    (2 + std::tuple_size_v<decltype(TileSummary::regimes)> +
                                     std::tuple_size_v<decltype(TileSummary::validity)> +
                                     std::tuple_size_v<decltype(TileSummary::bem_regimes)> + 1 + 1) *
                                        sizeof(std::uint64_t);

/// Appends raw bytes at a moving cursor; memcpy keeps the buffer free of alignment demands.
class Writer {
 public:
  explicit Writer(std::byte* at) : at_(at) {}
  template <typename T>
  void put(const T& value) {
    std::memcpy(at_, &value, sizeof(T));
    at_ += sizeof(T);
  }
  void put(const std::vector<std::byte>& bytes) {
    if (bytes.empty()) return;  // data() may be null, which memcpy does not allow
    std::memcpy(at_, bytes.data(), bytes.size());
    at_ += bytes.size();
  }

 private:
  std::byte* at_;
};

class Reader {
 public:
  explicit Reader(const std::byte* at) : at_(at) {}
  template <typename T>
  T get() {
    T value;
    std::memcpy(&value, at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::vector<std::byte> get(std::size_t n) {
    std::vector<std::byte> bytes(at_, at_ + n);
    at_ += n;
    return bytes;
  }

 private:
  const std::byte* at_;
};

}  // namespace

std::vector<std::byte> pack_encoded_tile(const EncodedTile& tile) {
  std::size_t size = kHeaderSize + tile.chunks.size() * sizeof(std::uint64_t);
  for (const std::vector<std::byte>& chunk : tile.chunks) size += chunk.size();
  std::vector<std::byte> bytes(size);
  Writer w(bytes.data());
  w.put(kMagic);
  w.put(kVersion);
  w.put(tile.tile);
  w.put(tile.summary.points);
  for (const std::uint64_t n : tile.summary.regimes) w.put(n);
  for (const std::uint64_t n : tile.summary.validity) w.put(n);
  for (const std::uint64_t n : tile.summary.bem_regimes) w.put(n);
  w.put(tile.summary.bem_agreeing);
  w.put(static_cast<std::uint64_t>(tile.chunks.size()));
  for (const std::vector<std::byte>& chunk : tile.chunks) w.put(static_cast<std::uint64_t>(chunk.size()));
  for (const std::vector<std::byte>& chunk : tile.chunks) w.put(chunk);
  return bytes;
}

EncodedTile unpack_encoded_tile(const std::byte* bytes, std::size_t size) {
  if (size < kHeaderSize) {
    throw std::runtime_error("unpack_encoded_tile: buffer of " + std::to_string(size) +
                             " bytes is shorter than the " + std::to_string(kHeaderSize) +
                             "-byte tile header");
  }
  Reader r(bytes);
  if (r.get<std::uint32_t>() != kMagic)
    throw std::runtime_error("unpack_encoded_tile: buffer does not start with the encoded-tile magic");
  const auto version = r.get<std::uint32_t>();
  if (version != kVersion) {
    throw std::runtime_error("unpack_encoded_tile: encoded-tile format version " + std::to_string(version) +
                             ", expected " + std::to_string(kVersion));
  }
  EncodedTile tile;
  tile.tile = r.get<std::uint64_t>();
  tile.summary.points = r.get<std::uint64_t>();
  for (std::uint64_t& n : tile.summary.regimes) n = r.get<std::uint64_t>();
  for (std::uint64_t& n : tile.summary.validity) n = r.get<std::uint64_t>();
  for (std::uint64_t& n : tile.summary.bem_regimes) n = r.get<std::uint64_t>();
  tile.summary.bem_agreeing = r.get<std::uint64_t>();
  // What is left of `total` after the counts, or nothing when they exceed it (subtracting
  // cannot overflow, unlike summing).
  const auto left_after = [](std::uint64_t total, const auto& counts) -> std::optional<std::uint64_t> {
    for (const std::uint64_t n : counts) {
      if (n > total) return std::nullopt;
      total -= n;
    }
    return total;
  };
  const std::uint64_t points = tile.summary.points;
  const std::optional<std::uint64_t> not_bem = left_after(points, tile.summary.bem_regimes);
  if (!left_after(points, tile.summary.regimes) || !left_after(points, tile.summary.validity) || !not_bem) {
    throw std::runtime_error("unpack_encoded_tile: the regime, validity or BEM counts exceed the tile's " +
                             std::to_string(points) + " points");
  }
  if (tile.summary.bem_agreeing > points - *not_bem) {
    throw std::runtime_error("unpack_encoded_tile: " + std::to_string(tile.summary.bem_agreeing) +
                             " BEM points agree with the model, but the tile has only " +
                             std::to_string(points - *not_bem));
  }
  const auto chunks = r.get<std::uint64_t>();
  std::size_t left = size - kHeaderSize;
  if (chunks > left / sizeof(std::uint64_t)) {
    throw std::runtime_error("unpack_encoded_tile: impossible chunk count " + std::to_string(chunks) +
                             " for a buffer of " + std::to_string(size) + " bytes");
  }
  left -= static_cast<std::size_t>(chunks) * sizeof(std::uint64_t);
  std::vector<std::size_t> lengths(static_cast<std::size_t>(chunks));
  std::uint64_t needed = 0;  // stays <= left + one length, so it cannot overflow
  for (std::size_t& length : lengths) {
    const auto n = r.get<std::uint64_t>();
    needed += n;
    if (n > left || needed > left) {
      throw std::runtime_error("unpack_encoded_tile: chunk lengths run past the end of the " +
                               std::to_string(size) + "-byte buffer");
    }
    length = static_cast<std::size_t>(n);
  }
  if (needed != left) {
    throw std::runtime_error("unpack_encoded_tile: buffer has " + std::to_string(size) +
                             " bytes, but its header and chunk lengths need " +
                             std::to_string(size - left + needed));
  }
  tile.chunks.reserve(lengths.size());
  for (const std::size_t length : lengths) tile.chunks.push_back(r.get(length));
  return tile;
}

}  // namespace punchsweep::io
