#pragma once

#include <cmath>
#include <vector>

namespace punchsweep::model {

/// The m = 0 average, about a punch, of a neighbour's spot (docs/model.md, section 11): for
/// a neighbour whose contact of radius a carries the isolated punch's pressure p_(k,m)
/// (eq 9.1, exponent s), centred at distance rho,
///   <f> = (1/P) int f(|x'|) p(x' - rho e) dA',
/// the mean of f over the distances of the spot's points, weighted by their load: 24
/// Gauss-Legendre nodes in phi (r' = a sin(phi)) by 48 midpoint angles on [0, pi] (the
/// integrand is even and periodic in the angle, so the rule converges as (a/rho)^96) near
/// the punch; from rho >= kFarDistance a on, 16 angles (the two agree to 1e-13 there,
/// `single_level_shells_test.cpp`).
class SpotAverage {
 public:
  explicit SpotAverage(int s);

  static constexpr double kFarDistance = 4.0;

  template <class F>
  double operator()(F&& f, double rho, double a) const {
    const Rule& rule = rho < kFarDistance * a ? near_ : far_;
    double sum = 0.0;
    for (std::size_t i = 0; i < rule.sin.size(); ++i) {
      const double r = a * rule.sin[i];
      for (std::size_t j = 0; j < rule.cos_angle.size(); ++j) {
        sum += rule.weight[i] * rule.angle_weight[j] * f(std::sqrt(rho * rho + r * r + 2.0 * rho * r * rule.cos_angle[j]));
      }
    }
    return sum;
  }

 private:
  struct Rule {
    std::vector<double> sin;           ///< r'/a at the radial nodes
    std::vector<double> weight;        ///< load share of each radial node (sum 1)
    std::vector<double> cos_angle;     ///< at the angular nodes on [0, pi]
    std::vector<double> angle_weight;  ///< sum 1
  };
  static Rule make_rule(int s, int radial, int angular);
  Rule near_;
  Rule far_;
};

}  // namespace punchsweep::model
