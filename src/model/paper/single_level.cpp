#include "model/paper/single_level.hpp"

#include <cmath>
#include <numbers>

#include "model/numerics/integer_power.hpp"

#include "model/numerics/root_finding.hpp"

namespace punchsweep::model {
namespace {

constexpr double kPi = std::numbers::pi;
// A1 / l = sqrt(5/pi) and A / l = 2/sqrt(pi): the single-level nominal-pressure radii.
const double kAlpha = std::sqrt(5.0 / kPi);
const double kAlpha2 = 5.0 / kPi;
const double kBeta = 2.0 / std::sqrt(kPi);

}  // namespace

SingleLevel::SingleLevel(double l, Shape shape)
    : l_(l),
      shape_(shape),
      K_P_(load_coefficient(shape)),
      K_d_(depth_coefficient(shape)),
      kappa_per_X_(ipow(l, 1 - shape.s) / (kPi * K_P_)) {}

double SingleLevel::D(double x) {
  return 10.0 * (std::acos(x / kAlpha) + x / kAlpha2 * std::sqrt(kAlpha2 - x * x)) -
         8.0 * (std::acos(x) + x / std::sqrt(1.0 - x * x));
}

double SingleLevel::D_rate(double x) {
  const double q = 1.0 - x * x;
  return -20.0 * x * x / (kAlpha2 * std::sqrt(kAlpha2 - x * x)) - 8.0 * x * x / (q * std::sqrt(q));
}

double SingleLevel::G(double x) {
  return std::sqrt(kAlpha2 - x * x) - 2.0 * kAlpha2 / (5.0 * std::sqrt(1.0 - x * x)) +
         2.0 * std::numbers::sqrt2 * kAlpha2 / 5.0 - kBeta;
}

double SingleLevel::G_rate(double x) {
  const double q = 1.0 - x * x;
  return -x / std::sqrt(kAlpha2 - x * x) - 2.0 * kAlpha2 * x / (5.0 * q * std::sqrt(q));
}

// Eq 9.5 in x: phi(x) = (s+1) log x - log D(x) - log kappa, increasing on (0, x_D).
double SingleLevel::contact_radius(double X) const {
  if (!(X > 0.0)) return 0.0;
  if (std::isinf(X)) return kScaledRadiusLimit * l_;
  const double log_kappa = std::log(X * kappa_per_X_);
  const int s1 = shape_.s + 1;
  // Small-contact guess: D(0) = pi.
  const double guess = std::exp((log_kappa + std::log(kPi)) / s1);
  auto phi = [&](double x, double* rate) {
    const double d = D(x);
    *rate = s1 / x - D_rate(x) / d;
    return s1 * std::log(x) - std::log(d) - log_kappa;
  };
  const RootResult root = newton_bisect_increasing(phi, 0.0, kScaledRadiusLimit, guess,
                                                   kRadiusTolerance * std::min(guess, 1.0));
  return root.x * l_;
}

double SingleLevel::creep_scaled_pressure(double a1) const {
  const double x = a1 / l_;
  return ipow(x, shape_.s + 1) / D(x) / kappa_per_X_;
}

double SingleLevel::displacement_difference(double a1, double X) const {
  const double x = a1 / l_;
  return K_d_ * ipow(a1, shape_.s) - 2.0 * l_ * X * G(x);
}

double SingleLevel::displacement_difference(double a1) const {
  return displacement_difference(a1, creep_scaled_pressure(a1));
}

double SingleLevel::displacement_difference_rate(double a1) const {
  // h = C l^s eta(x) with x = a1 / l.
  double rate = 0.0;
  eta(a1 / l_, &rate);
  return shape_.C * ipow(l_, shape_.s - 1) * rate;
}

double SingleLevel::eta(double x, double* rate) const {
  const int s = shape_.s;
  const double kd = K_d_ / shape_.C;
  const double kp = K_P_ / shape_.C;
  const double xs = ipow(x, s);
  const double d = D(x);
  const double g = G(x);
  const double ratio = x * g / d;  // x G / D
  const double ratio_rate = (g + x * G_rate(x)) / d - x * g * D_rate(x) / (d * d);
  *rate = kd * s * xs / x - 2.0 * kPi * kp * (s * xs / x * ratio + xs * ratio_rate);
  return kd * xs - 2.0 * kPi * kp * xs * ratio;
}

double SingleLevel::contact_radius_at_gap(double dh) const {
  if (!(dh > 0.0)) return 0.0;
  const double target = dh / (shape_.C * ipow(l_, shape_.s));
  auto f = [&](double x, double* rate) { return eta(x, rate) - target; };
  // Small-contact guess: eta ~ K_d' x^s.
  const double guess = std::pow(target * shape_.C / K_d_, 1.0 / shape_.s);
  const RootResult root = newton_bisect_increasing(f, 0.0, kScaledRadiusLimit, guess,
                                                   kRadiusTolerance * std::min(guess, 1.0));
  return root.x * l_;
}

}  // namespace punchsweep::model
