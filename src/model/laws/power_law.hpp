#pragma once

#include <string>
#include <vector>

#include "model/laws/creep_law.hpp"

namespace punchsweep::model {

/// The Mittag-Leffler function of one parameter on the negative axis, E_a(-x) for
/// 0 < a < 1 and x >= 0, held in the completely monotone form (docs/model.md, section 10)
///   f(s) = E_a(-s^a) = int_0^inf exp(-r s) K(r) dr,
///   K(r) = sin(a pi) r^(a-1) / (pi (r^(2a) + 2 r^a cos(a pi) + 1)) > 0,
/// with its derivative f'(s) = -s^(a-1) E_(a,a)(-s^a) = -int_0^inf r exp(-r s) K(r) dr.
/// Three regions in x = s^a, each exact to rounding; every table is set up per order a in
/// the constructor (about 50 us; up to 0.4 ms near a = 1), so a call costs no special
/// function beyond pow (and one atan2):
///  - x <= 0.5: the power series sum_k (-x)^k / Gamma(a k + 1) (no cancellation worth a
///    digit: its terms' moduli sum to E_a(x) <= 3 E_a(-x)); f' from sum_k (-x)^k / Gamma(a k);
///  - x >= x_asymptotic() (s >= 42 to 65 for a >= 0.3, 178 at a = 0.1): the asymptotic
///    series sum_(k=1..K) (-1)^(k+1) x^-k / Gamma(1 - a k), K <= 100, whose error past its
///    smallest term is of order exp(-s);
///  - in between, the integral by composite 16-point Gauss-Legendre on panels graded
///    against the integrand's complex singularities (each panel's Bernstein ellipse of
///    parameter 4.5 keeps clear of them: the discretization error is about 1e-21), in one
///    of two variables. v = log(r s), where exp(-e^v) is fixed and the spectrum moves with
///    s: one division a node, 176 nodes for a <= 0.72, rising to 1400 at a = 0.98 (its
///    poles come within (1 - a) pi / a of the real axis). Or w = a log r, near a = 1 (from
///    a = 0.98, where K tends to a delta at r = 1): the nodes are fixed rates r_j and
///    f(s) = T + sum_j W_j exp(-r_j s), a positive sum of exponentials, one exp a node,
///    350 to 530 nodes (700 at a = 1 - 1e-6). The integrand is positive, so the sum keeps
///    the relative accuracy of its terms.
/// Measured against mpmath (40+ digits) for a from 0.01 to 0.999 and s from 1e-6 to 1e6,
/// and against exp(x^2) erfc(x) for a = 1/2: relative error below 1.3e-15 for f and s f'.
/// A call costs about 60-200 ns in the series and asymptotic regions, and in the middle one
/// 170 ns for a <= 0.72, 0.3 us at a = 0.9, 1 us at 0.98 and 2 us near a = 1.
class MittagLeffler {
 public:
  /// Throws std::invalid_argument unless 0 < a < 1.
  explicit MittagLeffler(double a);

  /// E_a(-x) for x >= 0.
  double negative(double x) const;
  /// f(s) = E_a(-s^a) for s >= 0: 1 at s = 0, completely monotone, ~ s^-a / Gamma(1 - a).
  double relaxation(double s) const;
  /// f'(s) = d/ds E_a(-s^a) for s >= 0: -infinity at s = 0 (~ -s^(a-1) / Gamma(a)).
  double relaxation_rate(double s) const;

  /// The region boundaries in x = s^a: series below x_series, asymptotic from x_asymptotic.
  double x_series() const { return x_series_; }
  double x_asymptotic() const { return x_asymptotic_; }

 private:
  double series(double x) const;
  double series_rate(double x) const;  // sum_k>=1 (-1)^(k-1) x^(k-1) / Gamma(a k)
  double asymptotic(double x) const;
  double asymptotic_rate(double x) const;  // s f'(s)
  double quadrature(double x, double s) const;
  double quadrature_rate(double x, double s) const;  // s f'(s)

  double a_;
  double sin_pi_a_, cos_pi_a_;
  double x_series_, x_asymptotic_;
  std::vector<double> series_, series_rate_;          // 1/Gamma(a k + 1), k >= 0; 1/Gamma(a k), k >= 1
  std::vector<double> asymptotic_, asymptotic_size_;  // g_k = 1/Gamma(1 - a k), k >= 1; max(|g_k|, |g_k+1|)
  bool fixed_rates_ = false;
  // v variable: nodes a v_j / 2 as exp(+-a v_j / 2), weights g_j exp(-e^v_j) and times e^v_j;
  // w variable: rates r_j, weights W_j (node_b_ unused).
  std::vector<double> node_a_, node_b_, weight_, weight_rate_;
  double tail_ = 0.0;  // v: exp(a v_T); w: the constant tail T
  double denominator_shift_ = 0.0;  // 4 cos^2(a pi / 2)
};

/// Power-law creep (docs/model.md, section 10), normalized by the instantaneous modulus:
///   J(t) = 1 + (t / t_1)^n,   0 < n < 1,
/// unlimited creep (J(inf) = infinity), with the exactly interconverted relaxation function
///   E(t) = E_n(-Gamma(1 + n) (t / t_1)^n) = E_n(-(t / tau)^n),   tau = t_1 Gamma(1 + n)^(-1/n),
/// E_n the Mittag-Leffler function (in Laplace space J^(s) = 1/s + Gamma(1 + n) t_1^-n
/// s^(-1-n) and E^(s) = 1/(s^2 J^(s)) = s^(n-1) / (s^n + Gamma(1 + n) t_1^-n), the transform of
/// E_n(-Gamma(1 + n) t_1^-n t^n)). E decays like (t/t_1)^-n / (Gamma(1 + n) Gamma(1 - n)), so
/// J E -> sin(n pi) / (n pi): the memory is long. Both rates are singular at t = 0:
/// J' ~ t^(n-1) and E' ~ -t^(n-1) (the kernel of a history integral is weakly singular at
/// age 0: no step size resolves it, a history quadrature must treat that end specially).
class PowerLaw final : public CreepLaw {
 public:
  /// Throws std::invalid_argument naming the bad value unless 0 < n < 1 and t_1 is finite
  /// and > 0.
  PowerLaw(double n, double t_1);

  double creep(double t) const override;
  /// n/t_1 (t/t_1)^(n-1): +infinity at t = 0.
  double creep_rate(double t) const override;
  /// int_u^(u+d) J dv = d + t_1/(n+1) (((u+d)/t_1)^(n+1) - (u/t_1)^(n+1)), the difference
  /// by expm1/log1p of d/u when d < u.
  double creep_integral(double u, double d) const override;
  double relaxation(double t) const override;
  /// dE/dt = f'(t/tau)/tau (f of MittagLeffler): -infinity at t = 0.
  double relaxation_rate(double t) const override;
  double creep_initial() const override { return 1.0; }
  /// +infinity: creep is unlimited.
  double creep_final() const override;
  /// t_1 (J - 1)^(1/n); 0 for J <= 1.
  double time_at_creep(double J) const override;
  /// tau = t_1 Gamma(1 + n)^(-1/n) (between t_1 and e^gamma t_1 = 1.78 t_1): E(t) =
  /// E_n(-(t/tau)^n), so E(tau) = E_n(-1), between 1/e and 1/2. A power law has no
  /// shortest time (E and J change by a fixed fraction over every decade); tau and t_1
  /// are where E and J change by order one.
  double relaxation_time_scale() const override { return tau_; }
  /// t_1, the time at which J has doubled (J(t_1) = 2 J(0)).
  double creep_time_scale() const override { return t_1_; }
  /// J' ~ t^(n-1) and E' ~ -t^(n-1) at 0.
  bool singular_at_zero() const override { return true; }
  /// +infinity: E' decays like t^(-1-n) only.
  double relaxation_memory() const override;
  std::string describe() const override;

  double exponent() const { return n_; }
  /// t_1, the time at which J has doubled.
  double doubling_time() const { return t_1_; }
  const MittagLeffler& mittag_leffler() const { return ml_; }

 private:
  double n_, t_1_, tau_;
  MittagLeffler ml_;
};

}  // namespace punchsweep::model
