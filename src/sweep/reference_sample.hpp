#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace punchsweep::sweep {

/// The grid points at which a sweep evaluates the reference solver: all of them, or K
/// distinct points drawn uniformly at random. Points are numbered row-major over
/// (l, dh, T, pbar, s), as in the map. The draw is a pure function of (point count, K,
/// seed): Floyd's algorithm over std::mt19937_64 (whose output the standard fixes), with
/// its own unbiased bounded draw, because std::uniform_int_distribution differs between
/// standard libraries. So every rank, tiling and resumed run agrees on the sample.
class ReferenceSample {
 public:
  /// All `points` points when `sample` is empty, else `*sample` of them drawn with `seed`.
  /// Throws std::invalid_argument when *sample is 0 or more than `points`.
  ReferenceSample(std::uint64_t points, std::optional<std::uint64_t> sample, std::uint64_t seed);
  /// The points listed in `chosen` (flat indices below `points`, increasing; may be none).
  ReferenceSample(std::uint64_t points, std::vector<std::uint64_t> chosen);

  /// Whether grid point `point` (flat index) is in the sample.
  bool contains(std::uint64_t point) const;

  /// The number of sampled points.
  std::uint64_t size() const { return all_ ? points_ : static_cast<std::uint64_t>(chosen_.size()); }

  /// The k-th sampled point in increasing order, for k < size().
  std::uint64_t at(std::uint64_t k) const { return all_ ? k : chosen_[static_cast<std::size_t>(k)]; }

 private:
  std::uint64_t points_ = 0;
  bool all_ = true;
  std::vector<std::uint64_t> chosen_;  ///< sorted; empty when all_
};

}  // namespace punchsweep::sweep
