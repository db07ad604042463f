#include "model/lattice.hpp"

#include <algorithm>
#include <cstdint>
#include <map>

namespace punchsweep::model {

std::vector<DistanceShell> level1_shells(double cx, double cy, int K) { return lattice_shells(cx, cy, K, 0.0); }

std::vector<DistanceShell> lattice_shells(double cx, double cy, int K, double offset) {
  // Squared distances are exact in quarters (the points used sit on the half-integer
  // grid), so the shells are keyed by 4 d^2, an integer; a square of half-width R holds
  // every site within R of the point, and K shells lie within sqrt(K) + 2 of it.
  const int R = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(K)) * 2.0)) + 4;
  std::map<std::int64_t, int> counts;
  for (int i = -R; i <= R; ++i) {
    for (int j = -R; j <= R; ++j) {
      const double dx = i + offset - cx;
      const double dy = j + offset - cy;
      const auto key = static_cast<std::int64_t>(std::llround(4.0 * (dx * dx + dy * dy)));
      if (key > 0) ++counts[key];
    }
  }
  std::vector<DistanceShell> shells;
  for (const auto& [key, n] : counts) {
    if (static_cast<int>(shells.size()) == K) break;
    shells.push_back({0.5 * std::sqrt(static_cast<double>(key)), n});
  }
  return shells;
}

}  // namespace punchsweep::model
