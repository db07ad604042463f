#include "io/tile_codec.hpp"

#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace punchsweep::io {

namespace {

constexpr std::uint32_t kMagic = 0x44545350;  // "PSTD" read as little-endian bytes
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kHeaderSize = 2 * sizeof(std::uint32_t) + 3 * sizeof(std::uint64_t);
constexpr std::size_t kPointArrays8 = 2;   // regime, valid
constexpr std::size_t kPointArrays64 = 6;  // t_star .. area_fraction_inf
constexpr std::size_t kSeriesArrays = 5;   // a1, a2, P1, P2, area_fraction

/// Appends raw bytes at a moving cursor; memcpy keeps the buffer free of alignment demands.
class Writer {
 public:
  explicit Writer(std::byte* at) : at_(at) {}
  template <typename T>
  void put(const T& value) {
    std::memcpy(at_, &value, sizeof(T));
    at_ += sizeof(T);
  }
  template <typename T>
  void put(const std::vector<T>& values) {
    if (values.empty()) return;  // data() may be null, which memcpy does not allow
    std::memcpy(at_, values.data(), values.size() * sizeof(T));
    at_ += values.size() * sizeof(T);
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
  template <typename T>
  void get(std::vector<T>* values, std::size_t n) {
    values->resize(n);
    if (n == 0) return;
    std::memcpy(values->data(), at_, n * sizeof(T));
    at_ += n * sizeof(T);
  }

 private:
  const std::byte* at_;
};

/// Checked form of packed_tile_size for counts read from untrusted bytes.
bool fits_in_size(std::uint64_t points, std::uint64_t series) {
  constexpr std::uint64_t kMax = std::numeric_limits<std::size_t>::max();
  const std::uint64_t per_point = kPointArrays8 + kPointArrays64 * sizeof(double);
  const std::uint64_t per_series = kSeriesArrays * sizeof(double);
  if (points > (kMax - kHeaderSize) / per_point) return false;
  const std::uint64_t used = kHeaderSize + points * per_point;
  return series <= (kMax - used) / per_series;
}

}  // namespace

std::size_t packed_tile_size(std::size_t points, std::size_t series) {
  return kHeaderSize + points * (kPointArrays8 + kPointArrays64 * sizeof(double)) +
         series * kSeriesArrays * sizeof(double);
}

std::vector<std::byte> pack_tile(std::uint64_t tile_index, const TileData& data) {
  const std::size_t points = data.regime.size();
  const std::size_t series = data.a1.size();
  if (data.valid.size() != points)
    throw std::invalid_argument("pack_tile: valid has a different length than regime");
  for (const auto* v :
       {&data.t_star, &data.h_0, &data.h_inf, &data.a1_inf, &data.a2_inf, &data.area_fraction_inf}) {
    if (v->size() != points)
      throw std::invalid_argument("pack_tile: a float64 point array has a different length than regime");
  }
  for (const auto* v : {&data.a2, &data.P1, &data.P2, &data.area_fraction}) {
    if (v->size() != series)
      throw std::invalid_argument("pack_tile: the time-series arrays differ in length");
  }

  std::vector<std::byte> bytes(packed_tile_size(points, series));
  Writer w(bytes.data());
  w.put(kMagic);
  w.put(kVersion);
  w.put(tile_index);
  w.put(static_cast<std::uint64_t>(points));
  w.put(static_cast<std::uint64_t>(series));
  w.put(data.regime);
  w.put(data.valid);
  for (const auto* v :
       {&data.t_star, &data.h_0, &data.h_inf, &data.a1_inf, &data.a2_inf, &data.area_fraction_inf})
    w.put(*v);
  for (const auto* v : {&data.a1, &data.a2, &data.P1, &data.P2, &data.area_fraction}) w.put(*v);
  return bytes;
}

std::uint64_t unpack_tile(const std::byte* bytes, std::size_t size, TileData* out) {
  if (size < kHeaderSize) {
    throw std::runtime_error("unpack_tile: buffer of " + std::to_string(size) +
                             " bytes is shorter than the " + std::to_string(kHeaderSize) +
                             "-byte tile header");
  }
  Reader r(bytes);
  const auto magic = r.get<std::uint32_t>();
  if (magic != kMagic) throw std::runtime_error("unpack_tile: buffer does not start with the tile magic");
  const auto version = r.get<std::uint32_t>();
  if (version != kVersion) {
    throw std::runtime_error("unpack_tile: tile format version " + std::to_string(version) + ", expected " +
                             std::to_string(kVersion));
  }
  const auto tile_index = r.get<std::uint64_t>();
  const auto points = r.get<std::uint64_t>();
  const auto series = r.get<std::uint64_t>();
  if (!fits_in_size(points, series)) {
    throw std::runtime_error("unpack_tile: impossible point count " + std::to_string(points) +
                             " / series count " + std::to_string(series));
  }
  if (points == 0 ? series != 0 : series % points != 0) {
    throw std::runtime_error("unpack_tile: series count " + std::to_string(series) +
                             " is not a multiple of the point count " + std::to_string(points));
  }
  const std::size_t expected = packed_tile_size(points, series);
  if (size != expected) {
    throw std::runtime_error("unpack_tile: buffer has " + std::to_string(size) + " bytes, but its header (" +
                             std::to_string(points) + " points, " + std::to_string(series) +
                             " series values) needs " + std::to_string(expected));
  }
  r.get(&out->regime, points);
  r.get(&out->valid, points);
  for (auto* v : {&out->t_star, &out->h_0, &out->h_inf, &out->a1_inf, &out->a2_inf, &out->area_fraction_inf})
    r.get(v, points);
  for (auto* v : {&out->a1, &out->a2, &out->P1, &out->P2, &out->area_fraction}) r.get(v, series);
  return tile_index;
}

}  // namespace punchsweep::io
