#include "sweep/reference_sample.hpp"

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>

namespace punchsweep::sweep {
namespace {

/// A uniform draw from [0, bound), bound >= 1: rejecting the lowest 2^64 mod bound outputs
/// leaves a whole number of copies of every residue.
std::uint64_t uniform_below(std::mt19937_64& rng, std::uint64_t bound) {
  const std::uint64_t reject_below = (0 - bound) % bound;
  while (true) {
    const std::uint64_t x = rng();
    if (x >= reject_below) return x % bound;
  }
}

}  // namespace

ReferenceSample::ReferenceSample(std::uint64_t points, std::optional<std::uint64_t> sample,
                                 std::uint64_t seed)
    : points_(points), all_(!sample.has_value()) {
  if (all_) return;
  const std::uint64_t k = *sample;
  if (k == 0 || k > points) {
    throw std::invalid_argument("reference sample of " + std::to_string(k) + " points from a grid of " +
                                std::to_string(points) + ": it must hold 1 to " + std::to_string(points));
  }
  // Floyd's algorithm: K draws, each subset equally likely, memory O(K) whatever the grid.
  std::mt19937_64 rng(seed);
  std::unordered_set<std::uint64_t> chosen;
  chosen.reserve(static_cast<std::size_t>(k));
  for (std::uint64_t j = points - k; j < points; ++j) {
    const std::uint64_t t = uniform_below(rng, j + 1);
    if (!chosen.insert(t).second) chosen.insert(j);
  }
  chosen_.assign(chosen.begin(), chosen.end());
  std::sort(chosen_.begin(), chosen_.end());
}

ReferenceSample::ReferenceSample(std::uint64_t points, std::vector<std::uint64_t> chosen)
    : points_(points), all_(false), chosen_(std::move(chosen)) {
  if (!std::is_sorted(chosen_.begin(), chosen_.end()) ||
      std::adjacent_find(chosen_.begin(), chosen_.end()) != chosen_.end() ||
      (!chosen_.empty() && chosen_.back() >= points)) {
    throw std::invalid_argument("reference sample: the chosen points must be distinct, increasing and below " +
                                std::to_string(points));
  }
}

bool ReferenceSample::contains(std::uint64_t point) const {
  if (all_) return point < points_;
  return std::binary_search(chosen_.begin(), chosen_.end(), point);
}

}  // namespace punchsweep::sweep
