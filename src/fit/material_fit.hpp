#pragma once
/// @file
/// From measurements to a material: the master curve (master_curve.hpp) and the Prony
/// series fitted on it (prony_fit.hpp), with every reading's reduced abscissa and the
/// fit's values there for the report and the picture.

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
  /// The terms moved by the window: slower ones joined to E_inf, faster ones dropped.
  int frozen = 0, dropped = 0;
  /// RMS relative errors of the fit before the window, over every reading (prony's are
  /// the written series' over the readings within the window).
  double rms_all_first = 0.0, rms_all_second = 0.0;
};

/// Throws std::invalid_argument with the reason when the measurements cannot give a
/// material (none, mixed kinds, no equilibrium modulus within the window, or as
/// build_master_curve and the Prony fits throw).
MaterialFit fit_material(const Measurements& measurements, const MaterialFitRequest& request);

}  // namespace punchsweep::fit
