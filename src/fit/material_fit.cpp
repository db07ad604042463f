#include "fit/material_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <functional>
#include <stdexcept>
#include <utility>

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

/// The RMS relative error (of E' and of E'', or of E(t)) within which a law fitted with the
/// series is taken where the overlap failed.
constexpr double kJointRms = 0.05;

/// The readings of one kind, and each one's isotherm: what the series and the law are
/// fitted to (fitted_readings).
struct Readings {
  bool dma = true;
  std::vector<double> x, first, second;
  std::vector<std::size_t> isotherm;
  std::vector<double> weight;  ///< how many readings each stands for; empty: each one
};

/// The most readings the series (and a law fitted with it) are fitted to. Each of the fit's
/// least-squares solves takes time in proportion to the readings, and a fit makes 25,000
/// (the law polished) to 80,000 (the law searched) of them: 70 readings took 1 s, 2,100 took
/// 14 s and 20,000 (a 1 MiB export) 143 s. More than this are binned (fitted_readings).
constexpr std::size_t kMaxFitted = 300;

/// The readings the series is fitted to, each with its isotherm: every reading, in order,
/// where they number kMaxFitted or fewer. More (a long export) are binned per isotherm in
/// log10 of the abscissa: each isotherm's span cut into bins of equal width, as many as its
/// share of kMaxFitted; the readings of a bin become one at their mean log10 abscissa and
/// mean log10 moduli (geometric means), weighted by their number, so that the sum of squared
/// relative residuals is theirs less their scatter within the bin (the noise, which no
/// series fits). A bin of one reading keeps it as read.
Readings fitted_readings(const MaterialFit& out, const std::vector<std::size_t>& isotherm_of, std::size_t isotherms) {
  Readings r;
  r.dma = out.abscissa == Abscissa::frequency;
  const std::size_t n = out.readings.size();
  const auto keep = [&r](const ReducedReading& reading, std::size_t isotherm) {
    r.x.push_back(reading.x);
    r.first.push_back(reading.first);
    r.second.push_back(reading.second);
    r.isotherm.push_back(isotherm);
  };
  if (n <= kMaxFitted) {
    for (std::size_t k = 0; k < n; ++k) keep(out.readings[k], isotherm_of[k]);
    return r;
  }
  std::vector<std::vector<std::size_t>> members(isotherms);
  for (std::size_t k = 0; k < n; ++k) members[isotherm_of[k]].push_back(k);
  for (std::size_t i = 0; i < isotherms; ++i) {
    const std::vector<std::size_t>& m = members[i];
    if (m.empty()) continue;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const std::size_t k : m) {
      lo = std::min(lo, std::log10(out.readings[k].x));
      hi = std::max(hi, std::log10(out.readings[k].x));
    }
    const std::size_t bins = std::max<std::size_t>(1, m.size() * kMaxFitted / n);
    struct Bin {
      std::size_t count = 0, first = 0;
      double log_x = 0.0, log_first = 0.0, log_second = 0.0;
    };
    std::vector<Bin> bin(bins);
    for (const std::size_t k : m) {
      const ReducedReading& reading = out.readings[k];
      const double lx = std::log10(reading.x);
      const double along = hi > lo ? (lx - lo) / (hi - lo) : 0.0;  // 0 to 1 across the isotherm
      Bin& b = bin[std::min(bins - 1, static_cast<std::size_t>(along * static_cast<double>(bins)))];
      if (b.count++ == 0) b.first = k;
      b.log_x += lx;
      b.log_first += std::log10(reading.first);
      if (r.dma) b.log_second += std::log10(reading.second);
    }
    for (const Bin& b : bin) {
      if (b.count == 0) continue;
      const double c = static_cast<double>(b.count);
      if (b.count == 1) {
        keep(out.readings[b.first], i);
      } else {
        r.x.push_back(std::pow(10.0, b.log_x / c));
        r.first.push_back(std::pow(10.0, b.log_first / c));
        r.second.push_back(r.dma ? std::pow(10.0, b.log_second / c) : 0.0);
        r.isotherm.push_back(i);
      }
      r.weight.push_back(c);
    }
  }
  return r;
}

/// The Prony fit of the readings reduced by the isotherms' shifts L (log10 a_T each).
PronyFit fit_reduced(const Readings& r, const std::vector<double>& L, const PronyOptions& options) {
  std::vector<double> x(r.x.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double a = std::pow(10.0, L[r.isotherm[k]]);
    x[k] = r.dma ? r.x[k] * a : r.x[k] / a;
  }
  return r.dma ? fit_prony_frequency(x, r.first, r.second, options, r.weight)
               : fit_prony_relaxation(x, r.first, options, r.weight);
}

/// Nelder-Mead simplex minimum of f over R^d from `start` with initial steps `step`
/// (Lagarias et al., SIAM J. Optim. 9:112, 1998: reflection 1, expansion 2, contraction
/// 1/2, shrink 1/2), until the simplex's values agree to `tolerance` (relative) or after
/// `evaluations`.
std::vector<double> simplex_minimum(const std::function<double(const std::vector<double>&)>& f,
                                    const std::vector<double>& start, double step, double tolerance, int evaluations) {
  const std::size_t d = start.size();
  std::vector<std::vector<double>> x(d + 1, start);
  std::vector<double> v(d + 1);
  for (std::size_t i = 0; i < d; ++i) x[i + 1][i] += step;
  for (std::size_t i = 0; i <= d; ++i) v[i] = f(x[i]);
  int used = static_cast<int>(d) + 1;
  while (used < evaluations) {
    std::vector<std::size_t> order(d + 1);
    for (std::size_t i = 0; i <= d; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
    const std::size_t best = order.front(), worst = order.back(), second = order[d - 1];
    if (std::abs(v[worst] - v[best]) <= tolerance * (std::abs(v[best]) + 1e-300)) break;
    std::vector<double> centre(d, 0.0);
    for (std::size_t i = 0; i <= d; ++i) {
      if (i == worst) continue;
      for (std::size_t k = 0; k < d; ++k) centre[k] += x[i][k] / static_cast<double>(d);
    }
    const auto along = [&](double t) {
      std::vector<double> p(d);
      for (std::size_t k = 0; k < d; ++k) p[k] = centre[k] + t * (x[worst][k] - centre[k]);
      return p;
    };
    const std::vector<double> r = along(-1.0);
    const double fr = f(r);
    ++used;
    if (fr < v[best]) {
      const std::vector<double> e = along(-2.0);
      const double fe = f(e);
      ++used;
      x[worst] = fe < fr ? e : r;
      v[worst] = std::min(fe, fr);
    } else if (fr < v[second]) {
      x[worst] = r;
      v[worst] = fr;
    } else {
      const std::vector<double> c = fr < v[worst] ? along(-0.5) : along(0.5);
      const double fc = f(c);
      ++used;
      if (fc < std::min(fr, v[worst])) {
        x[worst] = c;
        v[worst] = fc;
      } else {
        for (std::size_t i = 0; i <= d; ++i) {
          if (i == best) continue;
          for (std::size_t k = 0; k < d; ++k) x[i][k] = x[best][k] + 0.5 * (x[i][k] - x[best][k]);
          v[i] = f(x[i]);
          ++used;
        }
      }
    }
  }
  return x[static_cast<std::size_t>(std::min_element(v.begin(), v.end()) - v.begin())];
}

/// The shift law and the series fitted together: the law's parameters (WLF's C1 and C2, or
/// Arrhenius' E_a) chosen so that one series, fitted at the shifts the law gives, meets
/// every reading best (E' and E'' of a DMA test, or E(t)). Where E' is flat within the
/// noise (a glassy or rubbery plateau) its overlap cannot place an isotherm, but E''
/// (peaked) and the series' continuity across the isotherms can. Simplex searches from the
/// overlap's law and from a grid of starts (the overlap's law is wrong where cold isotherms
/// sit on a plateau), with the `coarse` series' residual, then the best polished with the
/// `fine` one's. Where the overlap's law stands (`search` false) it is only polished: the
/// law fitted to the measured shifts weighs every isotherm's shift alike, the readings
/// themselves weigh it by what each isotherm says. Returns the law and the residual (rss)
/// of its `fine` fit.
std::pair<model::TemperatureShift, double> joint_law(const Readings& r, const std::vector<double>& temperatures,
                                                     const model::TemperatureShift& start, bool search,
                                                     const PronyOptions& coarse, const PronyOptions& fine) {
  const bool wlf = start.kind == model::TemperatureShift::Kind::wlf;
  const double floor_C2 = std::max(0.0, start.T_ref - temperatures.front()) + 0.1;  // every isotherm above T_ref - C2
  const auto law_of = [&](const std::vector<double>& p) {
    model::TemperatureShift law = start;
    if (wlf) {
      law.C1 = std::exp(p[0]);
      law.C2 = floor_C2 + std::exp(p[1]);
    } else {
      law.E_a = std::exp(p[0]);
    }
    return law;
  };
  const auto cost_with = [&](const std::vector<double>& p, const PronyOptions& options) {
    const model::TemperatureShift law = law_of(p);
    std::vector<double> L;
    for (const double t : temperatures) {
      const double l = law.log10_factor(t);
      if (!(std::abs(l) < 100.0)) return std::numeric_limits<double>::infinity();  // no series spans that
      L.push_back(l);
    }
    try {
      return fit_reduced(r, L, options).rss;
    } catch (const std::invalid_argument&) {
      return std::numeric_limits<double>::infinity();
    }
  };
  const auto cost = [&](const std::vector<double>& p) { return cost_with(p, coarse); };
  const auto polished = [&](const std::vector<double>& p) { return cost_with(p, fine); };
  // Starts: the overlap's law, then a grid over the laws polymers have (WLF C1 5-40, C2
  // 30-300 K; Arrhenius E_a 30-500 kJ/mol): the residual has local minima where isotherms
  // jump past each other.
  std::vector<std::vector<double>> starts;
  if (wlf) {
    starts.push_back({std::log(start.C1), std::log(std::max(start.C2 - floor_C2, 1e-3))});
  } else {
    starts.push_back({std::log(start.E_a)});
  }
  if (!search) {
    const std::vector<double> p = simplex_minimum(polished, starts.front(), 0.05, 1e-7, 80);
    return {law_of(p), polished(p)};
  }
  if (wlf) {
    for (const double c1 : {5.0, 9.0, 15.0, 25.0, 40.0}) {
      for (const double c2 : {30.0, 60.0, 100.0, 170.0, 300.0}) {
        if (c2 > floor_C2) starts.push_back({std::log(c1), std::log(c2 - floor_C2)});
      }
    }
  } else {
    for (const double e : {30e3, 60e3, 100e3, 150e3, 220e3, 320e3, 500e3}) starts.push_back({std::log(e)});
  }
  // Two stages: the basins from every start with the cheap residual (a grid of times, not
  // refined: milliseconds a fit), then the three best polished with the series' times
  // refined (variable projection), whose minimum is the law's (the grid's is biased by
  // up to a few percent in the law's parameters, which is a factor 2 in a_T 40 K away).
  std::vector<std::pair<double, std::vector<double>>> ends;
  for (const std::vector<double>& s0 : starts) {
    const std::vector<double> p = simplex_minimum(cost, s0, 0.3, 1e-6, 150);
    ends.emplace_back(cost(p), p);
  }
  std::sort(ends.begin(), ends.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<double> best_p = ends.front().second;
  double best = polished(best_p);
  for (std::size_t k = 0; k < std::min<std::size_t>(3, ends.size()); ++k) {
    const std::vector<double> p = simplex_minimum(polished, ends[k].second, 0.05, 1e-7, 80);
    const double c = polished(p);
    if (c < best) {
      best = c;
      best_p = p;
    }
  }
  return {law_of(best_p), best};
}

/// The series fitted on `out.master`'s master curve (the `fitted` readings, each reduced by
/// its isotherm's shift), then cut to the time window, and its RMS errors over every reading.
void fit_series(MaterialFit& out, const Readings& fitted, const std::vector<std::size_t>& isotherm_of,
                const MaterialFitRequest& request) {
  const bool dma = out.abscissa == Abscissa::frequency;
  out.used = 0;
  out.frozen = out.dropped = 0;
  for (std::size_t k = 0; k < out.readings.size(); ++k) {
    ReducedReading& r = out.readings[k];
    const double a = std::pow(10.0, out.master.log10_aT(isotherm_of[k]));
    r.x_reduced = dma ? r.x * a : r.x / a;
    const double tau = dma ? 1.0 / r.x_reduced : r.x_reduced;
    r.used = tau >= request.window_lo && tau <= request.window_hi;
    out.used += r.used ? 1 : 0;
  }
  std::vector<double> L;
  for (std::size_t i = 0; i < out.master.temperatures.size(); ++i) L.push_back(out.master.log10_aT(i));
  out.prony = fit_reduced(fitted, L, request.prony);
  out.fitted = fitted.x.size();
  // The errors over every reading (the series may have been fitted to bins of them).
  double a1 = 0.0, a2 = 0.0;
  for (const ReducedReading& r : out.readings) {
    const PronyTerms& t = out.prony.terms;
    const double e1 = (dma ? t.storage(r.x_reduced) : t.relaxation(r.x_reduced)) / r.first - 1.0;
    a1 += e1 * e1;
    if (dma) {
      const double e2 = t.loss(r.x_reduced) / r.second - 1.0;
      a2 += e2 * e2;
    }
  }
  const auto n = static_cast<double>(out.readings.size());
  out.rms_all_first = std::sqrt(a1 / n);
  out.rms_all_second = dma ? std::sqrt(a2 / n) : 0.0;
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

  // (A law of k parameters needs k + 1 isotherms: WLF 3, Arrhenius 2; fewer are refused
  // with the overlap's reason.)
  const std::size_t needed = request.shift.law == ShiftRequest::Law::wlf ? 3 : 2;
  const bool may_join =
      request.fit_law_with_series && request.shift.law != ShiftRequest::Law::given && isotherms.size() >= needed;
  // The overlap of E' first (what instruments' software does); where it cannot lay the
  // isotherms onto each other (no common moduli: a plateau) or fails the fit's own checks,
  // the law is fitted together with the series instead, and kept where the series then
  // meets the readings better (both residuals on one footing, below) and within kJointRms.
  const Readings fitted = fitted_readings(out, isotherm_of, isotherms.size());
  std::string overlap_failed;
  try {
    out.master = build_master_curve(isotherms, out.abscissa, request.shift);
    fit_series(out, fitted, isotherm_of, request);
  } catch (const std::invalid_argument& e) {
    if (!may_join) throw;
    overlap_failed = e.what();
  }
  const bool overlap_stands = overlap_failed.empty() && fit_problems(out).empty();
  // Where the overlap stands, the law is polished with the series (the readings weigh each
  // isotherm's shift by what it says, the law fitted to the shifts weighs them alike), but
  // not where the series misses the readings by more than a law fitted with it may: one law
  // meets them no better than the free shifts do.
  const bool series_misses = out.rms_all_first > kJointRms ||
                             (out.abscissa == Abscissa::frequency && out.rms_all_second > kJointRms);
  if (!may_join || (overlap_stands && series_misses)) return out;
  const Readings& r = fitted;
  std::vector<double> temperatures;
  for (const Isotherm& iso : isotherms) temperatures.push_back(iso.temperature);
  // The residual on one footing for both: the series at one density (the overlap's choice,
  // at least 1 a decade), its times refined; and a cheap one for the search's first stage
  // (at least 3 a decade, the times on their grid).
  PronyOptions options = request.prony;
  options.per_decade = {std::max(1.0, overlap_failed.empty() ? out.prony.candidates[out.prony.chosen].per_decade : 1.0)};
  options.refine = true;
  PronyOptions coarse = request.prony;
  coarse.per_decade = {std::max(3.0, options.per_decade.front())};
  coarse.refine = false;
  model::TemperatureShift start;
  if (overlap_failed.empty() && out.master.law) {
    start = *out.master.law;
  } else {
    start.kind = request.shift.law == ShiftRequest::Law::wlf ? model::TemperatureShift::Kind::wlf
                                                              : model::TemperatureShift::Kind::arrhenius;
    start.T_ref = request.shift.T_ref;
    start.C1 = 15.0;
    start.C2 = std::max(100.0, request.shift.T_ref - temperatures.front() + 20.0);
    start.E_a = 150e3;
  }
  start.T_min = std::min(temperatures.front(), request.shift.T_ref);
  start.T_max = std::max(temperatures.back(), request.shift.T_ref);
  const auto [law, joint_rss] = joint_law(r, temperatures, start, !overlap_stands, coarse, options);
  if (overlap_failed.empty() && !overlap_stands) {  // a fallback: kept only where it fits better
    std::vector<double> L;
    for (std::size_t i = 0; i < isotherms.size(); ++i) L.push_back(out.master.log10_aT(i));
    if (!(joint_rss < fit_reduced(r, L, options).rss)) return out;
  }
  MaterialFit joint = out;
  joint.master.temperatures = temperatures;
  joint.master.joint = true;
  joint.master.polished = overlap_stands;
  joint.master.law = law;
  joint.master.law_log10_aT.clear();
  for (const double t : temperatures) joint.master.law_log10_aT.push_back(law.log10_factor(t));
  if (!overlap_failed.empty()) {
    joint.master.measured_log10_aT.assign(temperatures.size(), std::numeric_limits<double>::quiet_NaN());
    joint.master.rms_log10 = std::numeric_limits<double>::quiet_NaN();
  } else {
    // The overlap's shifts are relative to each other: their zero was the overlap's law's
    // (fit_shift_law), which sits off this law's by a constant (0.2 decades and more where the
    // overlap failed). They are put on this law's zero, log10 a_T(T_ref) = 0, by the constant
    // that best matches it (least squares: their mean offset), as the overlap's own law's zero
    // is fitted, so that a good fit does not read as a misfit.
    const std::size_t n = temperatures.size();
    double offset = 0.0;
    for (std::size_t i = 0; i < n; ++i) offset += joint.master.measured_log10_aT[i] - joint.master.law_log10_aT[i];
    offset /= static_cast<double>(n);
    double ss = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      joint.master.measured_log10_aT[i] -= offset;
      ss += std::pow(joint.master.measured_log10_aT[i] - joint.master.law_log10_aT[i], 2);
    }
    joint.master.rms_log10 = std::sqrt(ss / static_cast<double>(n));
  }
  try {
    fit_series(joint, fitted, isotherm_of, request);
  } catch (const std::invalid_argument& e) {
    if (!overlap_failed.empty()) {
      throw std::invalid_argument(overlap_failed + "; nor does fitting the law with the series: " + e.what());
    }
    return out;  // the joint law leaves no series the engine takes: the overlap's stands, judged
  }
  // A fallback is taken only where it meets every reading closely (the noise of a DMA test
  // is 1-3%): a law that misses by more places the isotherms no better than the overlap.
  if (joint.rms_all_first > kJointRms || (joint.abscissa == Abscissa::frequency && joint.rms_all_second > kJointRms)) {
    if (!overlap_failed.empty()) {
      throw std::invalid_argument(overlap_failed + "; fitting the law with the series meets the readings only to " +
                                  model::number_text(100 * joint.rms_all_first, 3) + "% (E' or E(t)) and " +
                                  model::number_text(100 * joint.rms_all_second, 3) + "% (E''), above " +
                                  model::number_text(100 * kJointRms, 3) + "%");
    }
    return out;
  }
  return joint;
}

std::vector<std::string> fit_problems(const MaterialFit& fit, const FitLimits& limits) {
  std::vector<std::string> problems;
  const MasterCurve& m = fit.master;
  const auto text = [](double v, int digits = 3) { return model::number_text(v, digits); };
  // The shifts' checks apply to the shifts the readings are moved by: the overlap's, not
  // where the law was given or fitted with the series (monotone by construction).
  const bool overlap = !m.measured_log10_aT.empty() && !std::isnan(m.measured_log10_aT.front());
  const bool measured = overlap && !m.joint;
  std::vector<std::string> rises;  // of the overlap's shifts
  if (overlap) {
    for (std::size_t i = 1; i < m.temperatures.size(); ++i) {
      const double rise = m.measured_log10_aT[i] - m.measured_log10_aT[i - 1];
      if (rise > limits.shift_rise) {
        rises.push_back("the shifts rise with temperature: " + text(m.temperatures[i]) + " degC is shifted by " +
                           text(m.measured_log10_aT[i]) + " decades, " + text(m.temperatures[i - 1]) + " degC by " +
                           text(m.measured_log10_aT[i - 1]) +
                           " (a warmer isotherm relaxes sooner: swapped labels, or isotherms on a plateau where E' "
                           "cannot place them)");
      }
    }
  }
  if (measured) problems.insert(problems.end(), rises.begin(), rises.end());
  if (measured || m.joint) {
    if (m.law && m.law->kind == model::TemperatureShift::Kind::wlf) {
      const double lower = std::max(0.0, m.law->T_ref - m.temperatures.front()) + 0.1;
      if (m.law->C2 > 0.99 * kWlfC2Max || m.law->C2 < 1.01 * lower) {
        problems.push_back("WLF's C2 = " + text(m.law->C2, 6) + " K lies on the bound of its search (" + text(lower, 4) +
                           " to " + text(kWlfC2Max, 4) + " K): the shifts do not determine it");
      }
    }
    if (!m.joint && m.rms_log10 > limits.shift_rms) {
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
  // A law fitted with the series is monotone; where even it misses the readings, the
  // overlap's rising shifts are the likely cause, and are named.
  if (m.joint && !problems.empty()) problems.insert(problems.end(), rises.begin(), rises.end());
  return problems;
}

}  // namespace punchsweep::fit
