#pragma once

#include <algorithm>
#include <cmath>

#include "model/creep_law.hpp"
#include "model/gauss_legendre.hpp"

namespace punchsweep::model {

/// Gauss points per piece of the relaxation-kernel quadrature.
inline constexpr int kKernelNodes = 16;

/// Longest time one Gauss piece spans: 2 relaxation time scales (16 points integrate
/// exp(-x) over 2 units to machine precision), and at most one creep time scale (J, and
/// so Q, varies on that scale; T_eps for the standard linear solid).
inline double kernel_piece_span(const CreepLaw& creep) {
  return std::min(2.0 * creep.relaxation_time_scale(), creep.creep_time_scale());
}

/// int E'(t - tau(u)) f(u) tau'(u) du over [u_a, u_b] by 16-point Gauss pieces, as many as
/// make each piece span at most kernel_piece_span in time (`tau_span` is the whole span).
/// `map(u, &dtau_du)` returns tau(u). `zero` is the additive identity of f's result type.
template <class Map, class F, class R>
R relaxation_integral_mapped(const CreepLaw& creep, double t, double u_a, double u_b,
                             double tau_span, Map&& map, F&& f, R zero) {
  if (!(u_b > u_a)) return zero;
  const GaussLegendreRule& rule = gauss_legendre(kKernelNodes);
  const int pieces = std::max(1, static_cast<int>(std::ceil(tau_span / kernel_piece_span(creep))));
  const double width = (u_b - u_a) / pieces;
  R sum = zero;
  for (int k = 0; k < pieces; ++k) {
    const double mid = u_a + (k + 0.5) * width;
    for (int g = 0; g < kKernelNodes; ++g) {
      const double u = mid + 0.5 * width * rule.nodes[g];
      double dtau_du = 0.0;
      const double tau = map(u, &dtau_du);
      sum += (0.5 * width * rule.weights[g] * dtau_du * creep.relaxation_rate(t - tau)) * f(u);
    }
  }
  return sum;
}

/// int_{tau_a}^{tau_b} E'(t - tau) f(tau) dtau for an f smooth on [tau_a, tau_b].
template <class F, class R>
R relaxation_integral(const CreepLaw& creep, double t, double tau_a, double tau_b, F&& f, R zero) {
  const auto identity = [](double tau, double* dtau) {
    *dtau = 1.0;
    return tau;
  };
  return relaxation_integral_mapped(creep, t, tau_a, tau_b, tau_b - tau_a, identity, f, zero);
}

/// int E'(t - tau) f dtau over tau in [tau0 + v_a^2, tau0 + v_b^2], in the variable
/// v = sqrt(tau - tau0) (dtau = 2 v dv), for an f that is smooth in v but behaves like
/// sqrt(tau - tau0) in tau (a contact edge passing, level 2 touching). f takes v.
template <class F, class R>
R relaxation_integral_sqrt(const CreepLaw& creep, double t, double tau0, double v_a, double v_b,
                           F&& f, R zero) {
  const auto square = [tau0](double v, double* dtau) {
    *dtau = 2.0 * v;
    return tau0 + v * v;
  };
  return relaxation_integral_mapped(creep, t, v_a, v_b, v_b * v_b - v_a * v_a, square, f, zero);
}

}  // namespace punchsweep::model
