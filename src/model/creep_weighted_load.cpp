#include "model/creep_weighted_load.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "model/root_finding.hpp"

namespace punchsweep::model {

double CreepWeightedLoad::response(double t) const {
  if (shape_.is_step()) return creep_.creep(t);
  double g = shape_.jump() > 0.0 ? shape_.jump() * creep_.creep(t) : 0.0;
  for (const LoadShape::Segment& s : shape_.segments()) {
    if (!(t > s.t_a)) break;
    g += s.slope * creep_.creep_integral(t - std::min(t, s.t_b), std::min(t, s.t_b) - s.t_a);
  }
  return g;
}

double CreepWeightedLoad::response_rate(double t) const {
  if (shape_.is_step()) return creep_.creep_rate(t);
  double rate = shape_.jump() > 0.0 ? shape_.jump() * creep_.creep_rate(t) : 0.0;
  for (const LoadShape::Segment& s : shape_.segments()) {
    if (!(t > s.t_a)) break;
    // d/dt of int_{t_a}^{min(t, t_b)} J(t - tau) dtau: J(t - t_a), less J(t - t_b) once past t_b.
    rate += s.slope * (creep_.creep(t - s.t_a) - (t > s.t_b ? creep_.creep(t - s.t_b) : 0.0));
  }
  return rate;
}

double CreepWeightedLoad::settled_time() const {
  const std::optional<RetardationSeries> series = creep_.retardation_series();
  if (!series) return std::numeric_limits<double>::infinity();
  double longest = 0.0;
  for (const RetardationSeries::Term& term : series->terms) longest = std::max(longest, term.lambda);
  return shape_.rise_time() + kForgetting * longest;
}

double CreepWeightedLoad::time_at_response(double g) const {
  if (shape_.is_step()) return creep_.time_at_creep(g);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (g <= response_initial()) return 0.0;
  if (g >= response_final()) return kInf;
  // g rises monotonically: bracket by doubling from the end of the rise (or the creep time).
  double lo = 0.0;
  double hi = std::max(shape_.rise_time(), creep_.creep_time_scale());
  while (response(hi) < g) {
    lo = hi;
    hi *= 2.0;
    if (!std::isfinite(hi)) return kInf;
  }
  const auto residual = [&](double t, double* slope) {
    *slope = response_rate(t);
    return response(t) - g;
  };
  return newton_bisect_increasing(residual, lo, hi, 0.5 * (lo + hi), 0.0, 400,
                                  2.0 * std::numeric_limits<double>::epsilon())
      .x;
}

}  // namespace punchsweep::model
