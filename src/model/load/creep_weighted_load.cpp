#include "model/load/creep_weighted_load.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "model/numerics/root_finding.hpp"

namespace punchsweep::model {

CreepWeightedLoad::CreepWeightedLoad(const CreepLaw& creep, double pbar0, const LoadShape& shape)
    : creep_(creep), pbar0_(pbar0), shape_(shape) {
  if (shape_.is_step() || shape_.segments().size() <= kDirectPieces) return;
  std::optional<RetardationSeries> series = creep_.retardation_series();
  if (!series) return;  // unlimited creep, a power law: the direct sums
  auto completed = std::make_shared<CompletedPieces>();
  const std::vector<LoadShape::Segment>& pieces = shape_.segments();
  const std::size_t terms = series->terms.size();
  completed->S.assign(pieces.size() * terms, 0.0);
  double load = 0.0;
  for (std::size_t n = 0; n < pieces.size(); ++n) {
    const LoadShape::Segment& p = pieces[n];
    load += p.slope * (p.t_b - p.t_a);
    completed->ends.push_back(p.t_b);
    completed->load.push_back(load);
    for (std::size_t k = 0; k < terms; ++k) {
      const double lambda = series->terms[k].lambda;
      const double before = n == 0 ? 0.0 : std::exp(-(p.t_b - pieces[n - 1].t_b) / lambda) * completed->S[(n - 1) * terms + k];
      completed->S[n * terms + k] = before - p.slope * std::expm1(-(p.t_b - p.t_a) / lambda);
    }
  }
  completed->series = std::move(*series);
  completed_ = std::move(completed);
}

std::size_t CreepWeightedLoad::add_completed(double t, double* g, double* rate) const {
  if (!completed_) return 0;
  const auto pieces = static_cast<std::size_t>(
      std::upper_bound(completed_->ends.begin(), completed_->ends.end(), t) - completed_->ends.begin());
  if (pieces == 0) return 0;
  const std::size_t n = pieces - 1;
  const std::vector<RetardationSeries::Term>& terms = completed_->series.terms;
  const double age = t - completed_->ends[n];
  if (g != nullptr) *g += completed_->series.J_final * completed_->load[n];
  for (std::size_t k = 0; k < terms.size(); ++k) {
    const double decay = std::exp(-age / terms[k].lambda);
    const double S = completed_->S[n * terms.size() + k];
    if (g != nullptr) *g -= terms[k].J * terms[k].lambda * decay * S;
    if (rate != nullptr) *rate += terms[k].J * decay * S;
  }
  return pieces;
}

double CreepWeightedLoad::response(double t) const {
  if (shape_.is_step()) return creep_.creep(t);
  double g = shape_.jump() > 0.0 ? shape_.jump() * creep_.creep(t) : 0.0;
  const std::vector<LoadShape::Segment>& pieces = shape_.segments();
  for (std::size_t i = add_completed(t, &g, nullptr); i < pieces.size(); ++i) {
    const LoadShape::Segment& s = pieces[i];
    if (!(t > s.t_a)) break;
    g += s.slope * creep_.creep_integral(t - std::min(t, s.t_b), std::min(t, s.t_b) - s.t_a);
  }
  return g;
}

double CreepWeightedLoad::response_rate(double t) const {
  if (shape_.is_step()) return creep_.creep_rate(t);
  double rate = shape_.jump() > 0.0 ? shape_.jump() * creep_.creep_rate(t) : 0.0;
  const std::vector<LoadShape::Segment>& pieces = shape_.segments();
  for (std::size_t i = add_completed(t, nullptr, &rate); i < pieces.size(); ++i) {
    const LoadShape::Segment& s = pieces[i];
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
