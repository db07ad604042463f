#pragma once

#include "model/problem/contact_problem.hpp"
#include "model/problem/shape.hpp"

namespace punchsweep::model {

/// The single-level phase: only level-1 punches touch (docs/model.md, section 4).
///
/// "Creep-scaled nominal pressure" X = pbar0 J(t) is the only way time enters: the
/// contact radius and h are functions of X alone. Everything is solved in the scaled
/// radius x = a1/l, where eq 9.5 reads x^(s+1) / D(x) = X l^(1-s) / (pi K_P) and
/// h = C l^s eta_s(x) along the solution curve (eta depends on s only).
class SingleLevel {
 public:
  /// Root of D(x) = 0: the scaled contact radius at which eq 9.5 needs X -> infinity.
  static constexpr double kScaledRadiusLimit = 0.713712194371619;
  /// Relative tolerance of every radius root (in x).
  static constexpr double kRadiusTolerance = 1e-15;

  SingleLevel(double l, Shape shape);

  /// D(x) of eq 9.5 (corrected) with A1 = sqrt(5/pi) l, as a function of x = a/l.
  static double D(double x);
  /// dD/dx.
  static double D_rate(double x);

  /// Contact radius a1 of a level-1 punch at creep-scaled pressure X = pbar0 J,
  /// eq (9.5) with the misprint corrected (docs/model.md, section 8). Always in (0, kScaledRadiusLimit l).
  double contact_radius(double X) const;

  /// X = pbar0 J at which the contact radius is a1 (eq 9.5 solved for X).
  double creep_scaled_pressure(double a1) const;

  /// h = u(O) - u(M), eq (9.10) corrected: displacement difference between the punch tip
  /// and the square centre at contact radius a1 and creep-scaled pressure X.
  double displacement_difference(double a1, double X) const;

  /// h along the solution curve, h(a1) of section 9.3.3 (X eliminated with eq 9.5).
  double displacement_difference(double a1) const;

  /// dh/da1 along the solution curve (Fig. 9.2b).
  double displacement_difference_rate(double a1) const;

  /// The contact radius a1 at which h(a1) = dh (h increases from 0 to +infinity on
  /// (0, kScaledRadiusLimit l): Fig. 9.2). Returns 0 for dh <= 0.
  double contact_radius_at_gap(double dh) const;

  double pitch() const { return l_; }
  const Shape& shape() const { return shape_; }

 private:
  /// G(x): the bracket of eq 9.10 divided by l.
  static double G(double x);
  static double G_rate(double x);
  /// eta_s(x) = h / (C l^s) and its derivative.
  double eta(double x, double* rate) const;

  double l_;
  Shape shape_;
  double K_P_;
  double K_d_;
  double kappa_per_X_;  ///< l^(1-s) / (pi K_P)
};

}  // namespace punchsweep::model
