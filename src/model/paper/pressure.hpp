#pragma once

#include "model/problem/contact_problem.hpp"
#include "model/load/creep_weighted_load.hpp"
#include "model/paper/single_level.hpp"

namespace punchsweep::model {

/// p_(k,m)(r) of eq (9.1): the pressure under an isolated punch f = C r^s / R^(s-1)
/// with contact radius a is (C / pi) p_(k,m)(r) (E* = 1); k for odd s = 2k + 1,
/// m for even s = 2m. Zero for r >= a; for s = 1 it is log-singular at r = 0.
/// p_(k) carries the factor pi/2 that the printed eq (9.1) lacks (see pressure.cpp).
double punch_pressure_shape(int s, double r, double a);

/// Contact pressure under a level-1 punch during the single-level phase, eq (9.4):
///   p(r, t) = int_0-^t E(t - tau) d/dtau q(r, tau) = E(0) q(r, t) + int E'(t - tau) q dtau,
/// with q the elastic pressure at the creep-weighted load X(tau) (pbar0 J(tau) for a step): punch term, the
/// four level-1 neighbours as a ring load on radius l, and the nominal pressure outside
/// A1 = sqrt(5/pi) l. Meaningful while only level 1 touches (t <= t*, or always when
/// level 2 never touches).
class Level1Pressure {
 public:
  Level1Pressure(const ContactProblem& problem, const CreepLaw& creep);

  /// q(r) of eq (9.4)'s bracket: pressure of the elastic problem at contact radius a1 and
  /// creep-scaled pressure X (in E0* when E* = 1).
  double creep_scaled(double r, double a1, double X) const;

  /// p(r, t), in E0*.
  double at(double r, double t) const;

  /// Level-1 contact radius at time t, in R.
  double contact_radius(double t) const;

  /// int_0^a1(t) p(r, t) 2 pi r dr, in R^2 E0* (Gauss-Legendre in r = a1 sin(phi), split at
  /// a1(0) where p has a (a1(0) - r)^(3/2) kink, graded towards r = 0 for the cone's log).
  double total_load(double t) const;

 private:
  ContactProblem problem_;
  const CreepLaw& creep_;
  CreepWeightedLoad load_;  ///< a step of problem.pbar0 on creep_
  SingleLevel single_;
  double A1_;
};

}  // namespace punchsweep::model
