#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/laws/creep_law.hpp"
#include "model/numerics/gauss_rules.hpp"

namespace punchsweep::model {

/// Gauss points per piece of the relaxation-kernel quadrature.
inline constexpr int kKernelNodes = 16;

/// Longest time one Gauss piece spans: 2 relaxation time scales (16 points integrate
/// exp(-x) over 2 units to machine precision), and at most one creep time scale (J, and
/// so Q, varies on that scale; T_eps for the standard linear solid).
template <class Kernel>
double kernel_piece_span(const Kernel& creep) {
  return std::min(2.0 * creep.relaxation_time_scale(), creep.creep_time_scale());
}

/// The most uniform pieces a kernel integral takes before it grades them by age.
inline constexpr int kMaxUniformKernelPieces = 256;
/// Graded pieces: a piece at age s = t - tau (its end nearest t) spans at most
/// max(kernel_piece_span, kAgeRatio s). A relaxation term exp(-s/tau_k) matters at age s
/// only while s/tau_k < 37 (below that it is under 1e-16 of its weight), so such a piece
/// spans at most 37 kAgeRatio = 11 of its times, over which 16 Gauss points integrate
/// exp(-x) to 1e-19: a spectrum over many decades costs 9 pieces a decade of age.
inline constexpr double kAgeRatio = 0.3;
/// Geometric pieces (a factor 4 each) toward a singular end of a power-law integrand: 4^-40 of
/// the first piece is left, where the integrand's share is below 1e-16 of it (n >= 0.05).
inline constexpr int kSingularLevels = 40;
/// Graded pieces are laid out in age up to kSplitAge t (see relaxation_integral_mapped).
inline constexpr double kSplitAge = 1e-3;

/// int E'(t - tau(u)) f(u) tau'(u) du over [u_a, u_b] by 16-point Gauss pieces: uniform,
/// as many as make each piece span at most kernel_piece_span in time (`tau_span` is the
/// whole span), while that is at most kMaxUniformKernelPieces; else graded by age
/// (kAgeRatio), which needs `inverse(tau)`, the u of a tau. `map(u, &dtau_du)` returns
/// tau(u). `zero` is the additive identity of f's result type. With `graded_f`, f itself
/// varies on the creep time scale only near tau(u_a) and on the scale tau - tau(u_a) beyond
/// (the creep-weighted load from the start of the load or a kink): graded pieces then also
/// span at most max(creep_time_scale, kAgeRatio (tau - tau(u_a))).
/// `Kernel` is a CreepLaw, or any type with its relaxation, relaxation_rate,
/// relaxation_time_scale, creep_time_scale and singular_at_zero (LoadHistory passes the
/// slow terms of a relaxation series).
template <class Kernel, class Map, class Inverse, class F, class R>
R relaxation_integral_mapped(const Kernel& creep, double t, double u_a, double u_b, double tau_span, Map&& map,
                             Inverse&& inverse, F&& f, R zero, bool graded_f = false) {
  if (!(u_b > u_a)) return zero;
  const GaussRule& rule = gauss_legendre(kKernelNodes);
  const double span = kernel_piece_span(creep);
  R sum = zero;
  const auto piece = [&](double mid, double width) {
    for (int g = 0; g < kKernelNodes; ++g) {
      const double u = mid + 0.5 * width * rule.nodes[g];
      double dtau_du = 0.0;
      const double tau = map(u, &dtau_du);
      sum += (0.5 * width * rule.weights[g] * dtau_du * creep.relaxation_rate(t - tau)) * f(u);
    }
  };
  // A power-law kernel E' ~ -s^(n-1) is singular at age 0, and under a power law J ~ tau^n
  // makes f singular where it starts: both ends are then graded geometrically (a factor 4
  // a piece, kSingularLevels pieces), where Gauss converges as for a smooth integrand.
  const bool singular_kernel = creep.singular_at_zero();
  const bool singular_f = graded_f && singular_kernel;
  const double uniform = std::ceil(tau_span / span);
  if (uniform <= kMaxUniformKernelPieces && !singular_kernel && !singular_f) {
    const int pieces = std::max(1, static_cast<int>(uniform));
    const double width = (u_b - u_a) / pieces;
    for (int k = 0; k < pieces; ++k) {
      piece(u_a + (k + 0.5) * width, width);
    }
    return sum;
  }
  // Graded. Near t (region A) the kernel's fastest terms decay within ages far below the
  // rounding of tau ~ t, so the pieces there are laid out in the age s = t - tau itself,
  // from the end nearest t: a node's age is exact to its own size. Beyond s_split (region
  // B: ages of at least kSplitAge t, where t - tau is exact enough, and at least half the
  // range) they are laid out in u from u_a, where f may vary fast (graded_f) or be singular
  // in tau (the sqrt map). Each piece spans at most max(span, kAgeRatio s) at the age s of
  // its end nearest t, and with graded_f at most max(creep_time_scale, kAgeRatio (tau -
  // tau_a)) at its end nearest tau_a.
  double dtau = 0.0;
  const double tau_a = map(u_a, &dtau);
  const double tau_b = map(u_b, &dtau);
  const double age_a = t - tau_a;
  // An end that is t itself up to the rounding of tau(u_b) (v_t = sqrt(t - tau0) maps back
  // to t within a few ulps) is age 0 exactly: the fastest terms of the kernel would
  // otherwise miss a sliver of age as wide as that rounding.
  const double age_b = t - tau_b <= 8.0 * std::numeric_limits<double>::epsilon() * std::abs(t) ? 0.0 : t - tau_b;
  const double s_split = std::clamp(kSplitAge * t, age_b, age_b + 0.5 * (age_a - age_b));
  const double f_span = creep.creep_time_scale();
  // Region A: ages [age_b, s_split], integrated in s (dtau = -ds).
  const auto age_piece = [&](double s_lo, double s_hi) {
    const double mid = 0.5 * (s_lo + s_hi);
    const double half = 0.5 * (s_hi - s_lo);
    for (int g = 0; g < kKernelNodes; ++g) {
      const double age = mid + half * rule.nodes[g];
      sum += (half * rule.weights[g] * creep.relaxation_rate(age)) * f(inverse(t - age));
    }
  };
  double s_lo = age_b;
  if (singular_kernel && age_b == 0.0 && s_split > 0.0) {
    // [0, eps]: int E' = E(eps) - E(0), f taken at eps/2; then pieces growing 4-fold.
    const double first = std::min(s_split, span);
    double edge = first * std::pow(0.25, kSingularLevels);
    sum += (creep.relaxation(edge) - creep.relaxation(0.0)) * f(inverse(t - 0.5 * edge));
    for (int k = 0; k < kSingularLevels; ++k, edge *= 4.0) age_piece(edge, std::min(first, 4.0 * edge));
    s_lo = first;
  }
  // A singular kernel has no smallest scale: its pieces grow with age from any age.
  const double floor_span = singular_kernel ? 0.0 : span;
  while (s_lo < s_split) {
    double width = std::max(floor_span, kAgeRatio * s_lo);
    if (graded_f) width = std::min(width, std::max(f_span, kAgeRatio * (age_a - s_lo) / (1.0 + kAgeRatio)));
    const double s_hi = std::min(s_split, s_lo + width);
    age_piece(s_lo, s_hi);
    s_lo = s_hi;
  }
  // Region B: tau in [tau_a, t - s_split], in u from u_a up.
  const double tau_split = t - s_split;
  const double u_split = s_split <= age_b ? u_b : std::min(u_b, inverse(tau_split));
  double lo = u_a;
  double tau_lo = tau_a;
  if (singular_f && u_split > u_a) {
    // f ~ (tau - tau_a)^n: pieces growing 4-fold from tau_a up to the creep time scale.
    const double first = std::min(f_span, tau_split - tau_a);
    double edge = first * std::pow(0.25, kSingularLevels);
    double u_edge = std::min(u_split, inverse(tau_a + edge));
    piece(0.5 * (u_a + u_edge), u_edge - u_a);
    for (int k = 0; k < kSingularLevels; ++k) {
      const double u_next = std::min(u_split, inverse(tau_a + std::min(first, 4.0 * edge)));
      if (u_next > u_edge) piece(0.5 * (u_edge + u_next), u_next - u_edge);
      u_edge = u_next;
      edge *= 4.0;
    }
    lo = u_edge;
    tau_lo = tau_a + first;
  }
  while (lo < u_split) {
    double width = std::max(floor_span, kAgeRatio * (t - tau_lo) / (1.0 + kAgeRatio));
    if (graded_f) width = std::min(width, std::max(f_span, kAgeRatio * (tau_lo - tau_a)));
    const double tau_hi = tau_lo + width;
    const double hi = tau_hi >= tau_split ? u_split : std::min(u_split, inverse(tau_hi));
    if (!(hi > lo)) break;
    piece(0.5 * (lo + hi), hi - lo);
    lo = hi;
    tau_lo = tau_hi;
  }
  return sum;
}

/// int_{tau_a}^{tau_b} E'(t - tau) f(tau) dtau for an f smooth on [tau_a, tau_b] on the
/// creep time scale near tau_a and on the scale tau - tau_a beyond (graded_f above).
template <class Kernel, class F, class R>
R relaxation_integral(const Kernel& creep, double t, double tau_a, double tau_b, F&& f, R zero) {
  const auto identity = [](double tau, double* dtau) {
    *dtau = 1.0;
    return tau;
  };
  return relaxation_integral_mapped(creep, t, tau_a, tau_b, tau_b - tau_a, identity, [](double tau) { return tau; },
                                    f, zero, true);
}

/// int E'(t - tau) f dtau over tau in [tau0 + v_a^2, tau0 + v_b^2], in the variable
/// v = sqrt(tau - tau0) (dtau = 2 v dv), for an f that is smooth in v but behaves like
/// sqrt(tau - tau0) in tau (a contact edge passing, level 2 touching). f takes v.
template <class Kernel, class F, class R>
R relaxation_integral_sqrt(const Kernel& creep, double t, double tau0, double v_a, double v_b,
                           F&& f, R zero) {
  const auto square = [tau0](double v, double* dtau) {
    *dtau = 2.0 * v;
    return tau0 + v * v;
  };
  const auto root = [tau0](double tau) { return std::sqrt(std::max(tau - tau0, 0.0)); };
  return relaxation_integral_mapped(creep, t, v_a, v_b, v_b * v_b - v_a * v_a, square, root, f, zero);
}

}  // namespace punchsweep::model
