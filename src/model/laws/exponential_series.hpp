#pragma once

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/laws/creep_law.hpp"

namespace punchsweep::model {

/// A law whose relaxation and creep functions are both sums of exponentials, normalized by
/// the instantaneous modulus (docs/model.md, section 10):
///   E(t) = E_inf + sum_i E_i exp(-t / tau_i),
///   J(t) = 1 + sum_k J_k (1 - exp(-t / lambda_k)) + phi t    (phi: a dashpot, E_0/eta),
/// held with both series; a derived law is given one and finds the other by its exact
/// interconversion (PronySeries from E, KelvinSeries from J). Everything a CreepLaw
/// evaluates is here, once, for both.
class ExponentialSeriesLaw : public CreepLaw {
 public:
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
  /// Every term of dE/dt is negligible after kForgetting of the longest tau.
  double relaxation_memory() const override { return kForgetting * tau_.back(); }
  /// The creep series; empty with a dashpot (J(inf) is not finite).
  std::optional<RetardationSeries> retardation_series() const override;
  /// The relaxation series (with a dashpot too: E(inf) = 0 then).
  std::optional<RelaxationSeries> relaxation_series() const override;

  /// The normalized moduli E_i / E_0 and E_inf / E_0, the relaxation and retardation times,
  /// the normalized compliances J_k E_0.
  const std::vector<double>& moduli() const { return E_; }
  double modulus_final() const { return E_inf_; }
  const std::vector<double>& relaxation_times() const { return tau_; }
  const std::vector<double>& retardation_times() const { return lambda_; }
  const std::vector<double>& compliances() const { return J_; }

 protected:
  ExponentialSeriesLaw() = default;

  /// Roots (relaxation or retardation rates) to two units in the last place.
  static constexpr double kRootTolerance = 2.0 * std::numeric_limits<double>::epsilon();

  /// "LAW: WHAT = VALUE is outside its range: RANGE".
  static std::string out_of_range(std::string_view law, const std::string& what, double value,
                                  const std::string& range);
  /// Throws std::invalid_argument unless `values` and `times` are equally many, at least
  /// one: "LAW: N KIND NAME_i and M times TIME_i; valid: ...".
  static void check_count(std::string_view law, std::string_view kind, std::string_view name,
                          const std::vector<double>& values, std::string_view time, const std::vector<double>& times);
  /// The times a series accepts, in its time unit: each within [kMinTime, kMaxTime], all
  /// within kMaxSpan of each other (the slowest over the fastest). Beyond these the
  /// interconversion's roots, 1/time apart, are no longer resolved in double precision
  /// (a subnormal time gives an infinite rate; times 1e-200 and 1e200 gave J(inf) = 2.5
  /// where it is 3), and no polymer's spectrum comes near them (a DMA master curve spans
  /// some 15-20 decades).
  static constexpr double kMinTime = 1e-30;
  static constexpr double kMaxTime = 1e30;
  static constexpr double kMaxSpan = 1e24;
  /// Throws std::invalid_argument naming the first term whose value is not finite and > 0,
  /// or whose time is not finite, within [kMinTime, kMaxTime] and above the one before it,
  /// or the times if they span more than kMaxSpan.
  static void check_terms(std::string_view law, std::string_view name, const std::vector<double>& values,
                          std::string_view time, const std::vector<double>& times);
  /// The interconversion's own invariants, checked before the law is used: every
  /// retardation and relaxation term finite and positive, E(0) = E_inf + sum E_i = 1 = J(0)
  /// and, for limited creep, J(inf) E_inf = 1, each to 1e-9. Throws std::invalid_argument
  /// saying which failed and by how much (a series the roots cannot resolve).
  void check_interconversion(std::string_view law) const;
  /// J(inf) = 1 + sum_k J_k as the series reaches it (so that J(t), J(inf) and the
  /// retardation series agree to the last bit), or infinity with a dashpot.
  void set_creep_final();

  double E_inf_ = 0.0;
  std::vector<double> E_, tau_;     ///< relaxation terms
  std::vector<double> J_, lambda_;  ///< retardation terms
  double phi_ = 0.0;                ///< dashpot fluidity E_0/eta; 0 without
  double J_sum_ = 0.0;              ///< 1 + sum_k J_k
  double J_final_ = 0.0;            ///< J_sum_, or infinity with a dashpot
};

}  // namespace punchsweep::model
