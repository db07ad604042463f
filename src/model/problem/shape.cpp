#include "model/problem/shape.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace punchsweep::model {

namespace {

// K_P / C and K_d / C for every admissible s, computed once (the sweep builds solvers per
// point; lgamma there showed up in profiles). Log-gamma keeps both finite for every s.
struct CoefficientTable {
  std::array<double, Shape::kMaxExponent + 1> load{};
  std::array<double, Shape::kMaxExponent + 1> depth{};
  CoefficientTable() {
    for (int n = Shape::kMinExponent; n <= Shape::kMaxExponent; ++n) {
      const double s = n;
      load[n] = std::exp((s - 1.0) * std::numbers::ln2 + 2.0 * std::log(s) + 2.0 * std::lgamma(0.5 * s) -
                         std::log(s + 1.0) - std::lgamma(s));
      depth[n] = std::exp(std::log(s) + 2.0 * std::lgamma(0.5 * s) - (2.0 - s) * std::numbers::ln2 -
                          std::lgamma(s));
    }
  }
};

const CoefficientTable& coefficients() {
  static const CoefficientTable table;
  return table;
}

}  // namespace

double load_coefficient(const Shape& shape) { return shape.C * coefficients().load.at(shape.s); }

double depth_coefficient(const Shape& shape) { return shape.C * coefficients().depth.at(shape.s); }

}  // namespace punchsweep::model
