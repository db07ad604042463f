#include "model/time_shift.hpp"

#include <cmath>
#include <stdexcept>

#include "model/number_text.hpp"

namespace punchsweep::model {
std::string TemperatureShift::error() const {
  const auto bad = [](const char* name, double v, const char* range) {
    return std::string("shift ") + name + " = " + number_text(v, 10) + " is outside its range: " + range;
  };
  if (!(std::isfinite(T_ref) && T_ref > -kZeroCelsius)) return bad("T_ref", T_ref, "T_ref > -273.15 (in degC)");
  if (kind == Kind::wlf) {
    if (!(std::isfinite(C1) && C1 > 0.0)) return bad("C1", C1, "C1 > 0");
    if (!(std::isfinite(C2) && C2 > 0.0)) return bad("C2", C2, "C2 > 0 (in K)");
  } else if (!(std::isfinite(E_a) && E_a > 0.0)) {
    return bad("E_a", E_a, "E_a > 0 (in J/mol)");
  }
  return {};
}

bool TemperatureShift::admits(double th) const {
  if (!(std::isfinite(th) && th > -kZeroCelsius)) return false;
  return kind == Kind::arrhenius || C2 + th - T_ref > 0.0;
}

std::string TemperatureShift::range() const {
  if (kind == Kind::arrhenius) return "temperature > -273.15 (in degC)";
  return "temperature > " + number_text(T_ref - C2, 10) + " (in degC; T_ref - C2, where WLF diverges)";
}

double TemperatureShift::log10_factor(double th) const {
  const double d = th - T_ref;
  if (kind == Kind::wlf) return -C1 * d / (C2 + d);
  return E_a / kGasConstant * (1.0 / (th + kZeroCelsius) - 1.0 / (T_ref + kZeroCelsius)) / std::log(10.0);
}

std::string TemperatureShift::describe() const {
  if (kind == Kind::wlf) {
    return "WLF, C1 = " + number_text(C1, 10) + ", C2 = " + number_text(C2, 10) + " K, T_ref = " + number_text(T_ref, 10) + " degC";
  }
  return "Arrhenius, E_a = " + number_text(E_a, 10) + " J/mol, T_ref = " + number_text(T_ref, 10) + " degC";
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
