#include "model/laws/power_law.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "model/numerics/gauss_rules.hpp"

namespace punchsweep::model {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Series region: x = s^a <= 0.5. The terms' moduli sum to E_a(x), at most about 3 E_a(-x)
// there (exactly 3 as a -> 0, e for a -> 1), so rounding costs no digit.
constexpr double kSeriesLimit = 0.5;
// Terms of the asymptotic series, at most.
constexpr int kAsymptoticTerms = 100;
// A series stops once its terms (bounds on them) fall below this fraction of the sum.
constexpr double kTruncation = 5e-18;
// Gauss-Legendre points per panel, and the Bernstein ellipse parameter every panel's
// ellipse must keep clear of the integrand's singularities: the error is about
// rho^(-2n) = 4.5^-32 = 1e-21 of the integrand's size near the panel.
constexpr int kPanelNodes = 16;
constexpr double kEllipse = 4.5;
// exp(-e^v) (exp(-s r)) is negligible beyond e^v = 50, and 1 - exp(-e^v) below v = -37.
constexpr double kCutoff = 50.0;
constexpr double kTailLog = -37.0;
// A quadrature needing more panels than this is not built (the other variable serves).
constexpr std::size_t kMaxPanels = 1000;

std::string shortest(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string bad(const std::string& what, double value, const std::string& range) {
  return "power law: " + what + " = " + shortest(value) + " is outside its range: " + range;
}

double checked_exponent(double n) {
  if (!(n > 0.0 && n < 1.0)) throw std::invalid_argument(bad("n", n, "0 < n < 1"));
  return n;
}

double checked_time_unit(double t_1) {
  if (!(std::isfinite(t_1) && t_1 > 0.0)) throw std::invalid_argument(bad("t_1", t_1, "t_1 > 0, finite"));
  return t_1;
}

// sin(pi z) for z = hi + lo (|lo| << |hi|), reduced exactly so that it keeps its relative
// accuracy near the zeros at the integers.
double sin_pi(double hi, double lo = 0.0) {
  double r = hi - 2.0 * std::nearbyint(0.5 * hi);  // exact, in [-1, 1]
  double sign = 1.0;
  if (r < 0.0) {
    r = -r;
    lo = -lo;
    sign = -1.0;
  }
  if (r > 0.5) {  // sin(pi r) = sin(pi (1 - r)); 1 - r exact
    r = 1.0 - r;
    lo = -lo;
  }
  return sign * std::sin(kPi * (r + lo));
}

// 1 / Gamma(1 - a k) = Gamma(a k) sin(pi a k) / pi, with a k split exactly into hi + lo.
double reciprocal_gamma_reflected(double a, int k) {
  const double hi = a * k;
  const double lo = std::fma(a, static_cast<double>(k), -hi);
  return std::tgamma(hi) * sin_pi(hi, lo) / kPi;
}

// Singular points x + i y (and conjugates) of an integrand, x in [from, to].
struct Singular {
  double from, to, height;
};

// The Bernstein ellipse parameter of the point (px, py) for the panel center +- half.
double ellipse_parameter(double center, double half, double px, double py) {
  const double zx = (px - center) / half;
  const double zy = py / half;
  const double m = 0.5 * (std::hypot(zx - 1.0, zy) + std::hypot(zx + 1.0, zy));
  return m + std::sqrt((m - 1.0) * (m + 1.0));
}

bool panel_fits(double l, double r, const std::vector<Singular>& singular, double max_width) {
  if (r - l > max_width) return false;
  const double center = 0.5 * (l + r);
  const double half = 0.5 * (r - l);
  for (const Singular& s : singular) {
    // For a fixed height the parameter grows with the distance from the center along x.
    const double px = std::clamp(center, s.from, s.to);
    if (ellipse_parameter(center, half, px, s.height) < kEllipse) return false;
  }
  return true;
}

// Panels covering [lo, hi], each as wide as the singularities allow (greedy from lo; the
// ellipse of a wider panel with the same left end contains the narrower one's, so the
// greedy cover is the shortest). Empty if more than `max_panels` would be needed.
std::vector<double> panel_breaks(double lo, double hi, const std::vector<Singular>& singular, double max_width,
                                 std::size_t max_panels) {
  std::vector<double> breaks{lo};
  double l = lo;
  while (l < hi) {
    if (breaks.size() > max_panels) return {};
    double r = hi;
    if (!panel_fits(l, hi, singular, max_width)) {
      double good = l;
      double bad = hi;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (good + bad);
        (panel_fits(l, mid, singular, max_width) ? good : bad) = mid;
      }
      r = good > l ? good : bad;
    }
    breaks.push_back(r);
    l = r;
  }
  return breaks;
}

// Gauss-Legendre nodes and weights on the panels.
void panel_nodes(const std::vector<double>& breaks, std::vector<double>* nodes, std::vector<double>* weights) {
  const GaussRule& rule = gauss_legendre(kPanelNodes);
  for (std::size_t p = 0; p + 1 < breaks.size(); ++p) {
    const double center = 0.5 * (breaks[p] + breaks[p + 1]);
    const double half = 0.5 * (breaks[p + 1] - breaks[p]);
    for (int g = 0; g < kPanelNodes; ++g) {
      nodes->push_back(center + half * rule.nodes[g]);
      weights->push_back(half * rule.weights[g]);
    }
  }
}

}  // namespace

MittagLeffler::MittagLeffler(double a) : a_(a) {
  if (!(a > 0.0 && a < 1.0)) {
    throw std::invalid_argument("Mittag-Leffler order a = " + shortest(a) + " is outside its range: 0 < a < 1");
  }
  sin_pi_a_ = sin_pi(a);
  cos_pi_a_ = a <= 0.5 ? std::cos(kPi * a) : -std::cos(kPi * (1.0 - a));
  // 2 cosh(u) + 2 cos(a pi) = 4 sinh^2(u/2) + 4 cos^2(a pi/2): both terms >= 0, no cancellation.
  const double half_cos = a <= 0.5 ? std::cos(0.5 * kPi * a) : std::sin(0.5 * kPi * (1.0 - a));
  denominator_shift_ = 4.0 * half_cos * half_cos;

  // Power series: 1/Gamma(a k + 1) (at most 1.13) until x^k < 1e-18 at x = 0.5.
  x_series_ = kSeriesLimit;
  for (int k = 0; std::pow(kSeriesLimit, k) > 0.1 * kTruncation; ++k) {
    series_.push_back(1.0 / std::tgamma(a * k + 1.0));
    if (k >= 1) series_rate_.push_back(1.0 / std::tgamma(a * k));
  }

  // Asymptotic series: g_k = 1/Gamma(1 - a k), k = 1..K+1; a term's size for the stopping
  // test is max(|g_k|, |g_(k+1)|) x^-k (g_k vanishes where a k is an integer, by accident).
  std::vector<double> g;
  for (int k = 1; k <= kAsymptoticTerms + 1; ++k) g.push_back(reciprocal_gamma_reflected(a, k));
  for (int k = 1; k <= kAsymptoticTerms; ++k) {
    asymptotic_.push_back(g[k - 1]);
    asymptotic_size_.push_back(std::max(std::abs(g[k - 1]), std::abs(g[k])));
  }
  // The asymptotic series is used from the x where (i) exp(-s), the order of its error at
  // its smallest term, is below the tolerance against f ~ g_1/x, and (ii) K terms reach
  // the tolerance (f >= g_1/(2x) there). s = x^(1/a) is 42 to 62 there for a >= 0.3, more
  // for small a (178 at a = 0.1), where the terms decrease slowly.
  const double g1 = g[0];
  double s_remainder = 40.0;
  for (int it = 0; it < 20; ++it) s_remainder = std::log(1.0 / (kTruncation * g1)) + a * std::log(s_remainder);
  const double log_x_remainder = a * std::log(s_remainder);
  const double log_x_terms = std::log(2.0 * asymptotic_size_.back() / (kTruncation * g1)) / (kAsymptoticTerms - 1);
  const double log_x_hi = std::max(log_x_remainder, log_x_terms);
  x_asymptotic_ = std::exp(log_x_hi);

  // The middle region, log s in [L_lo, L_hi].
  const double L_lo = std::log(kSeriesLimit) / a;
  const double L_hi = log_x_hi / a;
  const double delta = (1.0 - a) * kPi;  // the spectrum's poles: r^a = -exp(+-i a pi)
  const double strip = 0.9 * 0.5 * kPi;  // exp(-e^v) is bounded for |Im v| < pi/2

  // Variable v = log(r s): f = int exp(-e^v) R(a (v - log s)) dv with
  // R(u) = sin(a pi) / (pi (2 cosh u + 2 cos(a pi))), poles at v = log s +- i delta/a.
  const std::vector<Singular> v_singular{{-1.5, kInfinity, strip}, {L_lo, L_hi, delta / a}};
  // Variable w = a log r: f = int exp(-s e^(w/a)) R(w) dw / a, poles at w = +-i delta;
  // exp(-s e^(w/a)) is bounded for |Im w| < a pi/2 and grows beyond it where s e^(w/a) is
  // not small (w above about -a (L_hi + 1.5)).
  const double w_lo = a * (kTailLog - L_hi);
  const double w_hi = a * (std::log(kCutoff) - L_lo);
  const std::vector<Singular> w_singular{{-a * (L_hi + 1.5), kInfinity, a * strip}, {0.0, 0.0, delta}};

  // A v node costs a division, a w node an exp (about four times as much). The v panels
  // grow in number like 1/(1 - a) as a -> 1, the w panels like 1/a as a -> 0; at least one
  // of the two stays few. The likely cheaper is built first, the other only while it is
  // cheaper still.
  const auto build_v = [&](std::size_t max_panels) {
    return panel_breaks(kTailLog, std::log(kCutoff), v_singular, 8.0, max_panels);
  };
  const auto build_w = [&](std::size_t max_panels) { return panel_breaks(w_lo, w_hi, w_singular, 6.0, max_panels); };
  std::vector<double> v_breaks;
  std::vector<double> w_breaks;
  if (a < 0.97) {
    v_breaks = build_v(kMaxPanels);
    w_breaks = build_w(v_breaks.empty() ? kMaxPanels : (v_breaks.size() - 1) / 4);
  } else {
    w_breaks = build_w(kMaxPanels);
    v_breaks = build_v(w_breaks.empty() ? kMaxPanels : 4 * (w_breaks.size() - 1) - 1);
    if (!v_breaks.empty()) w_breaks.clear();
  }
  if (v_breaks.empty() && w_breaks.empty()) {
    throw std::logic_error("Mittag-Leffler order a = " + shortest(a) + ": no quadrature within " +
                           std::to_string(kMaxPanels) + " panels");
  }
  fixed_rates_ = !w_breaks.empty();
  std::vector<double> nodes;
  std::vector<double> weights;
  if (!fixed_rates_) {
    panel_nodes(v_breaks, &nodes, &weights);
    for (std::size_t j = 0; j < nodes.size(); ++j) {
      const double v = nodes[j];
      node_a_.push_back(std::exp(0.5 * a * v));
      node_b_.push_back(std::exp(-0.5 * a * v));
      weight_.push_back(weights[j] * std::exp(-std::exp(v)));
      weight_rate_.push_back(weight_.back() * std::exp(v));
    }
    tail_ = std::exp(a * kTailLog);
  } else {
    panel_nodes(w_breaks, &nodes, &weights);
    for (std::size_t j = 0; j < nodes.size(); ++j) {
      const double w = nodes[j];
      const double sh = std::sinh(0.5 * w);
      node_a_.push_back(std::exp(w / a));
      weight_.push_back(weights[j] * sin_pi_a_ / (a * kPi * (4.0 * sh * sh + denominator_shift_)));
      weight_rate_.push_back(weight_.back() * node_a_.back());
    }
    const double Z = std::exp(w_lo);
    tail_ = std::atan2(Z * sin_pi_a_, 1.0 + Z * cos_pi_a_) / (a * kPi);
  }
}

double MittagLeffler::series(double x) const {
  double sum = 0.0;
  double power = 1.0;
  for (const double c : series_) {
    sum += c * power;
    power *= -x;
    if (std::abs(power) < 0.1 * kTruncation) break;
  }
  return sum;
}

double MittagLeffler::series_rate(double x) const {
  double sum = 0.0;
  double power = 1.0;
  for (const double c : series_rate_) {
    sum += c * power;
    power *= -x;
    if (std::abs(power) < 0.1 * kTruncation) break;
  }
  return sum;
}

double MittagLeffler::asymptotic(double x) const {
  const double y = 1.0 / x;
  double sum = 0.0;
  double power = y;
  for (int k = 0; k < kAsymptoticTerms; ++k) {
    sum += (k % 2 ? -asymptotic_[k] : asymptotic_[k]) * power;
    if (asymptotic_size_[k] * power < kTruncation * std::abs(sum)) break;
    power *= y;
  }
  return sum;
}

double MittagLeffler::asymptotic_rate(double x) const {
  // s f'(s) ~ sum_k (-1)^k a k g_k x^-k.
  const double y = 1.0 / x;
  double sum = 0.0;
  double power = y;
  for (int k = 0; k < kAsymptoticTerms; ++k) {
    const double c = a_ * (k + 1) * asymptotic_[k];
    sum += (k % 2 ? c : -c) * power;
    if (a_ * (k + 1) * asymptotic_size_[k] * power < kTruncation * std::abs(sum)) break;
    power *= y;
  }
  return sum;
}

// The middle-region sums run over four accumulators: independent chains for the pipeline,
// and a shorter chain of roundings.
double MittagLeffler::quadrature(double x, double s) const {
  double sum[4] = {0.0, 0.0, 0.0, 0.0};
  const std::size_t nodes = node_a_.size();  // a multiple of 4 (16 a panel)
  if (!fixed_rates_) {
    const double root = std::sqrt(x);
    const double inverse_root = 1.0 / root;
    for (std::size_t j = 0; j < nodes; j += 4) {
      for (std::size_t i = 0; i < 4; ++i) {
        const double d = node_a_[j + i] * inverse_root - node_b_[j + i] * root;  // 2 sinh(a (v - log s)/2)
        sum[i] += weight_[j + i] / (d * d + denominator_shift_);
      }
    }
    // The tail v < v_T, where exp(-e^v) = 1: int_0^Z dz / (z^2 + 2 z cos(a pi) + 1) / (a pi),
    // z = e^(a (v - log s)).
    const double Z = tail_ / x;
    return std::atan2(Z * sin_pi_a_, 1.0 + Z * cos_pi_a_) / (a_ * kPi) +
           sin_pi_a_ / kPi * ((sum[0] + sum[1]) + (sum[2] + sum[3]));
  }
  // Rates ascend: stop where exp(-r s) < exp(-50).
  for (std::size_t j = 0; j < nodes && node_a_[j] * s <= kCutoff; j += 4) {
    for (std::size_t i = 0; i < 4; ++i) sum[i] += weight_[j + i] * std::exp(-node_a_[j + i] * s);
  }
  return tail_ + ((sum[0] + sum[1]) + (sum[2] + sum[3]));
}

double MittagLeffler::quadrature_rate(double x, double s) const {
  double sum[4] = {0.0, 0.0, 0.0, 0.0};
  const std::size_t nodes = node_a_.size();
  if (!fixed_rates_) {
    const double root = std::sqrt(x);
    const double inverse_root = 1.0 / root;
    for (std::size_t j = 0; j < nodes; j += 4) {
      for (std::size_t i = 0; i < 4; ++i) {
        const double d = node_a_[j + i] * inverse_root - node_b_[j + i] * root;
        sum[i] += weight_rate_[j + i] / (d * d + denominator_shift_);
      }
    }
    return -sin_pi_a_ / kPi * ((sum[0] + sum[1]) + (sum[2] + sum[3]));
  }
  for (std::size_t j = 0; j < nodes && node_a_[j] * s <= kCutoff; j += 4) {
    for (std::size_t i = 0; i < 4; ++i) sum[i] += weight_rate_[j + i] * std::exp(-node_a_[j + i] * s);
  }
  return -s * ((sum[0] + sum[1]) + (sum[2] + sum[3]));
}

double MittagLeffler::negative(double x) const {
  if (x <= x_series_) return series(x);
  if (x >= x_asymptotic_) return asymptotic(x);
  return quadrature(x, std::pow(x, 1.0 / a_));
}

double MittagLeffler::relaxation(double s) const {
  const double x = std::pow(s, a_);
  if (x <= x_series_) return series(x);
  if (x >= x_asymptotic_) return asymptotic(x);
  return quadrature(x, s);
}

double MittagLeffler::relaxation_rate(double s) const {
  if (s == 0.0) return -kInfinity;
  const double x = std::pow(s, a_);
  if (x <= x_series_) return -(x / s) * series_rate(x);  // s^(a-1): a - 1 is rounded, a not
  if (x >= x_asymptotic_) return asymptotic_rate(x) / s;
  return quadrature_rate(x, s) / s;
}

PowerLaw::PowerLaw(double n, double t_1)
    : n_(checked_exponent(n)),
      t_1_(checked_time_unit(t_1)),
      tau_(t_1 * std::exp(-std::lgamma(1.0 + n) / n)),
      ml_(n) {}

double PowerLaw::creep(double t) const { return 1.0 + std::pow(t / t_1_, n_); }

double PowerLaw::creep_rate(double t) const { return n_ / t_1_ * std::pow(t / t_1_, n_ - 1.0); }

double PowerLaw::creep_integral(double u, double d) const {
  if (!(d > 0.0)) return 0.0;
  // d + t_1/(n+1) (((u+d)/t_1)^(n+1) - (u/t_1)^(n+1)); for a short interval (d < u) the
  // difference is u (u/t_1)^n ((1 + d/u)^(n+1) - 1), by expm1 and log1p.
  const double u1 = u + d;
  const double creep_part = d < u ? u * std::pow(u / t_1_, n_) * std::expm1((n_ + 1.0) * std::log1p(d / u))
                                  : u1 * std::pow(u1 / t_1_, n_) - u * std::pow(u / t_1_, n_);
  return d + creep_part / (n_ + 1.0);
}

double PowerLaw::relaxation(double t) const { return ml_.relaxation(t / tau_); }

double PowerLaw::relaxation_rate(double t) const { return ml_.relaxation_rate(t / tau_) / tau_; }

double PowerLaw::creep_final() const { return kInfinity; }

double PowerLaw::time_at_creep(double J) const {
  if (J <= 1.0) return 0.0;
  return t_1_ * std::pow(J - 1.0, 1.0 / n_);
}

double PowerLaw::relaxation_memory() const { return kInfinity; }

std::string PowerLaw::describe() const { return "power law, n = " + shortest(n_) + ", t_1 = " + shortest(t_1_); }

}  // namespace punchsweep::model
