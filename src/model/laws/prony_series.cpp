#include "model/laws/prony_series.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "model/numerics/root_finding.hpp"

namespace punchsweep::model {

PronySeries::PronySeries(double E_inf, std::vector<double> E, std::vector<double> tau) {
  constexpr std::string_view kLaw = "Prony series";
  E_inf_ = E_inf;
  E_ = std::move(E);
  tau_ = std::move(tau);
  check_count(kLaw, "moduli", "E", E_, "tau", tau_);
  if (!(std::isfinite(E_inf_) && E_inf_ > 0.0)) throw std::invalid_argument(out_of_range(kLaw, "E_inf", E_inf_, "E_inf > 0"));
  check_terms(kLaw, "E", E_, "tau", tau_);
  double E0 = E_inf_;
  for (const double e : E_) E0 += e;
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
  set_creep_final();  // = E_0/E_inf to rounding
  check_interconversion(kLaw);
}

std::string PronySeries::describe() const {
  std::ostringstream out;
  out.precision(6);
  out << "Prony series, " << E_.size() << " term" << (E_.size() == 1 ? "" : "s") << ", E_inf/E_0 = " << E_inf_
      << ", tau from " << tau_.front() << " to " << tau_.back();
  return out.str();
}

}  // namespace punchsweep::model
