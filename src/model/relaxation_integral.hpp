#pragma once

#include <algorithm>
#include <cmath>

#include "model/creep_law.hpp"
#include "model/gauss_legendre.hpp"

namespace punchsweep::model {

/// Gauss points per piece of the relaxation-kernel quadrature.
inline constexpr int kKernelNodes = 16;

/// Longest time one Gauss piece spans: 2 relaxation time scales (16 points integrate
/// exp(-x) over 2 units to machine precision), and at most 1 T_eps (J varies on that scale).
inline double kernel_piece_span(const CreepLaw& creep) {
  return std::min(2.0 * creep.relaxation_time_scale(), 1.0);
}

/// int_{tau_a}^{tau_b} E'(t - tau) f(tau) dtau for an f smooth on [tau_a, tau_b].
/// `zero` is the additive identity of f's result type (double, Eigen vector, ...).
template <class F, class R>
R relaxation_integral(const CreepLaw& creep, double t, double tau_a, double tau_b, F&& f, R zero) {
  if (!(tau_b > tau_a)) return zero;
  const GaussLegendreRule& rule = gauss_legendre(kKernelNodes);
  const int pieces = std::max(1, static_cast<int>(std::ceil((tau_b - tau_a) / kernel_piece_span(creep))));
  const double width = (tau_b - tau_a) / pieces;
  R sum = zero;
  for (int k = 0; k < pieces; ++k) {
    const double mid = tau_a + (k + 0.5) * width;
    for (int g = 0; g < kKernelNodes; ++g) {
      const double tau = mid + 0.5 * width * rule.nodes[g];
      sum += (0.5 * width * rule.weights[g] * creep.relaxation_rate(t - tau)) * f(tau);
    }
  }
  return sum;
}

/// int E'(t - tau) f dtau over tau in [tau0 + v_a^2, tau0 + v_b^2], in the variable
/// v = sqrt(tau - tau0) (dtau = 2 v dv), for an f that is smooth in v but behaves like
/// sqrt(tau - tau0) in tau (a contact edge passing, level 2 touching). f takes v.
template <class F, class R>
R relaxation_integral_sqrt(const CreepLaw& creep, double t, double tau0, double v_a, double v_b,
                           F&& f, R zero) {
  if (!(v_b > v_a)) return zero;
  const GaussLegendreRule& rule = gauss_legendre(kKernelNodes);
  const double tau_span = v_b * v_b - v_a * v_a;
  const int pieces = std::max(1, static_cast<int>(std::ceil(tau_span / kernel_piece_span(creep))));
  const double width = (v_b - v_a) / pieces;
  R sum = zero;
  for (int k = 0; k < pieces; ++k) {
    const double mid = v_a + (k + 0.5) * width;
    for (int g = 0; g < kKernelNodes; ++g) {
      const double v = mid + 0.5 * width * rule.nodes[g];
      sum += (width * rule.weights[g] * v * creep.relaxation_rate(t - tau0 - v * v)) * f(v);
    }
  }
  return sum;
}

}  // namespace punchsweep::model
