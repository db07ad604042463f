#pragma once

#include <vector>

namespace punchsweep::model {

/// A Gauss quadrature rule: int f w ~= sum_i weights[i] f(nodes[i]), nodes ascending.
struct GaussRule {
  std::vector<double> nodes;
  std::vector<double> weights;
};

/// The n-point Gauss-Legendre rule on [-1, 1] (1 <= n <= 128), computed once by GSL and
/// cached (thread-safe).
const GaussRule& gauss_legendre(int n);

/// The n-point Gauss-Laguerre rule for int_0^inf exp(-x) f(x) dx (1 <= n <= 32): exact for
/// polynomials of degree 2n - 1. Computed once by GSL and cached (thread-safe).
const GaussRule& gauss_laguerre(int n);

}  // namespace punchsweep::model
