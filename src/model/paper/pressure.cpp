#include "model/paper/pressure.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "model/numerics/integer_power.hpp"

#include "model/numerics/gauss_rules.hpp"
#include "model/numerics/lattice.hpp"
#include "model/laws/relaxation_integral.hpp"

namespace punchsweep::model {
namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

// Eq (9.1): p_(k) for s = 2k + 1, p_(m) for s = 2m.
double punch_pressure_shape(int s, double r, double a) {
  if (!(r < a)) return 0.0;
  const double root = std::sqrt(1.0 - (r / a) * (r / a));
  if (s % 2 == 1) {
    const int k = (s - 1) / 2;
    double ratio = 1.0;  // (2k+1)!! / (2k)!!
    for (int j = 1; j <= k; ++j) ratio *= (2.0 * j + 1.0) / (2.0 * j);
    // sum_{i=1}^k (2i-2)!!/(2i-1)!! (a/r)^(2i), times r^(2k): no division by r.
    double sum = 0.0;
    double c = 1.0;
    for (int i = 1; i <= k; ++i) {
      if (i > 1) c *= (2.0 * i - 2.0) / (2.0 * i - 1.0);
      sum += c * ipow(a, 2 * i) * ipow(r, 2 * (k - i));
    }
    const double log_part = k == 0 ? std::acosh(a / r) : ipow(r, 2 * k) * std::acosh(a / r);
    // Misprint in eq (9.1): for odd s the printed p_(k) integrates to 2/pi of the load
    // K_P a^(s+1) for every k; the factor pi/2 restores it (s = 1: Sneddon's cone,
    // p = (C/2) arccosh(a/r)). Even s needs no correction.
    return 0.5 * kPi * ratio * ratio * (log_part + root * sum);
  }
  const int m = s / 2;
  double ratio = 1.0;  // (2m)!! / (2m-1)!!
  for (int j = 1; j <= m; ++j) ratio *= (2.0 * j) / (2.0 * j - 1.0);
  double sum = 0.0;
  double d = 1.0;  // (2i-3)!!/(2i-2)!!
  for (int i = 1; i <= m; ++i) {
    if (i > 1) d *= (2.0 * i - 3.0) / (2.0 * i - 2.0);
    sum += d * ipow(r / a, 2 * (m - i));
  }
  return ratio * ratio * ipow(a, 2 * m - 1) * root * sum;
}

Level1Pressure::Level1Pressure(const ContactProblem& problem, const CreepLaw& creep)
    : problem_(problem),
      creep_(creep),
      load_(creep, problem.pbar0, problem.loading),
      single_(problem.l, problem.shape),
      A1_(Lattice{problem.l}.A1_single()) {}

double Level1Pressure::creep_scaled(double r, double a1, double X) const {
  if (!(r < a1)) return 0.0;
  const double l = problem_.l;
  const double inside = a1 * a1 - r * r;
  const double ring = 2.0 * A1_ * A1_ / (l * l - r * r) * std::sqrt(inside / (l * l - a1 * a1));
  const double nominal = 5.0 * std::atan(std::sqrt(inside / (A1_ * A1_ - a1 * a1)));
  return problem_.shape.C * punch_pressure_shape(problem_.shape.s, r, a1) / kPi +
         2.0 / (5.0 * kPi) * X * (ring + nominal);
}

double Level1Pressure::contact_radius(double t) const {
  return single_.contact_radius(load_(t));
}

double Level1Pressure::at(double r, double t) const {
  const double X_t = load_(t);
  const double a_t = single_.contact_radius(X_t);
  if (!(r < a_t)) return 0.0;
  // The spot edge passes r at tau_r (0 if r was inside from the start); before that q = 0,
  // after it q grows like sqrt(tau - tau_r), hence the sqrt variable.
  const double g_r = single_.creep_scaled_pressure(r) / load_.pbar0();
  const double tau_r = g_r <= load_.response_initial() ? 0.0 : load_.time_at_response(g_r);
  const double tau_min = std::max(tau_r, t - creep_.relaxation_memory());
  auto q_at = [&](double v) {
    const double X = load_(tau_r + v * v);
    return creep_scaled(r, single_.contact_radius(X), X);
  };
  // q has a kink wherever the load does: the quadrature ends its pieces there.
  double p = creep_.relaxation(0.0) * creep_scaled(r, a_t, X_t);
  for_each_piece(problem_.loading.kinks(), tau_min, t, [&](double a, double b) {
    p += relaxation_integral_sqrt(creep_, t, tau_r, std::sqrt(std::max(a - tau_r, 0.0)),
                                  std::sqrt(std::max(b - tau_r, 0.0)), q_at, 0.0);
  });
  return p;
}

double Level1Pressure::total_load(double t) const {
  const double a_t = contact_radius(t);
  const double a_0 = contact_radius(0.0);
  const GaussRule& rule = gauss_legendre(24);
  auto integrate = [&](double phi_a, double phi_b) {
    double sum = 0.0;
    for (int g = 0; g < 24; ++g) {
      const double phi = 0.5 * (phi_a + phi_b) + 0.5 * (phi_b - phi_a) * rule.nodes[g];
      const double r = a_t * std::sin(phi);
      sum += rule.weights[g] * 2.0 * kPi * r * at(r, t) * a_t * std::cos(phi);
    }
    return 0.5 * (phi_b - phi_a) * sum;
  };
  const double phi_kink = a_0 < a_t ? std::asin(a_0 / a_t) : 0.5 * kPi;
  // Geometric panels towards r = 0 (the cone's log singularity), then the rest up to the
  // kink, then the kink to the edge.
  double total = 0.0;
  double lo = phi_kink * 0x1p-30;
  total += integrate(0.0, lo);
  while (lo < phi_kink) {
    const double hi = std::min(2.0 * lo, phi_kink);
    total += integrate(lo, hi);
    lo = hi;
  }
  // Past a_0 the profile also kinks at the radius the spot had at each kink of the load
  // (where the edge passed when the load's rate changed): 4 panels between breaks.
  std::vector<double> breaks{phi_kink};
  for (const double kink : problem_.loading.kinks()) {
    const double a_k = kink < t ? contact_radius(kink) : a_t;
    if (a_k > a_0 && a_k < a_t) breaks.push_back(std::asin(a_k / a_t));
  }
  breaks.push_back(0.5 * kPi);
  constexpr int kOuterPanels = 4;
  for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
    for (int k = 0; k < kOuterPanels; ++k) {
      const double width = (breaks[b + 1] - breaks[b]) / kOuterPanels;
      total += integrate(breaks[b] + k * width, breaks[b] + (k + 1) * width);
    }
  }
  return total;
}

}  // namespace punchsweep::model
