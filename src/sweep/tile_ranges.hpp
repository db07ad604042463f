#pragma once

#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

namespace punchsweep::sweep {

/// A set of tile indices as increasing, disjoint ranges [first, last). A fresh sweep of any
/// size is one range, and a resumed one has a range per gap its journal leaves, so the
/// memory of the work list never grows with the grid (a 1e12-point grid is 2.4e8 tiles).
class TileRanges {
 public:
  TileRanges() = default;
  /// All tiles [0, count).
  explicit TileRanges(std::uint64_t count) { add(0, count); }

  /// Appends [first, last); ranges must come in increasing order (they may touch).
  void add(std::uint64_t first, std::uint64_t last) {
    if (last <= first) return;
    if (!ranges_.empty() && ranges_.back().second == first) {
      ranges_.back().second = last;
    } else {
      ranges_.emplace_back(first, last);
    }
    size_ += last - first;
  }
  /// Appends one tile (after every tile already in the set).
  void add(std::uint64_t tile) { add(tile, tile + 1); }

  std::uint64_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::uint64_t front() const { return ranges_.front().first; }

  /// Removes and returns the first tile.
  std::uint64_t pop_front() {
    const std::uint64_t tile = ranges_.front().first++;
    if (ranges_.front().first == ranges_.front().second) ranges_.pop_front();
    --size_;
    return tile;
  }

  /// Removes the first `n` tiles (or all there are) and returns them as ranges.
  TileRanges take(std::uint64_t n) {
    TileRanges taken;
    while (n > 0 && !ranges_.empty()) {
      auto& [first, last] = ranges_.front();
      const std::uint64_t k = std::min(n, last - first);
      taken.add(first, first + k);
      first += k;
      size_ -= k;
      n -= k;
      if (first == last) ranges_.pop_front();
    }
    return taken;
  }

  /// The ranges as a flat list first0, last0, first1, last1, ... (a message), and back.
  std::vector<std::uint64_t> flat() const {
    std::vector<std::uint64_t> out;
    out.reserve(2 * ranges_.size());
    for (const auto& [first, last] : ranges_) {
      out.push_back(first);
      out.push_back(last);
    }
    return out;
  }
  void add_flat(const std::vector<std::uint64_t>& flat) {
    for (std::size_t i = 0; i + 1 < flat.size(); i += 2) add(flat[i], flat[i + 1]);
  }

  /// Every tile, in order (for tests and small sets).
  std::vector<std::uint64_t> tiles() const {
    std::vector<std::uint64_t> out;
    for (const auto& [first, last] : ranges_) {
      for (std::uint64_t t = first; t < last; ++t) out.push_back(t);
    }
    return out;
  }

 private:
  std::deque<std::pair<std::uint64_t, std::uint64_t>> ranges_;
  std::uint64_t size_ = 0;
};

}  // namespace punchsweep::sweep
