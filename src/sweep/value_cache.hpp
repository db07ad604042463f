#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace punchsweep::sweep {

/// A bounded map from a key of `width` doubles (compared bit for bit) to a Value, by open
/// addressing: the batch evaluator's caches of parts that depend on fewer coordinates than
/// a point (a lookup is a hash and a probe or two, where std::unordered_map chased nodes).
/// Every cached value is a pure function of its key, so emptying the cache when it is full
/// changes no result, only the time. A reference from find() or insert() is good until the
/// next insert().
template <class Value>
class ValueCache {
 public:
  ValueCache(std::size_t width, std::size_t max_entries) : width_(width), max_entries_(max_entries) {}

  /// The value stored for `key` (width() doubles), or nullptr.
  Value* find(std::span<const double> key) {
    if (values_.empty()) return nullptr;
    for (std::size_t slot = hash(key) & mask_;; slot = (slot + 1) & mask_) {
      const std::uint32_t entry = slots_[slot];
      if (entry == 0) return nullptr;
      if (same(entry - 1, key)) return &values_[entry - 1];
    }
  }

  /// Stores `value` for `key` (not stored yet), emptying the cache first when it is full.
  Value& insert(std::span<const double> key, Value value) {
    if (values_.size() >= max_entries_) clear();
    if (2 * (values_.size() + 1) > slots_.size()) grow();
    keys_.insert(keys_.end(), key.begin(), key.end());
    values_.push_back(std::move(value));
    place(values_.size() - 1, key);
    return values_.back();
  }

  void clear() {
    keys_.clear();
    values_.clear();
    std::fill(slots_.begin(), slots_.end(), 0u);
  }
  std::size_t size() const { return values_.size(); }
  std::size_t width() const { return width_; }

 private:
  static std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }
  std::uint64_t hash(std::span<const double> key) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (const double v : key) {  // splitmix64's finaliser over each word
      std::uint64_t z = h ^ bits(v);
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
      h = z ^ (z >> 31);
    }
    return h;
  }
  bool same(std::size_t entry, std::span<const double> key) const {
    const double* stored = &keys_[entry * width_];
    for (std::size_t k = 0; k < width_; ++k) {
      if (bits(stored[k]) != bits(key[k])) return false;
    }
    return true;
  }
  void place(std::size_t entry, std::span<const double> key) {
    std::size_t slot = hash(key) & mask_;
    while (slots_[slot] != 0) slot = (slot + 1) & mask_;
    slots_[slot] = static_cast<std::uint32_t>(entry + 1);
  }
  void grow() {
    slots_.assign(std::max<std::size_t>(16, 2 * slots_.size()), 0u);
    mask_ = slots_.size() - 1;
    for (std::size_t e = 0; e < values_.size(); ++e) place(e, {&keys_[e * width_], width_});
  }

  std::size_t width_;
  std::size_t max_entries_;
  std::vector<double> keys_;           ///< width_ per entry
  std::vector<Value> values_;
  std::vector<std::uint32_t> slots_;   ///< a power of two of them; 0 = empty, else entry + 1
  std::size_t mask_ = 0;
};

}  // namespace punchsweep::sweep

namespace punchsweep::sweep {

/// A fixed-size, direct-mapped cache from a key of Width doubles (bit for bit) to a Value:
/// one multiply to find the only slot a key may sit in, and a newer key simply takes it
/// over. For the parts a point looks up (its single-level states, the paper's elastic
/// start), where ValueCache's hashing and probing cost a sweep 5-10% of its rate. As with
/// ValueCache, every value is a pure function of its key, so what the cache holds changes
/// no result.
template <class Value, std::size_t Width>
class DirectCache {
 public:
  /// 2^log2_slots slots.
  explicit DirectCache(int log2_slots) : slots_(std::size_t{1} << log2_slots), shift_(64 - log2_slots) {}

  /// The value stored for `key`, or nullptr.
  Value* find(const std::array<double, Width>& key) {
    Slot& slot = slots_[index(key)];
    return slot.used && same(slot.key, key) ? &slot.value : nullptr;
  }
  /// Stores `value` for `key`, in place of what its slot held.
  Value& put(const std::array<double, Width>& key, Value value) {
    Slot& slot = slots_[index(key)];
    slot = Slot{key, std::move(value), true};
    return slot.value;
  }

 private:
  struct Slot {
    std::array<double, Width> key{};
    Value value{};
    bool used = false;
  };
  static std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }
  static bool same(const std::array<double, Width>& a, const std::array<double, Width>& b) {
    for (std::size_t k = 0; k < Width; ++k) {
      if (bits(a[k]) != bits(b[k])) return false;
    }
    return true;
  }
  std::size_t index(const std::array<double, Width>& key) const {
    std::uint64_t h = 0;
    for (const double v : key) h = (h ^ bits(v)) * 0x9e3779b97f4a7c15ull;  // Fibonacci hashing
    return static_cast<std::size_t>(h >> shift_);
  }

  std::vector<Slot> slots_;
  int shift_;
};

}  // namespace punchsweep::sweep
