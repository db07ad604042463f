#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/creep_law.hpp"

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
class KelvinSeries final : public CreepLaw {
 public:
  /// J_i (in 1/E_0) and lambda_i; `fluidity` phi = E_0/eta (in 1/time unit), 0 for no
  /// dashpot. Throws std::invalid_argument naming the bad value when a J_i <= 0, a
  /// lambda_i <= 0, the lists differ in length or are empty, the lambda_i are not strictly
  /// increasing, phi < 0, or a value is not finite.
  KelvinSeries(std::vector<double> J, std::vector<double> lambda, double fluidity = 0.0);

  double creep(double t) const override;
  double creep_rate(double t) const override;
  double creep_integral(double u, double d) const override;
  double relaxation(double t) const override;
  double relaxation_rate(double t) const override;
  double creep_initial() const override { return 1.0; }
  double creep_final() const override { return J_final_; }
  double time_at_creep(double J) const override;
  double relaxation_time_scale() const override { return tau_.front(); }
  double creep_time_scale() const override { return lambda_.front(); }
  /// exp(-40) < 1e-17: every term of dE/dt is negligible after 40 of the longest tau.
  double relaxation_memory() const override { return 40.0 * tau_.back(); }
  /// The series itself; empty with the dashpot (J(inf) is not finite).
  std::optional<RetardationSeries> retardation_series() const override;
  std::string describe() const override;

  const std::vector<double>& relaxation_times() const { return tau_; }
  const std::vector<double>& moduli() const { return E_; }
  double modulus_final() const { return E_inf_; }

 private:
  std::vector<double> J_, lambda_;
  double phi_;
  double J_final_;  ///< 1 + sum J_i, or infinity with the dashpot
  double E_inf_ = 0.0;
  std::vector<double> E_, tau_;
};

}  // namespace punchsweep::model
