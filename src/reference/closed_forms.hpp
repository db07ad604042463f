#pragma once
/// @file
/// Closed-form contact solutions the reference solver is checked against (the tests import
/// them; so may anyone validating a grid). Units: lengths in R, pressures in E0*, loads in
/// R^2 E0*; every function takes the plane-strain modulus as E* = 1 / compliance.

namespace punchsweep::reference {

/// Z(1/2) of the unit square lattice, sum' (m^2 + n^2)^(-1/2) continued analytically,
/// = 4 zeta(1/2) beta(1/2) (Epstein zeta; Glasser & Zucker 1980). It is the regular part of
/// the zero-mean periodic 1/r potential at its source: sum'_k 2 pi/(L^2 |k|) e^(ik.x) =
/// 1/|x| + Z(1/2)/L + O(|x|^2).
inline constexpr double kSquareLatticeZetaHalf = -3.9002649200019558828;
/// Z(3/2) = sum' (m^2 + n^2)^(-3/2) = 4 zeta(3/2) beta(3/2): the curvature of the field
/// that the periodic images of a point load make at the load.
inline constexpr double kSquareLatticeZetaThreeHalves = 9.0336216831009503057;

/// Westergaard's sinusoidal contact (Johnson 1985, section 13.2): a rigid surface
/// z = Delta cos(2 pi x / lambda) on an elastic half-space. Full contact from the mean
/// pressure p* = pi E* Delta / lambda on.
double westergaard_full_contact_pressure(double amplitude, double wavelength,
                                         double compliance = 1.0);

/// Contact half-width a of the partial Westergaard contact: sin^2(pi a / lambda) = pbar / p*
/// (pbar <= p*; lambda / 2 beyond).
double westergaard_half_width(double mean_pressure, double amplitude, double wavelength,
                              double compliance = 1.0);

/// Pressure of the partial Westergaard contact at x (measured from a contact centre),
/// p = 2 pbar cos(pi x/lambda) sqrt(sin^2(pi a/lambda) - sin^2(pi x/lambda)) / sin^2(pi a/lambda)
/// for |x| < a, 0 elsewhere; p = pbar + p* cos(2 pi x/lambda) in full contact.
double westergaard_pressure(double x, double mean_pressure, double amplitude, double wavelength,
                            double compliance = 1.0);

/// Hertz contact of a sphere of radius R (profile r^2 / (2R)) under load P.
struct HertzContact {
  double a = 0.0;   ///< contact radius, in R
  double p0 = 0.0;  ///< peak pressure 3P / (2 pi a^2), in E0*
};

/// Isolated Hertz: a^3 = 3 P R / (4 E*).
HertzContact hertz(double load, double radius, double compliance = 1.0);

/// Hertz for one sphere per L x L cell of a square lattice, to first order in the images:
/// their field adds the curvature alpha r^2 with alpha = P Z(3/2) / (4 pi E* L^3) around the
/// spot, so R becomes R_eff = R / (1 + 2 R alpha). The next terms are O((a/L)^2) relative to
/// that correction.
HertzContact hertz_periodic(double load, double radius, double cell, double compliance = 1.0);

/// Approach of a periodic square array (pitch L) of flat circular punches of radius a under
/// load P each, measured from the zero-mean surface (the periodic solver's datum):
///   delta = P / (2 E* a) [1 + 2 a Z(1/2) / (pi L) + 2 Z(3/2) a^3 / (3 pi L^3) + O((a/L)^5)]
/// (isolated punch, Sneddon; the images as point loads, Z(1/2); their curvature and spread
/// averaged over the punch, each giving P Z(3/2) a^2 / (6 pi E* L^3)).
double flat_punch_periodic_approach(double load, double radius, double cell,
                                    double compliance = 1.0);

}  // namespace punchsweep::reference
