#include "model/kelvin_series.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "model/root_finding.hpp"

namespace punchsweep::model {
namespace {

// Roots (relaxation rates, times on J) to two units in the last place.
constexpr double kRootTolerance = 2.0 * std::numeric_limits<double>::epsilon();

std::string bad(const std::string& what, double value, const std::string& range) {
  std::ostringstream out;
  out.precision(17);
  out << "Kelvin series: " << what << " = " << value << " is outside its range: " << range;
  return out.str();
}

// A term decayed by exp(-50) < 2e-22 is left out of E and E' (history integrals evaluate
// them at every age, and libm's exp is slowest where it underflows).
constexpr double kNegligibleDecay = 50.0;

}  // namespace

KelvinSeries::KelvinSeries(std::vector<double> J, std::vector<double> lambda, double fluidity)
    : J_(std::move(J)), lambda_(std::move(lambda)), phi_(fluidity) {
  if (J_.empty() || J_.size() != lambda_.size()) {
    throw std::invalid_argument("Kelvin series: " + std::to_string(J_.size()) + " compliances J_i and " +
                                std::to_string(lambda_.size()) +
                                " times lambda_i; valid: the same number, at least one");
  }
  if (!(std::isfinite(phi_) && phi_ >= 0.0)) {
    throw std::invalid_argument(bad("E_0/eta", phi_, "E_0/eta >= 0 (0: no dashpot)"));
  }
  double J_final = 1.0;
  for (std::size_t i = 0; i < J_.size(); ++i) {
    if (!(std::isfinite(J_[i]) && J_[i] > 0.0)) {
      throw std::invalid_argument(bad("J_" + std::to_string(i + 1), J_[i], "J_i > 0"));
    }
    if (!(std::isfinite(lambda_[i]) && lambda_[i] > 0.0)) {
      throw std::invalid_argument(bad("lambda_" + std::to_string(i + 1), lambda_[i], "lambda_i > 0"));
    }
    if (i > 0 && !(lambda_[i] > lambda_[i - 1])) {
      throw std::invalid_argument(bad("lambda_" + std::to_string(i + 1), lambda_[i],
                                      "strictly increasing lambda_i (a repeated time is one term)"));
    }
    J_final += J_[i];
  }
  J_final_ = phi_ > 0.0 ? std::numeric_limits<double>::infinity() : J_final;
  E_inf_ = phi_ > 0.0 ? 0.0 : 1.0 / J_final;

  // g(s) = -h(s) = -(1 + sum J_i / (1 + s lambda_i) + phi/s), increasing between its poles.
  const auto g = [&](double s, double* dg) {
    double value = -1.0 - (phi_ > 0.0 ? phi_ / s : 0.0);
    double slope = phi_ > 0.0 ? phi_ / (s * s) : 0.0;
    for (std::size_t i = 0; i < J_.size(); ++i) {
      const double d = 1.0 + s * lambda_[i];
      value -= J_[i] / d;
      slope += J_[i] * lambda_[i] / (d * d);
    }
    *dg = slope;
    return value;
  };
  const auto add_root = [&](double lo, double hi) {
    const double s = newton_bisect_increasing(g, lo, hi, 0.5 * (lo + hi), 0.0, 400, kRootTolerance).x;
    double dg = 0.0;
    g(s, &dg);
    tau_.push_back(-1.0 / s);
    E_.push_back(-1.0 / (s * dg));  // residue of 1/(s h(s)) at s_k: 1/(s_k h'(s_k)), h' = -g'
  };
  // Below the fastest pole: g rises from -1 (at -infinity) to +infinity; bracket by doubling.
  const std::size_t n = J_.size();
  double lo = -2.0 / lambda_[0];
  double dg = 0.0;
  while (g(lo, &dg) > 0.0) lo *= 2.0;
  add_root(lo, -1.0 / lambda_[0]);
  for (std::size_t k = 0; k + 1 < n; ++k) add_root(-1.0 / lambda_[k], -1.0 / lambda_[k + 1]);
  if (phi_ > 0.0) add_root(-1.0 / lambda_[n - 1], 0.0);
  // Found from the most negative s up: tau_k increase, fastest first.
}

double KelvinSeries::creep(double t) const {
  double crept = phi_ * t;
  for (std::size_t k = 0; k < J_.size(); ++k) crept += J_[k] * -std::expm1(-t / lambda_[k]);
  return 1.0 + crept;
}

double KelvinSeries::creep_rate(double t) const {
  double rate = phi_;
  for (std::size_t k = 0; k < J_.size(); ++k) rate += J_[k] / lambda_[k] * std::exp(-t / lambda_[k]);
  return rate;
}

double KelvinSeries::creep_integral(double u, double d) const {
  double sum = d + phi_ * d * (u + 0.5 * d);
  for (std::size_t k = 0; k < J_.size(); ++k) {
    sum += J_[k] * (d + lambda_[k] * std::exp(-u / lambda_[k]) * std::expm1(-d / lambda_[k]));
  }
  return sum;
}

double KelvinSeries::relaxation(double t) const {
  double e = E_inf_;
  for (std::size_t i = 0; i < E_.size(); ++i) {
    const double x = t / tau_[i];
    if (x < kNegligibleDecay) e += E_[i] * std::exp(-x);
  }
  return e;
}

double KelvinSeries::relaxation_rate(double t) const {
  double rate = 0.0;
  for (std::size_t i = 0; i < E_.size(); ++i) {
    const double x = t / tau_[i];
    if (x < kNegligibleDecay) rate -= E_[i] / tau_[i] * std::exp(-x);
  }
  return rate;
}

double KelvinSeries::time_at_creep(double J) const {
  if (J <= 1.0) return 0.0;
  if (J >= J_final_) return std::numeric_limits<double>::infinity();
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

std::optional<RetardationSeries> KelvinSeries::retardation_series() const {
  if (phi_ > 0.0) return std::nullopt;
  RetardationSeries series{J_final_, {}};
  for (std::size_t k = 0; k < J_.size(); ++k) series.terms.push_back({J_[k], lambda_[k]});
  return series;
}

std::string KelvinSeries::describe() const {
  std::ostringstream out;
  out.precision(6);
  out << "Kelvin series, " << J_.size() << " term" << (J_.size() == 1 ? "" : "s") << ", lambda from "
      << lambda_.front() << " to " << lambda_.back();
  if (phi_ > 0.0) out << ", dashpot E_0/eta = " << phi_;
  return out.str();
}

}  // namespace punchsweep::model
