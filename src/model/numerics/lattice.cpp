#include "model/numerics/lattice.hpp"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <map>
#include <numbers>

namespace punchsweep::model {

double lattice_far_field_constant() {
  // zeta(1/2) and Dirichlet's beta(1/2) = sum (-1)^n / sqrt(2n + 1), to 30 digits (mpmath's
  // zeta(0.5) and dirichlet(0.5, [0, 1, 0, -1])).
  constexpr double kZetaHalf = -1.4603545088095868128894991525152980125;
  constexpr double kBetaHalf = 0.66769145718960917665869092930377;
  return 4.0 * (2.0 - std::numbers::sqrt2) * kZetaHalf * kBetaHalf / std::numbers::pi;
}

std::vector<DistanceShell> lattice_shells(double cx, double cy, int K, int level) {
  const double offset = level == 1 ? 0.0 : 0.5;
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
    shells.push_back({0.5 * std::sqrt(static_cast<double>(key)), n, level});
  }
  return shells;
}

std::vector<DistanceShell> kept_neighbours(int level, int D) {
  const double c = level == 1 ? 0.0 : 0.5;
  // Each level holds at least its share of the D nearest distances among its D nearest
  // shells; merge both and keep every shell at or within the D-th distinct distance.
  std::vector<DistanceShell> all = lattice_shells(c, c, D, 1);
  for (const DistanceShell& shell : lattice_shells(c, c, D, 2)) all.push_back(shell);
  std::sort(all.begin(), all.end(), [](const DistanceShell& a, const DistanceShell& b) {
    return a.distance < b.distance || (a.distance == b.distance && a.level < b.level);
  });
  std::vector<DistanceShell> kept;
  int distinct = 0;
  double last = -1.0;
  for (const DistanceShell& shell : all) {
    if (shell.distance != last) {
      if (++distinct > D) break;
      last = shell.distance;
    }
    kept.push_back(shell);
  }
  return kept;
}

}  // namespace punchsweep::model
