#pragma once

#include <array>
#include <cmath>
#include <vector>

namespace punchsweep::model {

/// The m = 0 average, about a punch, of a neighbour's spot (docs/model.md, section 11): for
/// a neighbour whose contact of radius a carries the isolated punch's pressure p_(k,m)
/// (eq 9.1, exponent s), centred at distance rho,
///   <f> = (1/P) int f(|x'|) p(x' - rho e) dA',
/// the mean of f over the distances of the spot's points, weighted by their load: Gauss-
/// Legendre nodes in phi (r' = a sin(phi)) by midpoint angles on [0, pi]. The integrand is
/// even and periodic in the angle, so n angles converge as (a/d)^(2n), d the distance from
/// the spot's centre to the nearest singularity of f; the kernels of the localization are
/// singular on the punch's own contact circle, |x'| = reach, so d = rho - reach. The rule
/// takes the fewest angles (16, 48, then doubling up to kMaxAngles) with (a/d)^(2n) <=
/// 1e-16, and kRadialNodes radial nodes in every rule, so that the rule's radial error (1e-8
/// for the cone's log-singular pressure, s = 1) is a smooth function of the geometry.
/// It agrees with a 2000 x 20000 midpoint sum to 1e-8 up to a gap of a hundredth of the
/// spot's radius (`single_level_shells_test.cpp`).
class SpotAverage {
 public:
  explicit SpotAverage(int s);

  static constexpr int kMaxAngles = 6144;
  static constexpr int kRadialNodes = 48;

  template <class F>
  double operator()(F&& f, double rho, double a, double reach = 0.0) const {
    return both([&f](double d) { return std::array<double, 1>{f(d)}; }, rho, a, reach)[0];
  }

  /// The averages of several kernels at once: f(d) returns std::array<double, N>, one value
  /// per kernel (the distances, and whatever the kernels share, computed once). Each
  /// average is the same sum, in the same order, as operator() of that kernel alone.
  template <class F>
  auto both(F&& f, double rho, double a, double reach = 0.0) const {
    using Values = decltype(f(1.0));
    const Rule& rule = pick(a / (rho - reach));
    Values sum{};
    for (std::size_t i = 0; i < rule.sin.size(); ++i) {
      const double r = a * rule.sin[i];
      Values ring{};
      for (std::size_t j = 0; j < rule.cos_angle.size(); ++j) {
        const Values v = f(std::sqrt(rho * rho + r * r + 2.0 * rho * r * rule.cos_angle[j]));
        for (std::size_t k = 0; k < v.size(); ++k) ring[k] += v[k];
      }
      for (std::size_t k = 0; k < ring.size(); ++k) sum[k] += rule.weight[i] * ring[k];
    }
    for (double& value : sum) value /= static_cast<double>(rule.cos_angle.size());
    return sum;
  }

 private:
  struct Rule {
    double ratio_limit = 0.0;          ///< a/d up to which the rule is used
    std::vector<double> sin;           ///< r'/a at the radial nodes
    std::vector<double> weight;        ///< load share of each radial node (sum 1)
    std::vector<double> cos_angle;     ///< at the angular nodes on [0, pi], equal weights
  };
  static Rule make_rule(int s, int radial, int angular, double ratio_limit);
  const Rule& pick(double ratio) const;
  std::vector<Rule> rules_;  ///< by ratio_limit, increasing
};

}  // namespace punchsweep::model
