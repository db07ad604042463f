#pragma once
/// @file
/// From measurements to a material: the master curve (master_curve.hpp) and the Prony
/// series fitted on it (prony_fit.hpp), with every reading's reduced abscissa and the
/// fit's values there for the report and the picture.

#include <string>
#include <vector>

#include "fit/master_curve.hpp"
#include "fit/prony_fit.hpp"

namespace punchsweep::fit {

/// A DMA reading in SI: temperature in degC, angular frequency in rad/s, moduli in Pa.
struct DmaReading {
  double temperature = 0.0;
  double omega = 0.0;
  double storage = 0.0;
  double loss = 0.0;
};

/// A relaxation-test reading: temperature in degC, time in s, E(t) in Pa.
struct RelaxationReading {
  double temperature = 0.0;
  double time = 0.0;
  double modulus = 0.0;
};

/// Readings of one kind (the other list empty).
struct Measurements {
  std::vector<DmaReading> dma;
  std::vector<RelaxationReading> relaxation;
  /// Per file read, the sample's name its preamble gives ("Sample name<TAB>TPE-A"), or "".
  std::vector<std::string> samples;
};

struct MaterialFitRequest {
  ShiftRequest shift;
  /// Readings whose temperatures (sorted) are within this many K of the previous one
  /// belong to one isotherm.
  double isotherm_gap = 1.0;
  /// The times the material is to hold, in s at T_ref. The series is fitted to every
  /// reading, then terms slower than window_hi join E_inf (they do not relax within it)
  /// and terms faster than window_lo are dropped (relaxed before it begins): the series
  /// written equals the fit for times within the window. The engine's interconversion
  /// resolves 24 decades; a master curve over -50..100 degC spans 30 or more.
  double window_lo = 1e-10;
  double window_hi = 1e12;
  PronyOptions prony;
  /// Where the overlap's shifts fail (no overlap, or fit_problems), fit the shift law
  /// together with the series instead (fit_material: kept where its residual is below the
  /// overlap's and it meets the readings within 5%); not where the law is given.
  bool fit_law_with_series = true;
};

/// A reading on the master curve: where it was measured, where it lands, and the fit there
/// (first: E' or E(t); second: E'', or 0 for relaxation data).
struct ReducedReading {
  double temperature = 0.0;  ///< its isotherm's, degC
  double x = 0.0;          ///< rad/s or s, as measured
  double x_reduced = 0.0;  ///< omega a_T or t / a_T
  double first = 0.0, second = 0.0;
  double first_fit = 0.0, second_fit = 0.0;
  bool used = true;  ///< within the time window (1/(omega a_T) or t / a_T), where the written series holds
};

struct MaterialFit {
  Abscissa abscissa = Abscissa::frequency;
  MasterCurve master;
  PronyFit prony;
  std::vector<ReducedReading> readings;
  std::size_t used = 0;  ///< readings within the window
  /// The readings the series (and a law fitted with it) were fitted to: every one, or where
  /// there are more than 300 (a long export) as many bins of them, per isotherm in log10 of
  /// the abscissa, each weighted by the readings it holds (fit_material).
  std::size_t fitted = 0;
  /// The terms moved by the window: slower ones joined to E_inf, faster ones dropped.
  int frozen = 0, dropped = 0;
  /// RMS relative errors of the fit before the window, over every reading (prony's are
  /// the written series' over the readings within the window).
  double rms_all_first = 0.0, rms_all_second = 0.0;
};

/// What a fit must meet to be written without --accept-poor-fit (docs/fitting.md, "When a
/// fit is refused"). The RMS limits are relative errors over every reading: 1-3% noise
/// fits to about the noise, the published EMS-CA data set to E' 5.1%, E'' 11.2%, and a
/// cold isotherm on the glassy plateau shifted 2.6 decades short to E' 12%, E'' 39%. The
/// shifts' RMS about their law: EMS-CA's 21 isotherms over 150 K sit 0.42 decades about
/// WLF; farther, the law does not describe them.
struct FitLimits {
  double rms_first = 0.10;   ///< E' or E(t)
  double rms_second = 0.20;  ///< E''
  double shift_rms = 0.5;    ///< decades, measured shifts about the law
  double shift_rise = 0.05;  ///< decades a shift may rise with temperature (noise) before it is non-monotone
};

/// The fit's own verdict: each way it fails `limits`, with its numbers (empty: a good fit).
/// Shifts that rise with temperature (a warmer isotherm shifted to longer times: swapped
/// labels, or a plateau where the overlap says nothing); WLF's C2 on the search's bound
/// (within 1% of it, either end); the shifts' RMS about the law; the series' RMS over every
/// reading.
std::vector<std::string> fit_problems(const MaterialFit& fit, const FitLimits& limits = {});

/// Throws std::invalid_argument with the reason when the measurements cannot give a
/// material (none, mixed kinds, no equilibrium modulus within the window, or as
/// build_master_curve and the Prony fits throw).
MaterialFit fit_material(const Measurements& measurements, const MaterialFitRequest& request);

}  // namespace punchsweep::fit
