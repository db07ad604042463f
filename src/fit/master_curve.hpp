#pragma once
/// @file
/// Time-temperature superposition of measured isotherms into a master curve (Ferry,
/// Viscoelastic Properties of Polymers, 3rd ed., 1980, chapter 11): each isotherm's log
/// abscissa is shifted by log10 a_T until it overlaps its neighbours', and a shift law
/// (WLF or Arrhenius, model::TemperatureShift) is fitted to the shifts or given.

#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "model/laws/time_shift.hpp"

namespace punchsweep::fit {

/// One isotherm: its temperature (degC) and its readings, x the abscissa (angular frequency
/// in rad/s, or time in s) and y the monotone modulus the shifts are found from (E' rising
/// with frequency, or E(t) falling with time), in Pa.
struct Isotherm {
  double temperature = 0.0;
  std::vector<double> x;
  std::vector<double> y;
};

/// How an abscissa moves with a_T: a frequency is multiplied by it (omega a_T, the reduced
/// frequency), a time divided (t / a_T, the reduced time).
enum class Abscissa { frequency, time };

/// What the shift law is: fitted (WLF or Arrhenius) to the measured shifts, or given.
struct ShiftRequest {
  enum class Law { wlf, arrhenius, given };
  Law law = Law::wlf;
  double T_ref = 0.0;                     ///< degC
  model::TemperatureShift given;          ///< used when law == given
};

/// The largest WLF C2 the fit searches, in K (a C2 there is a bound, not a fit).
inline constexpr double kWlfC2Max = 1e4;

/// The master curve's shifts: per isotherm (in temperature order) the shift measured from
/// the overlaps (relative to each other; on the law's zero, log10 a_T(T_ref) = 0, by the
/// constant that best matches the law: its fitted zero, or with `joint` the mean offset
/// from the law fitted with the series), the law's value, and the law itself.
struct MasterCurve {
  std::vector<double> temperatures;       ///< degC, increasing
  std::vector<double> measured_log10_aT;  ///< NaN where the law was given (nothing measured)
  std::vector<double> law_log10_aT;       ///< the shift law at each isotherm
  std::optional<model::TemperatureShift> law;  ///< none for one isotherm at T_ref and no law given
  double rms_log10 = 0.0;                 ///< RMS of measured - law, in decades (0 when given)
  /// The law was fitted with the series (fit::fit_material: the overlap shifts could not
  /// place every isotherm), and the readings are shifted by it; measured_log10_aT keeps the
  /// overlap's shifts for the record.
  bool joint = false;
  /// With `joint`: the overlap's shifts passed the fit's checks, and the law fitted to them
  /// was only polished with the series (the readings weigh each isotherm's shift by what it
  /// says; the law fitted to the shifts weighs them alike). Otherwise the overlap failed
  /// and the law was searched for.
  bool polished = false;
  /// log10 a_T each isotherm's readings are shifted by onto the master curve: the measured
  /// shift (the law's where it was given or fitted jointly), so the curve the series is
  /// fitted to is the data's own; the law carries it to other temperatures.
  double log10_aT(std::size_t isotherm) const {
    const double m = measured_log10_aT[isotherm];
    return joint || std::isnan(m) ? law_log10_aT[isotherm] : m;
  }
};

/// The shift d (decades of abscissa) that lays isotherm `upper` onto `lower`: the mean
/// over the moduli both reach of log10 x_lower(y) - log10 x_upper(y), weighted by
/// 1 / (1/slope_lower^2 + 1/slope_upper^2) (noise in y moves each by noise / slope), each isotherm's
/// log10 x(y) interpolated linearly in log-log between its readings (made monotone by
/// isotonic regression, so noise does not fold the inverse). This is the horizontal shift of
/// E' (or E(t)) alone, as instruments' software and pyvisco make it; where E' is flat
/// within the noise (a glassy or rubbery plateau) it says little, so isotherms there
/// shift poorly. Throws std::invalid_argument naming both temperatures when their moduli
/// do not overlap.
double overlap_shift(const Isotherm& lower, const Isotherm& upper);

/// Shifts of isotherms (any order, distinct temperatures) by overlapping neighbours, from
/// the one nearest T_ref outward, and the shift law fitted to them by least squares in
/// log10 a_T with a free zero (WLF: C1 > 0, C2 > 0 with every isotherm above T_ref - C2,
/// C2 searched on a logarithmic grid and refined by golden section, C1 and the zero linear;
/// Arrhenius: E_a > 0, linear), or the law given. The law's T_min and T_max are the
/// isotherms' range. Throws std::invalid_argument with the reason when the data cannot
/// give the request (too few isotherms for the law, no overlap, a fitted C1 or E_a <= 0).
MasterCurve build_master_curve(std::span<const Isotherm> isotherms, Abscissa abscissa, const ShiftRequest& request);

/// The shift law fitted to measured shifts (log10 a_T per isotherm, temperatures
/// increasing, any common zero), as build_master_curve fits it: the result's measured
/// shifts are `log10_aT` less the law's zero.
MasterCurve fit_shift_law(const std::vector<double>& temperatures, const std::vector<double>& log10_aT,
                          const ShiftRequest& request);

}  // namespace punchsweep::fit
