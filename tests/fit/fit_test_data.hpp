#pragma once
// A known material sampled as an instrument would: a Prony series and a WLF shift, E' and
// E'' at 10 frequencies per isotherm (0.1 to 100 Hz), with multiplicative Gaussian noise.

#include <cmath>
#include <random>
#include <vector>

#include "fit/material_fit.hpp"
#include "model/laws/time_shift.hpp"

namespace punchsweep::fit::testing {

/// E_inf = 1 MPa and five terms 1 to 2 decades apart (1e-4 .. 30 s), in Pa, s: the
/// isotherms below reach the rubbery plateau (omega a_T tau < 0.2 for the slowest).
inline PronyTerms known_series() {
  PronyTerms t;
  t.E_inf = 1e6;
  t.E = {8e6, 4e6, 3e6, 2e6, 1e6};
  t.tau = {1e-4, 1e-3, 1e-2, 1.0, 30.0};
  return t;
}

inline model::TemperatureShift known_wlf() {
  model::TemperatureShift s;
  s.kind = model::TemperatureShift::Kind::wlf;
  s.T_ref = 20.0;
  s.C1 = 8.0;
  s.C2 = 120.0;
  return s;
}

/// DMA readings at `temperatures` (degC), each E' and E'' multiplied by (1 + noise N(0, 1)).
inline Measurements sample(const std::vector<double>& temperatures, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  const PronyTerms t = known_series();
  const model::TemperatureShift law = known_wlf();
  Measurements m;
  for (const double th : temperatures) {
    const double aT = std::pow(10.0, law.log10_factor(th));
    for (int k = 0; k < 10; ++k) {
      const double omega = 2.0 * M_PI * 0.1 * std::pow(10.0, 3.0 * k / 9.0);
      m.dma.push_back({th, omega, t.storage(omega * aT) * (1.0 + noise * n(rng)), t.loss(omega * aT) * (1.0 + noise * n(rng))});
    }
  }
  return m;
}

}  // namespace punchsweep::fit::testing
