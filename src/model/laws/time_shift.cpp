#include "model/laws/time_shift.hpp"

#include <cmath>
#include <stdexcept>

#include "model/numerics/number_text.hpp"

namespace punchsweep::model {
std::string TemperatureShift::error() const {
  const auto bad = [](const char* name, double v, const std::string& range) {
    return std::string("shift ") + name + " = " + number_text(v, 10) + " is outside its range: " + range;
  };
  if (!(std::isfinite(T_ref) && T_ref > -kZeroCelsius)) return bad("T_ref", T_ref, "T_ref > -273.15 (in degC)");
  if (kind == Kind::wlf) {
    if (!(std::isfinite(C1) && C1 > 0.0)) return bad("C1", C1, "C1 > 0");
    if (!(std::isfinite(C2) && C2 > 0.0)) return bad("C2", C2, "C2 > 0 (in K)");
    if (!(std::isfinite(E_a_below) && E_a_below >= 0.0)) {
      return bad("E_a_below", E_a_below, "E_a_below > 0 (in J/mol; leave it out for WLF on both sides of T_ref)");
    }
  } else if (!(std::isfinite(E_a) && E_a > 0.0)) {
    return bad("E_a", E_a, "E_a > 0 (in J/mol)");
  }
  if (!(T_min >= -kZeroCelsius && T_min < T_max)) {
    return bad("T_min", T_min, "-273.15 <= T_min < T_max = " + number_text(T_max, 10) + " (in degC)");
  }
  return {};
}

bool TemperatureShift::admits(double th) const {
  if (!(std::isfinite(th) && th > -kZeroCelsius && th >= T_min && th <= T_max)) return false;
  if (wlf_at(th) && !(C2 + th - T_ref > 0.0)) return false;
  return std::abs(log10_factor(th)) <= kMaxDecades;
}

std::string TemperatureShift::range() const {
  const bool diverges = kind == Kind::wlf && !(E_a_below > 0.0);  // WLF below T_ref too
  const bool limited = T_min > -kZeroCelsius || std::isfinite(T_max);
  // Where WLF's a_T reaches 10^kMaxDecades on its way to the divergence at T_ref - C2.
  const double lowest = T_ref - C2 * kMaxDecades / (C1 + kMaxDecades);
  std::string r = "temperature";
  if (T_min > -kZeroCelsius && !(diverges && T_min <= lowest)) {
    r += " >= " + number_text(T_min, 10);
  } else {
    r += " > " + (diverges ? number_text(lowest, 10) : std::string("-273.15"));
  }
  if (std::isfinite(T_max)) r += " and <= " + number_text(T_max, 10);
  r += " (in degC";
  if (diverges) {
    r += "; below " + number_text(lowest, 10) + " the shift a_T exceeds 1e" + number_text(kMaxDecades, 3) +
         " on its way to WLF's divergence at T_ref - C2 = " + number_text(T_ref - C2, 10);
  }
  if (limited) r += "; T_min, T_max: the range the shift was fitted over";
  r += "; and where |log10 a_T| <= " + number_text(kMaxDecades, 3);
  return r + ")";
}

bool TemperatureShift::wlf_at(double th) const { return kind == Kind::wlf && !(E_a_below > 0.0 && th < T_ref); }

double TemperatureShift::log10_factor(double th) const {
  const double d = th - T_ref;
  if (wlf_at(th)) return -C1 * d / (C2 + d);
  const double energy = kind == Kind::wlf ? E_a_below : E_a;
  return energy / kGasConstant * (1.0 / (th + kZeroCelsius) - 1.0 / (T_ref + kZeroCelsius)) / std::log(10.0);
}

std::string TemperatureShift::describe() const {
  std::string d;
  if (kind == Kind::wlf) {
    d = "WLF, C1 = " + number_text(C1, 10) + ", C2 = " + number_text(C2, 10) + " K, T_ref = " + number_text(T_ref, 10) +
        " degC";
    if (E_a_below > 0.0) d += ", Arrhenius below T_ref with E_a = " + number_text(E_a_below, 10) + " J/mol";
  } else {
    d = "Arrhenius, E_a = " + number_text(E_a, 10) + " J/mol, T_ref = " + number_text(T_ref, 10) + " degC";
  }
  if (T_min > -kZeroCelsius || std::isfinite(T_max)) {
    d += ", fitted from " + number_text(T_min, 10) + " to " + number_text(T_max, 10) + " degC";
  }
  return d;
}

TimeShiftedLaw::TimeShiftedLaw(std::unique_ptr<CreepLaw> reference, double a_T) : ref_(std::move(reference)), a_(a_T) {
  if (!(std::isfinite(a_) && a_ > 0.0)) {
    throw std::invalid_argument("time-temperature shift factor a_T = " + number_text(a_, 10) +
                                " is outside its range: a finite a_T > 0 (the temperature is too far from T_ref)");
  }
}

std::optional<RetardationSeries> TimeShiftedLaw::retardation_series() const {
  std::optional<RetardationSeries> series = ref_->retardation_series();
  if (series) {
    for (RetardationSeries::Term& term : series->terms) term.lambda *= a_;
  }
  return series;
}

std::optional<RelaxationSeries> TimeShiftedLaw::relaxation_series() const {
  std::optional<RelaxationSeries> series = ref_->relaxation_series();
  if (series) {
    for (RelaxationSeries::Term& term : series->terms) term.tau *= a_;
  }
  return series;
}

std::string TimeShiftedLaw::describe() const {
  return ref_->describe() + ", times shifted by a_T = " + number_text(a_, 10);
}

}  // namespace punchsweep::model
