#include "model/spot_average.hpp"

#include <numbers>

#include "model/gauss_rules.hpp"
#include "model/pressure.hpp"

namespace punchsweep::model {

SpotAverage::SpotAverage(int s) : near_(make_rule(s, 24, 48)), far_(make_rule(s, 24, 16)) {}

SpotAverage::Rule SpotAverage::make_rule(int s, int radial, int angular) {
  constexpr double kPi = std::numbers::pi;
  Rule rule;
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
  // geometrically, as (a/rho)^(2 angular).
  for (int j = 0; j < angular; ++j) {
    rule.cos_angle.push_back(std::cos(kPi * (j + 0.5) / angular));
    rule.angle_weight.push_back(1.0 / angular);
  }
  return rule;
}

}  // namespace punchsweep::model
