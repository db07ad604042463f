#include "model/shells/spot_average.hpp"

#include <numbers>

#include "model/numerics/gauss_rules.hpp"
#include "model/paper/pressure.hpp"

namespace punchsweep::model {

SpotAverage::SpotAverage(int s) {
  // n angles reach 1e-16 up to a/d = 1e-16^(1/(2n)).
  for (int angles = 16; angles <= kMaxAngles; angles = angles == 16 ? 48 : 2 * angles) {
    const double limit = angles == kMaxAngles ? 2.0 : std::pow(1e-16, 0.5 / angles);
    rules_.push_back(make_rule(s, kRadialNodes, angles, limit));
  }
}

const SpotAverage::Rule& SpotAverage::pick(double ratio) const {
  for (const Rule& rule : rules_) {
    if (ratio <= rule.ratio_limit) return rule;
  }
  return rules_.back();
}

SpotAverage::Rule SpotAverage::make_rule(int s, int radial, int angular, double ratio_limit) {
  constexpr double kPi = std::numbers::pi;
  Rule rule;
  rule.ratio_limit = ratio_limit;
  // Radial: r' = a sin(phi), phi in [0, pi/2], dA = r' dr' dtheta: the load at a node is
  // p(r') r' a cos(phi) dphi (a = 1 here; the shape scales out), normalized to sum 1.
  const GaussRule& g = gauss_legendre(radial);
  double total = 0.0;
  for (int i = 0; i < radial; ++i) {
    const double phi = 0.25 * kPi * (g.nodes[i] + 1.0);
    const double r = std::sin(phi);
    rule.sin.push_back(r);
    rule.weight.push_back(g.weights[i] * punch_pressure_shape(s, r, 1.0) * r * std::cos(phi));
    total += rule.weight.back();
  }
  for (double& w : rule.weight) w /= total;
  // Angle: the integrand is even and 2 pi-periodic in it, so the midpoint rule converges
  // geometrically, as (a/d)^(2 angular).
  for (int j = 0; j < angular; ++j) rule.cos_angle.push_back(std::cos(kPi * (j + 0.5) / angular));
  return rule;
}

}  // namespace punchsweep::model
