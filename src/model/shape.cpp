#include "model/shape.hpp"

#include <cmath>
#include <numbers>

namespace punchsweep::model {

std::string shape_error(const Shape& shape) {
  if (shape.s < Shape::kMinExponent || shape.s > Shape::kMaxExponent) {
    return "shape exponent s = " + std::to_string(shape.s) + " is outside its range: an integer in [" +
           std::to_string(Shape::kMinExponent) + ", " + std::to_string(Shape::kMaxExponent) + "]";
  }
  if (!(shape.C > 0.0) || !std::isfinite(shape.C)) {
    return "shape constant C = " + std::to_string(shape.C) + " is outside its range: C > 0";
  }
  return {};
}

// Log-gamma keeps both coefficients finite for every admissible s (Gamma(s) alone
// overflows long before the exponent limit would).
double load_coefficient(const Shape& shape) {
  const double s = shape.s;
  return shape.C * std::exp((s - 1.0) * std::numbers::ln2 + 2.0 * std::log(s) +
                            2.0 * std::lgamma(0.5 * s) - std::log(s + 1.0) - std::lgamma(s));
}

double depth_coefficient(const Shape& shape) {
  const double s = shape.s;
  return shape.C * std::exp(std::log(s) + 2.0 * std::lgamma(0.5 * s) -
                            (2.0 - s) * std::numbers::ln2 - std::lgamma(s));
}

}  // namespace punchsweep::model
