#pragma once

#include <string>
#include <vector>

#include "model/laws/exponential_series.hpp"

namespace punchsweep::model {

/// A generalized Maxwell solid given by its Prony series (docs/model.md, section 10):
///   E(t) = E_inf + sum_i E_i exp(-t / tau_i),
/// normalized by the instantaneous modulus E_0 = E_inf + sum_i E_i, so that E(0) = 1 (in
/// E0*) and J(0) = 1, with time in the unit of the tau_i. Its creep function follows by an
/// exact interconversion: a generalized Kelvin series
///   J(t) = 1 + sum_k J_k (1 - exp(-t / lambda_k)),   J(inf) = 1 + sum_k J_k = E_0 / E_inf,
/// whose -1/lambda_k are the N roots of s E^(s) = E_inf + sum_i E_i s / (s + 1/tau_i) = 0,
/// one between each pair of consecutive -1/tau_i and one between the slowest and 0
/// (retardation times interlace the relaxation times: tau_k < lambda_k < tau_(k+1)), and
/// J_k = -1 / (s_k f'(s_k)) the residues of J^(s) = 1 / (s^2 E^(s)). Each root is
/// bracketed and found by safeguarded Newton to the last bits: no numerical Laplace
/// inversion. Limited creep only (E_inf > 0).
class PronySeries final : public ExponentialSeriesLaw {
 public:
  /// Throws std::invalid_argument naming the bad value when E_inf <= 0, an E_i <= 0, a
  /// tau_i <= 0, the lists differ in length or are empty, the tau_i are not strictly
  /// increasing, or a value is not finite.
  PronySeries(double E_inf, std::vector<double> E, std::vector<double> tau);

  std::string describe() const override;
};

}  // namespace punchsweep::model
