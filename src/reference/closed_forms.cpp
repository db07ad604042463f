#include "reference/closed_forms.hpp"

#include <cmath>
#include <numbers>

namespace punchsweep::reference {

namespace {
constexpr double pi = std::numbers::pi;
}  // namespace

double westergaard_full_contact_pressure(double amplitude, double wavelength, double compliance) {
  return pi * amplitude / (wavelength * compliance);
}

double westergaard_half_width(double mean_pressure, double amplitude, double wavelength,
                              double compliance) {
  const double ratio =
      mean_pressure / westergaard_full_contact_pressure(amplitude, wavelength, compliance);
  if (ratio >= 1.0) return 0.5 * wavelength;
  return wavelength / pi * std::asin(std::sqrt(ratio));
}

double westergaard_pressure(double x, double mean_pressure, double amplitude, double wavelength,
                            double compliance) {
  const double p_star = westergaard_full_contact_pressure(amplitude, wavelength, compliance);
  if (mean_pressure >= p_star) return mean_pressure + p_star * std::cos(2.0 * pi * x / wavelength);
  const double a = westergaard_half_width(mean_pressure, amplitude, wavelength, compliance);
  const double xr = std::remainder(x, wavelength);
  if (std::abs(xr) >= a) return 0.0;
  const double sa = std::sin(pi * a / wavelength);
  const double sx = std::sin(pi * xr / wavelength);
  return 2.0 * mean_pressure * std::cos(pi * xr / wavelength) * std::sqrt(sa * sa - sx * sx) /
         (sa * sa);
}

HertzContact hertz(double load, double radius, double compliance) {
  HertzContact c;
  c.a = std::cbrt(0.75 * load * radius * compliance);
  c.p0 = 1.5 * load / (pi * c.a * c.a);
  return c;
}

HertzContact hertz_periodic(double load, double radius, double cell, double compliance) {
  const double alpha =
      load * compliance * kSquareLatticeZetaThreeHalves / (4.0 * pi * cell * cell * cell);
  return hertz(load, radius / (1.0 + 2.0 * radius * alpha), compliance);
}

double flat_punch_periodic_approach(double load, double radius, double cell, double compliance) {
  const double x = radius / cell;
  return load * compliance / (2.0 * radius) *
         (1.0 + 2.0 * x * kSquareLatticeZetaHalf / pi +
          2.0 * kSquareLatticeZetaThreeHalves * x * x * x / (3.0 * pi));
}

}  // namespace punchsweep::reference
