#pragma once

#include <vector>

namespace punchsweep::model {

/// Gauss-Legendre rule on [-1, 1], nodes ascending.
struct GaussLegendreRule {
  std::vector<double> nodes;
  std::vector<double> weights;
};

/// The n-point rule (1 <= n <= 128), computed once by GSL and cached (thread-safe).
const GaussLegendreRule& gauss_legendre(int n);

}  // namespace punchsweep::model
