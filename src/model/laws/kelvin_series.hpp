#pragma once

#include <string>
#include <vector>

#include "model/laws/exponential_series.hpp"

namespace punchsweep::model {

/// A generalized Kelvin-Voigt solid given by its creep (retardation) series, optionally
/// with a dashpot in series (docs/model.md, section 10):
///   J(t) = 1/E_0 + sum_i J_i (1 - exp(-t / lambda_i)) + t / eta,
/// normalized by the instantaneous modulus E_0, so that J(0) = 1 (in 1/E0*), with time in
/// the unit of the lambda_i. The relaxation function follows by the exact interconversion
/// mirrored from PronySeries: with h(s) = s J^(s) = 1 + sum_i J_i / (1 + s lambda_i) + phi/s
/// (phi = E_0/eta, 0 without the dashpot), s E^(s) = 1/h(s), and h decreases between its
/// poles -1/lambda_i. So E(t) = E_inf + sum_k E_k exp(-t / tau_k) with -1/tau_k the roots
/// of h: one below -1/lambda_1, one between each pair of consecutive poles, and, with the
/// dashpot, one between -1/lambda_N and 0 (then E_inf = 0, else E_inf = 1/J(inf));
/// E_k = 1 / (s_k h'(s_k)) the residues. Each root bracketed and found by safeguarded Newton.
/// With the dashpot creep is unlimited (J(inf) = infinity): level 2 always touches.
class KelvinSeries final : public ExponentialSeriesLaw {
 public:
  /// J_i (in 1/E_0) and lambda_i; `fluidity` phi = E_0/eta (in 1/time unit), 0 for no
  /// dashpot. Throws std::invalid_argument naming the bad value when a J_i <= 0, a
  /// lambda_i <= 0, the lists differ in length or are empty, the lambda_i are not strictly
  /// increasing, phi < 0, or a value is not finite.
  KelvinSeries(std::vector<double> J, std::vector<double> lambda, double fluidity = 0.0);

  std::string describe() const override;
};

}  // namespace punchsweep::model
