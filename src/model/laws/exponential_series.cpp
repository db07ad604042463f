#include "model/laws/exponential_series.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "model/numerics/number_text.hpp"
#include "model/numerics/root_finding.hpp"

namespace punchsweep::model {

std::string ExponentialSeriesLaw::out_of_range(std::string_view law, const std::string& what, double value,
                                               const std::string& range) {
  std::ostringstream out;
  out.precision(17);
  out << law << ": " << what << " = " << value << " is outside its range: " << range;
  return out.str();
}

void ExponentialSeriesLaw::check_count(std::string_view law, std::string_view kind, std::string_view name,
                                       const std::vector<double>& values, std::string_view time,
                                       const std::vector<double>& times) {
  if (values.empty() || values.size() != times.size()) {
    throw std::invalid_argument(std::string(law) + ": " + std::to_string(values.size()) + " " + std::string(kind) +
                                " " + std::string(name) + "_i and " + std::to_string(times.size()) + " times " +
                                std::string(time) + "_i; valid: the same number, at least one");
  }
}

void ExponentialSeriesLaw::check_terms(std::string_view law, std::string_view name, const std::vector<double>& values,
                                       std::string_view time, const std::vector<double>& times) {
  const std::string v(name);
  const std::string t(time);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string index = std::to_string(i + 1);
    if (!(std::isfinite(values[i]) && values[i] > 0.0)) {
      throw std::invalid_argument(out_of_range(law, v + "_" + index, values[i], v + "_i > 0"));
    }
    if (!(std::isfinite(times[i]) && times[i] >= kMinTime && times[i] <= kMaxTime)) {
      throw std::invalid_argument(out_of_range(law, t + "_" + index, times[i],
                                               number_text(kMinTime, 6) + " <= " + t + "_i <= " + number_text(kMaxTime, 6) +
                                                   " in the time unit"));
    }
    if (i > 0 && !(times[i] > times[i - 1])) {
      throw std::invalid_argument(out_of_range(law, t + "_" + index, times[i],
                                               "strictly increasing " + t + "_i (a repeated time is one term)"));
    }
  }
  if (!times.empty() && !(times.back() <= kMaxSpan * times.front())) {
    throw std::invalid_argument(std::string(law) + ": " + t + "_i from " + number_text(times.front(), 6) + " to " +
                                number_text(times.back(), 6) + " span more than " + number_text(kMaxSpan, 6) +
                                " (the slowest over the fastest), which the interconversion cannot resolve");
  }
}

void ExponentialSeriesLaw::check_interconversion(std::string_view law) const {
  constexpr double kTolerance = 1e-9;
  const auto fail = [&](const std::string& what) {
    throw std::invalid_argument(std::string(law) + ": the interconversion between its creep and relaxation series " +
                                "failed (" + what + "); the times span too many decades to be resolved");
  };
  for (std::size_t k = 0; k < J_.size(); ++k) {
    if (!(std::isfinite(J_[k]) && J_[k] > 0.0 && std::isfinite(lambda_[k]) && lambda_[k] > 0.0)) {
      fail("retardation term " + std::to_string(k + 1) + ": J = " + number_text(J_[k], 6) + ", lambda = " +
           number_text(lambda_[k], 6));
    }
  }
  double E0 = E_inf_;
  for (std::size_t i = 0; i < E_.size(); ++i) {
    if (!(std::isfinite(E_[i]) && E_[i] > 0.0 && std::isfinite(tau_[i]) && tau_[i] > 0.0)) {
      fail("relaxation term " + std::to_string(i + 1) + ": E = " + number_text(E_[i], 6) + ", tau = " + number_text(tau_[i], 6));
    }
    E0 += E_[i];
  }
  if (!(std::abs(E0 - 1.0) <= kTolerance)) fail("J(0) E(0) = " + number_text(E0, 12) + ", not 1");
  if (phi_ == 0.0 && !(std::abs(J_sum_ * E_inf_ - 1.0) <= kTolerance)) {
    fail("J(inf) E_inf = " + number_text(J_sum_ * E_inf_, 12) + ", not 1");
  }
}

void ExponentialSeriesLaw::set_creep_final() {
  J_sum_ = 1.0;
  for (const double j : J_) J_sum_ += j;
  J_final_ = phi_ > 0.0 ? std::numeric_limits<double>::infinity() : J_sum_;
}

double ExponentialSeriesLaw::creep(double t) const {
  // J(0) + sum J_k (1 - e^(-t/lambda_k)): exact at t = 0, no cancellation at small t. A
  // term past kForgetting is J_k exactly (-expm1(-x) rounds to 1 from x = 37.43 on).
  double crept = phi_ > 0.0 ? phi_ * t : 0.0;
  for (std::size_t k = 0; k < J_.size(); ++k) {
    const double x = t / lambda_[k];
    crept += x < kForgetting ? J_[k] * -std::expm1(-x) : J_[k];
  }
  return 1.0 + crept;
}

double ExponentialSeriesLaw::creep_rate(double t) const {
  double rate = phi_;
  for (std::size_t k = 0; k < J_.size(); ++k) rate += J_[k] / lambda_[k] * std::exp(-t / lambda_[k]);
  return rate;
}

double ExponentialSeriesLaw::creep_integral(double u, double d) const {
  // (1 + sum J_k) d + phi d (u + d/2) - sum J_k lambda_k (e^(-u/lambda_k) - e^(-(u+d)/lambda_k)).
  double sum = J_sum_ * d;
  if (phi_ > 0.0) sum += phi_ * d * (u + 0.5 * d);
  for (std::size_t k = 0; k < J_.size(); ++k) {
    sum += J_[k] * lambda_[k] * std::exp(-u / lambda_[k]) * std::expm1(-d / lambda_[k]);
  }
  return sum;
}

double ExponentialSeriesLaw::relaxation(double t) const {
  double e = E_inf_;
  for (std::size_t i = 0; i < E_.size(); ++i) {
    const double x = t / tau_[i];
    if (x < kNegligibleDecay) e += E_[i] * std::exp(-x);
  }
  return e;
}

double ExponentialSeriesLaw::relaxation_rate(double t) const {
  double rate = 0.0;
  for (std::size_t i = 0; i < E_.size(); ++i) {
    const double x = t / tau_[i];
    if (x < kNegligibleDecay) rate -= E_[i] / tau_[i] * std::exp(-x);
  }
  return rate;
}

double ExponentialSeriesLaw::time_at_creep(double J) const {
  if (J <= 1.0) return 0.0;
  if (J >= J_final_) return std::numeric_limits<double>::infinity();
  // J(t) rises monotonically; bracket by doubling from the shortest retardation time.
  double lo = 0.0;
  double hi = lambda_.front();
  while (creep(hi) < J) {
    lo = hi;
    hi *= 2.0;
    if (!std::isfinite(hi)) return std::numeric_limits<double>::infinity();
  }
  const auto residual = [&](double t, double* slope) {
    *slope = creep_rate(t);
    return creep(t) - J;
  };
  return newton_bisect_increasing(residual, lo, hi, 0.5 * (lo + hi), 0.0, 400, kRootTolerance).x;
}

std::optional<RetardationSeries> ExponentialSeriesLaw::retardation_series() const {
  if (phi_ > 0.0) return std::nullopt;
  RetardationSeries series{J_final_, {}};
  for (std::size_t k = 0; k < J_.size(); ++k) series.terms.push_back({J_[k], lambda_[k]});
  return series;
}

std::optional<RelaxationSeries> ExponentialSeriesLaw::relaxation_series() const {
  RelaxationSeries series{E_inf_, {}};
  for (std::size_t i = 0; i < E_.size(); ++i) series.terms.push_back({E_[i], tau_[i]});
  return series;
}

}  // namespace punchsweep::model
