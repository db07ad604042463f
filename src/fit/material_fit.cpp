#include "fit/material_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "model/numerics/number_text.hpp"

namespace punchsweep::fit {
namespace {

/// The readings as isotherms: sorted by temperature, a new isotherm wherever consecutive
/// temperatures are more than `gap` apart (an instrument logs each reading's measured
/// temperature, which wanders by tenths of a kelvin about the set point). An isotherm's
/// temperature is its readings' mean. `isotherm_of[k]` is reading k's.
std::vector<Isotherm> group_isotherms(const Measurements& m, double gap, std::vector<std::size_t>* isotherm_of) {
  struct Raw {
    double temperature, x, y;
    std::size_t index;
  };
  std::vector<Raw> raw;
  for (const DmaReading& r : m.dma) raw.push_back({r.temperature, r.omega, r.storage, raw.size()});
  for (const RelaxationReading& r : m.relaxation) raw.push_back({r.temperature, r.time, r.modulus, raw.size()});
  std::stable_sort(raw.begin(), raw.end(), [](const Raw& a, const Raw& b) { return a.temperature < b.temperature; });
  std::vector<Isotherm> isotherms;
  isotherm_of->assign(raw.size(), 0);
  for (std::size_t k = 0; k < raw.size(); ++k) {
    if (k == 0 || raw[k].temperature - raw[k - 1].temperature > gap) isotherms.emplace_back();
    Isotherm& iso = isotherms.back();
    iso.temperature += raw[k].temperature;
    iso.x.push_back(raw[k].x);
    iso.y.push_back(raw[k].y);
    (*isotherm_of)[raw[k].index] = isotherms.size() - 1;
  }
  for (Isotherm& iso : isotherms) iso.temperature /= static_cast<double>(iso.x.size());
  return isotherms;
}

}  // namespace

MaterialFit fit_material(const Measurements& measurements, const MaterialFitRequest& request) {
  const bool dma = !measurements.dma.empty();
  if (dma == !measurements.relaxation.empty()) {
    throw std::invalid_argument(dma ? "give DMA readings or a relaxation test, not both" : "no readings to fit");
  }
  MaterialFit out;
  out.abscissa = dma ? Abscissa::frequency : Abscissa::time;
  std::vector<std::size_t> isotherm_of;
  const std::vector<Isotherm> isotherms = group_isotherms(measurements, request.isotherm_gap, &isotherm_of);
  for (const DmaReading& r : measurements.dma) out.readings.push_back({r.temperature, r.omega, 0, r.storage, r.loss});
  for (const RelaxationReading& r : measurements.relaxation) out.readings.push_back({r.temperature, r.time, 0, r.modulus});
  for (std::size_t k = 0; k < out.readings.size(); ++k) out.readings[k].temperature = isotherms[isotherm_of[k]].temperature;

  out.master = build_master_curve(isotherms, out.abscissa, request.shift);
  std::vector<double> x, first, second;
  for (std::size_t k = 0; k < out.readings.size(); ++k) {
    ReducedReading& r = out.readings[k];
    const double a = std::pow(10.0, out.master.log10_aT(isotherm_of[k]));
    r.x_reduced = dma ? r.x * a : r.x / a;
    const double tau = dma ? 1.0 / r.x_reduced : r.x_reduced;
    r.used = tau >= request.window_lo && tau <= request.window_hi;
    out.used += r.used ? 1 : 0;
    x.push_back(r.x_reduced);
    first.push_back(r.first);
    second.push_back(r.second);
  }
  out.prony = dma ? fit_prony_frequency(x, first, second, request.prony) : fit_prony_relaxation(x, first, request.prony);
  out.rms_all_first = out.prony.rms_first;
  out.rms_all_second = out.prony.rms_second;
  // The window: slower terms frozen into E_inf, faster ones dropped.
  PronyTerms kept;
  kept.E_inf = out.prony.terms.E_inf;
  for (std::size_t i = 0; i < out.prony.terms.E.size(); ++i) {
    const double tau = out.prony.terms.tau[i], E = out.prony.terms.E[i];
    if (tau > request.window_hi) {
      kept.E_inf += E;
      ++out.frozen;
    } else if (tau < request.window_lo) {
      ++out.dropped;
    } else {
      kept.E.push_back(E);
      kept.tau.push_back(tau);
    }
  }
  out.prony.terms = kept;
  if (!(kept.E_inf > 0.0)) {
    throw std::invalid_argument(
        "the fit finds no equilibrium modulus (E_inf = 0, with the terms slower than the time window's end, " +
        model::number_text(request.window_hi, 3) +
        " s, held in it): the data do not reach a rubbery plateau, which the engine's laws need (limited "
        "creep); measure lower frequencies or higher temperatures");
  }
  if (kept.E.empty()) throw std::invalid_argument("no relaxation time of the fit lies within the time window");
  if (out.used < 2) {
    throw std::invalid_argument(std::to_string(out.used) + " of " + std::to_string(out.readings.size()) +
                                " readings lie within the time window (" + model::number_text(request.window_lo, 3) +
                                " to " + model::number_text(request.window_hi, 3) +
                                " s at the reference temperature); choose a window or reference temperature "
                                "nearer the data");
  }
  // The written series against the readings within the window.
  double s1 = 0.0, s2 = 0.0;
  for (ReducedReading& r : out.readings) {
    r.first_fit = dma ? kept.storage(r.x_reduced) : kept.relaxation(r.x_reduced);
    r.second_fit = dma ? kept.loss(r.x_reduced) : 0.0;
    if (!r.used) continue;
    s1 += std::pow(r.first_fit / r.first - 1.0, 2);
    if (dma) s2 += std::pow(r.second_fit / r.second - 1.0, 2);
  }
  out.prony.rms_first = std::sqrt(s1 / static_cast<double>(out.used));
  out.prony.rms_second = dma ? std::sqrt(s2 / static_cast<double>(out.used)) : 0.0;
  return out;
}

}  // namespace punchsweep::fit

namespace punchsweep::fit {

std::vector<std::string> fit_problems(const MaterialFit& fit, const FitLimits& limits) {
  std::vector<std::string> problems;
  const MasterCurve& m = fit.master;
  const auto text = [](double v, int digits = 3) { return model::number_text(v, digits); };
  const bool measured = !m.measured_log10_aT.empty() && !std::isnan(m.measured_log10_aT.front());
  if (measured) {
    for (std::size_t i = 1; i < m.temperatures.size(); ++i) {
      const double rise = m.measured_log10_aT[i] - m.measured_log10_aT[i - 1];
      if (rise > limits.shift_rise) {
        problems.push_back("the shifts rise with temperature: " + text(m.temperatures[i]) + " degC is shifted by " +
                           text(m.measured_log10_aT[i]) + " decades, " + text(m.temperatures[i - 1]) + " degC by " +
                           text(m.measured_log10_aT[i - 1]) +
                           " (a warmer isotherm relaxes sooner: swapped labels, or isotherms on a plateau where E' "
                           "cannot place them)");
      }
    }
    if (m.law && m.law->kind == model::TemperatureShift::Kind::wlf) {
      const double lower = std::max(0.0, m.law->T_ref - m.temperatures.front()) + 0.1;
      if (m.law->C2 > 0.99 * kWlfC2Max || m.law->C2 < 1.01 * lower) {
        problems.push_back("WLF's C2 = " + text(m.law->C2, 6) + " K lies on the bound of its search (" + text(lower, 4) +
                           " to " + text(kWlfC2Max, 4) + " K): the shifts do not determine it");
      }
    }
    if (m.rms_log10 > limits.shift_rms) {
      problems.push_back("the measured shifts lie " + text(m.rms_log10) + " decades (RMS) about the fitted law; limit " +
                         text(limits.shift_rms) + " decades");
    }
  }
  const bool dma = fit.abscissa == Abscissa::frequency;
  if (fit.rms_all_first > limits.rms_first) {
    problems.push_back(std::string(dma ? "E'" : "E(t)") + " is fitted to " + text(100 * fit.rms_all_first) +
                       "% (RMS over every reading); limit " + text(100 * limits.rms_first) + "%");
  }
  if (dma && fit.rms_all_second > limits.rms_second) {
    problems.push_back("E'' is fitted to " + text(100 * fit.rms_all_second) + "% (RMS over every reading); limit " +
                       text(100 * limits.rms_second) + "%");
  }
  return problems;
}

}  // namespace punchsweep::fit
