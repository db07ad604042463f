#include "model/laws/kelvin_series.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "model/numerics/root_finding.hpp"

namespace punchsweep::model {

KelvinSeries::KelvinSeries(std::vector<double> J, std::vector<double> lambda, double fluidity) {
  constexpr std::string_view kLaw = "Kelvin series";
  J_ = std::move(J);
  lambda_ = std::move(lambda);
  phi_ = fluidity;
  check_count(kLaw, "compliances", "J", J_, "lambda", lambda_);
  if (!(std::isfinite(phi_) && phi_ >= 0.0)) {
    throw std::invalid_argument(out_of_range(kLaw, "E_0/eta", phi_, "E_0/eta >= 0 (0: no dashpot)"));
  }
  check_terms(kLaw, "J", J_, "lambda", lambda_);
  set_creep_final();
  E_inf_ = phi_ > 0.0 ? 0.0 : 1.0 / J_sum_;

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
  check_interconversion(kLaw);
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
