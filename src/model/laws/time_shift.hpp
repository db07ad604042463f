#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "model/laws/creep_law.hpp"

namespace punchsweep::model {

/// 0 degC in K.
inline constexpr double kZeroCelsius = 273.15;

/// Time-temperature superposition (docs/model.md, section 10): the law at temperature th is
/// the reference law with t -> t / a_T(th). Temperatures in degrees Celsius.
struct TemperatureShift {
  enum class Kind { wlf, arrhenius };
  Kind kind = Kind::wlf;
  double T_ref = 0.0;  ///< reference temperature, in degC
  double C1 = 0.0;     ///< WLF: log10 a_T = -C1 (th - T_ref) / (C2 + th - T_ref)
  double C2 = 0.0;     ///< WLF, in K (a temperature difference)
  double E_a = 0.0;    ///< Arrhenius: ln a_T = (E_a / R) (1/(th + 273.15) - 1/(T_ref + 273.15)), in J/mol
  /// WLF only, optional (0: none): below T_ref the shift is Arrhenius with this activation
  /// energy, in J/mol (WLF above the glass transition T_ref, Arrhenius below; a_T is
  /// continuous at T_ref).
  double E_a_below = 0.0;
  /// Optional: the temperatures the shift was fitted over, in degC; others are refused.
  double T_min = -kZeroCelsius;
  double T_max = std::numeric_limits<double>::infinity();

  /// Empty when the constants are admissible (finite; C1 > 0, C2 > 0; E_a > 0; E_a_below
  /// >= 0; T_ref above absolute zero; T_min < T_max), else a sentence naming the bad one
  /// and its range.
  std::string error() const;
  /// The largest shift admitted, |log10 a_T| <= kMaxDecades: a_T stays finite and the
  /// shifted times (ExponentialSeriesLaw's within 1e-30..1e30, a run's up to 1e12) stay far
  /// from overflow; no fitted shift means anything there (1e100 s). Where WLF diverges
  /// (toward T_ref - C2) this is reached at T_ref - C2 kMaxDecades / (C1 + kMaxDecades).
  static constexpr double kMaxDecades = 100.0;
  /// Whether temperature th (degC) is one the shift holds at: above absolute zero, within
  /// [T_min, T_max], and with |log10 a_T| <= kMaxDecades (for WLF, above the temperature
  /// where that is reached on the way to its divergence at T_ref - C2).
  bool admits(double th) const;
  /// The range admits() checks, as messages print it: "temperature > 61.06 (in degC; below
  /// 61.06 the shift a_T exceeds 1e100 on its way to WLF's divergence at T_ref - C2 = 53.4 ...)".
  std::string range() const;
  /// log10 a_T(th); th must be admitted.
  double log10_factor(double th) const;
  /// "WLF, C1 = 17.44, C2 = 51.6 K, T_ref = 105 degC".
  std::string describe() const;

 private:
  /// Whether the WLF form holds at th (kind wlf, and not below T_ref with E_a_below).
  bool wlf_at(double th) const;
};

/// Gas constant, in J/(mol K).
inline constexpr double kGasConstant = 8.314462618;

/// A law with its time axis scaled by a_T: J(t) = J_ref(t / a_T), E(t) = E_ref(t / a_T).
/// a_T > 1 makes it slower (colder than T_ref for WLF and Arrhenius).
class TimeShiftedLaw final : public CreepLaw {
 public:
  /// Throws std::invalid_argument unless a_T is finite and > 0.
  TimeShiftedLaw(std::unique_ptr<CreepLaw> reference, double a_T);

  double creep(double t) const override { return ref_->creep(t / a_); }
  double creep_rate(double t) const override { return ref_->creep_rate(t / a_) / a_; }
  double creep_integral(double u, double d) const override { return a_ * ref_->creep_integral(u / a_, d / a_); }
  double relaxation(double t) const override { return ref_->relaxation(t / a_); }
  double relaxation_rate(double t) const override { return ref_->relaxation_rate(t / a_) / a_; }
  double creep_initial() const override { return ref_->creep_initial(); }
  double creep_final() const override { return ref_->creep_final(); }
  double time_at_creep(double J) const override { return a_ * ref_->time_at_creep(J); }
  double relaxation_time_scale() const override { return a_ * ref_->relaxation_time_scale(); }
  double creep_time_scale() const override { return a_ * ref_->creep_time_scale(); }
  double relaxation_memory() const override { return a_ * ref_->relaxation_memory(); }
  bool singular_at_zero() const override { return ref_->singular_at_zero(); }
  std::optional<RetardationSeries> retardation_series() const override;
  std::optional<RelaxationSeries> relaxation_series() const override;
  std::string describe() const override;


 private:
  std::unique_ptr<CreepLaw> ref_;
  double a_;
};

}  // namespace punchsweep::model
