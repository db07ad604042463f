#include "model/prony_series.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "model/root_finding.hpp"

namespace punchsweep::model {
namespace {

// Roots (retardation rates, times on J) to two units in the last place.
constexpr double kRootTolerance = 2.0 * std::numeric_limits<double>::epsilon();

std::string bad(const std::string& what, double value, const std::string& range) {
  std::ostringstream out;
  out.precision(17);
  out << "Prony series: " << what << " = " << value << " is outside its range: " << range;
  return out.str();
}

// A term decayed by exp(-50) < 2e-22 is left out of E and E' (history integrals evaluate
// them at every age, and libm's exp is slowest where it underflows).
constexpr double kNegligibleDecay = 50.0;

}  // namespace

PronySeries::PronySeries(double E_inf, std::vector<double> E, std::vector<double> tau)
    : E_inf_(E_inf), E_(std::move(E)), tau_(std::move(tau)) {
  if (E_.empty() || E_.size() != tau_.size()) {
    throw std::invalid_argument("Prony series: " + std::to_string(E_.size()) + " moduli E_i and " +
                                std::to_string(tau_.size()) + " times tau_i; valid: the same number, at least one");
  }
  if (!(std::isfinite(E_inf_) && E_inf_ > 0.0)) throw std::invalid_argument(bad("E_inf", E_inf_, "E_inf > 0"));
  double E0 = E_inf_;
  for (std::size_t i = 0; i < E_.size(); ++i) {
    if (!(std::isfinite(E_[i]) && E_[i] > 0.0)) {
      throw std::invalid_argument(bad("E_" + std::to_string(i + 1), E_[i], "E_i > 0"));
    }
    if (!(std::isfinite(tau_[i]) && tau_[i] > 0.0)) {
      throw std::invalid_argument(bad("tau_" + std::to_string(i + 1), tau_[i], "tau_i > 0"));
    }
    if (i > 0 && !(tau_[i] > tau_[i - 1])) {
      throw std::invalid_argument(bad("tau_" + std::to_string(i + 1), tau_[i],
                                      "strictly increasing tau_i (a repeated time is one term)"));
    }
    E0 += E_[i];
  }
  E_inf_ /= E0;  // normalized: E(0) = 1
  for (double& e : E_) e /= E0;

  // f(s) = E_inf + sum E_i s tau_i / (s tau_i + 1), increasing between its poles -1/tau_i.
  const auto f = [&](double s, double* df) {
    double value = E_inf_;
    double slope = 0.0;
    for (std::size_t i = 0; i < E_.size(); ++i) {
      const double d = s * tau_[i] + 1.0;
      value += E_[i] * s * tau_[i] / d;
      slope += E_[i] * tau_[i] / (d * d);
    }
    *df = slope;
    return value;
  };
  const std::size_t n = E_.size();
  for (std::size_t k = 0; k < n; ++k) {
    // The root in (-1/tau_k, -1/tau_(k+1)), or (-1/tau_n, 0) for the last.
    const double lo = -1.0 / tau_[k];
    const double hi = k + 1 < n ? -1.0 / tau_[k + 1] : 0.0;
    const double s = newton_bisect_increasing(f, lo, hi, 0.5 * (lo + hi), 0.0, 400, kRootTolerance).x;
    double df = 0.0;
    f(s, &df);
    lambda_.push_back(-1.0 / s);
    J_.push_back(-1.0 / (s * df));  // the residue of 1/(s f(s)) at s_k is -J_k
  }
  // J(inf) as the series reaches it (= E_0/E_inf to rounding), so that J(t), J(inf) and the
  // retardation series agree to the last bit.
  J_final_ = 1.0;
  for (const double j : J_) J_final_ += j;
}

double PronySeries::relaxation(double t) const {
  double e = E_inf_;
  for (std::size_t i = 0; i < E_.size(); ++i) {
    const double x = t / tau_[i];
    if (x < kNegligibleDecay) e += E_[i] * std::exp(-x);
  }
  return e;
}

double PronySeries::relaxation_rate(double t) const {
  double rate = 0.0;
  for (std::size_t i = 0; i < E_.size(); ++i) {
    const double x = t / tau_[i];
    if (x < kNegligibleDecay) rate -= E_[i] / tau_[i] * std::exp(-x);
  }
  return rate;
}

double PronySeries::creep(double t) const {
  // J(0) + sum J_k (1 - e^(-t/lambda_k)): exact at t = 0, no cancellation at small t.
  double crept = 0.0;
  for (std::size_t k = 0; k < J_.size(); ++k) crept += J_[k] * -std::expm1(-t / lambda_[k]);
  return 1.0 + crept;
}

double PronySeries::creep_rate(double t) const {
  double rate = 0.0;
  for (std::size_t k = 0; k < J_.size(); ++k) rate += J_[k] / lambda_[k] * std::exp(-t / lambda_[k]);
  return rate;
}

double PronySeries::creep_integral(double u, double d) const {
  // J(inf) d - sum J_k lambda_k (e^(-u/lambda_k) - e^(-(u+d)/lambda_k)).
  double sum = J_final_ * d;
  for (std::size_t k = 0; k < J_.size(); ++k) {
    sum += J_[k] * lambda_[k] * std::exp(-u / lambda_[k]) * std::expm1(-d / lambda_[k]);
  }
  return sum;
}

double PronySeries::time_at_creep(double J) const {
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

std::optional<RetardationSeries> PronySeries::retardation_series() const {
  RetardationSeries series{J_final_, {}};
  for (std::size_t k = 0; k < J_.size(); ++k) series.terms.push_back({J_[k], lambda_[k]});
  return series;
}

std::string PronySeries::describe() const {
  std::ostringstream out;
  out.precision(6);
  out << "Prony series, " << E_.size() << " term" << (E_.size() == 1 ? "" : "s") << ", E_inf/E_0 = " << E_inf_
      << ", tau from " << tau_.front() << " to " << tau_.back();
  return out.str();
}

}  // namespace punchsweep::model
